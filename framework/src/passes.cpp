#include "whitted/passes.hpp"

#include "lab_call.hpp"
#include "pass_pictures.hpp"
#include "whitted/labs.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace whitted {
namespace {

using detail::kBackground;
using detail::kNotApplicable;
using detail::kShadowBackground;
using detail::ramp;

const std::array<PassInfo, 9> kPasses = {{
    {Pass::normal, "normal", Stage::ray_casting,
     "the eye ray's hit normal: red, green, blue = its x, y, z from -1..1 mapped to 0..1; background black"},
    {Pass::depth, "depth", Stage::ray_casting, "the eye ray's distance to its hit: nearest white, farthest dark grey; background black"},
    {Pass::albedo, "albedo", Stage::ray_casting,
     "the diffuse colour Kd x C at the eye ray's hit (checkerboards included); background black"},
    {Pass::shadow, "shadow", Stage::shadows,
     "is_lit() at the eye ray's hit for the lights in front of the surface: white = every one reaches it, "
     "black = none, grey = some; dark blue = no light in front; teal = background"},
    {Pass::reflectance, "reflectance", Stage::reflection,
     "the weight of the eye ray's reflected ray (Ks x specular colour, or Kr with Fresnel); black = none"},
    {Pass::fresnel, "fresnel", Stage::fresnel,
     "fresnel_reflectance() at the eye ray's hit on transparent surfaces, black 0 to white 1; "
     "dark blue = not transparent; background black"},
    {Pass::ray_depth, "ray-depth", Stage::ray_casting,
     "the deepest ray of each pixel's ray tree: dark blue = the eye ray only, then green, yellow, red = max depth"},
    {Pass::object_id, "object-id", Stage::ray_casting, "one colour per object (per line of the scene file); background black"},
    {Pass::cost, "cost", Stage::ray_casting,
     "intersection tests per pixel (ray-box + ray-primitive, every ray of the pixel's tree), log scale: "
     "dark blue = fewest, red = most in this image"},
}};

// A bright colour for a number, the same every time.
Color id_color(std::uint32_t key) {
    std::uint32_t h = key * 2654435761u;
    h ^= h >> 15;
    h *= 2246822519u;
    h ^= h >> 13;
    return Color(0.25 + 0.75 * ((h & 0xff) / 255.0), 0.25 + 0.75 * (((h >> 8) & 0xff) / 255.0),
                 0.25 + 0.75 * (((h >> 16) & 0xff) / 255.0));
}

// One thread's tracers: one records each pixel's ray tree; the other casts the
// shadow pass's feelers into a tree of their own (into the first, they would
// grow it while the pass still reads the eye ray's hit from it).
struct Probe {
    RayTree tree;
    RayTree feeler_tree;
    Tracer tracer;
    Tracer feelers;
    std::uint64_t acne_pixels = 0; // the shadow pass's pixels where a feeler hit the surface it starts from
    // `traced`: how far the tree goes; the feelers see the lights as `settings` ask (area lights sampled from lab 8).
    Probe(const Scene& scene, const RenderSettings& traced, const RenderSettings& settings, RayStats& stats)
        : tracer(scene, traced, stats, &tree), feelers(scene, settings, stats, &feeler_tree) {}
};

// At the eye ray's hit: white when every light in front of the surface reaches it, black when none does,
// and the fraction of the points that reach it in the penumbra of area lights (lab 8). Counts the pixel
// as acne when one of its feelers hit the surface it starts from.
Color shadow_pixel(const Scene& scene, Probe& probe, const Hit& hit) {
    int facing = 0, lit = 0;
    probe.feeler_tree.clear();
    for (const PointLight& light : probe.feelers.lights()) {
        if (glm::dot(hit.normal, light.position - hit.point) <= 0.0) continue;
        ++facing;
        if (detail::call_lab("is_lit", is_lit, probe.feelers, hit, light)) ++lit;
    }
    for (const RayNode& feeler : probe.feeler_tree.nodes)
        if (hits_its_own_surface(scene, hit, feeler)) {
            ++probe.acne_pixels;
            break;
        }
    return facing == 0 ? kNotApplicable : Color(static_cast<double>(lit) / facing);
}

Color fresnel_pixel(const Scene& scene, const RayNode& eye) {
    const Hit& hit = *eye.hit;
    const Material& material = scene.material(hit);
    if (material.transmittance <= 0.0) return kNotApplicable;
    const double eta_i = hit.front_face ? 1.0 : material.ior;
    const double eta_t = hit.front_face ? material.ior : 1.0;
    return Color(detail::call_lab("fresnel_reflectance", fresnel_reflectance, glm::dot(-eye.ray.direction, hit.normal), eta_i, eta_t));
}

// The pixel's value; depth and cost give raw numbers that finish() turns into colours.
Color pass_pixel(Pass pass, const Scene& scene, const RenderSettings& settings, Probe& probe) {
    const std::vector<RayNode>& nodes = probe.tree.nodes;
    const RayNode& eye = nodes.front();
    switch (pass) {
    case Pass::reflectance: {
        Color weight(0.0);
        for (int child : eye.children)
            if (nodes[child].kind == RayKind::reflected) weight += nodes[child].weight;
        return weight;
    }
    case Pass::ray_depth: {
        int deepest = 1;
        for (const RayNode& node : nodes)
            if (node.kind != RayKind::shadow && node.fate == RayFate::traced) deepest = std::max(deepest, node.depth);
        return ramp(settings.max_depth > 1 ? (deepest - 1.0) / (settings.max_depth - 1.0) : 0.0);
    }
    case Pass::cost: {
        std::uint64_t tests = 0;
        for (const RayNode& node : nodes)
            if (node.fate == RayFate::traced)
                tests += scene.query_cost(node.ray, node.t_range, node.kind == RayKind::shadow).total();
        return Color(static_cast<double>(tests));
    }
    default: break;
    }
    if (!eye.hit) return pass == Pass::shadow ? kShadowBackground : kBackground;
    const Hit hit = *eye.hit;
    switch (pass) {
    case Pass::normal: return 0.5 * (hit.normal + 1.0);
    case Pass::depth: return Color(hit.t, 1.0, 0.0); // (distance, "hit") until finish()
    case Pass::albedo: {
        const Material& material = scene.material(hit);
        return material.diffuse * material.color_at(hit.point);
    }
    case Pass::shadow:
        // Its own budget for this pixel's feelers (it never runs trace_pixel()), and the eye ray's pixel sample.
        probe.feelers.begin_pixel(probe.tracer.pixel_sample());
        return shadow_pixel(scene, probe, hit);
    case Pass::fresnel: return fresnel_pixel(scene, eye);
    case Pass::object_id: {
        const Primitive& primitive = scene.primitives()[hit.primitive];
        return id_color(primitive.line > 0 ? primitive.line : (1u << 24) + primitive.index);
    }
    default: return kBackground;
    }
}

} // namespace

std::span<const PassInfo> all_passes() { return kPasses; }

std::optional<Pass> find_pass(std::string_view name) {
    for (const PassInfo& info : kPasses)
        if (info.name == name) return info.pass;
    return std::nullopt;
}

const PassInfo& pass_info(Pass pass) { return kPasses[static_cast<std::size_t>(pass)]; }

PassResult render_pass(const Scene& scene, const RenderSettings& settings, Pass pass, int threads,
                       const ProgressCallback& progress) {
    // Passes about the eye ray's hit need no secondary rays: stage 1 traces the eye ray alone.
    const bool whole_tree = pass == Pass::reflectance || pass == Pass::ray_depth || pass == Pass::cost;
    RenderSettings traced = settings;
    if (!whole_tree) traced.stage = stage_number(Stage::ray_casting);
    PassResult result;
    std::vector<std::shared_ptr<Probe>> probes; // one a thread
    std::mutex probes_mutex;
    result.render = render_pixels(scene.camera(), threads, progress, [&](RayStats& stats) -> PixelFunction {
        auto probe = std::make_shared<Probe>(scene, traced, settings, stats);
        const std::lock_guard lock(probes_mutex);
        probes.push_back(probe);
        return [&scene, &settings, pass, probe](double x, double y) {
            probe->tracer.trace_pixel(x, y);
            return pass_pixel(pass, scene, settings, *probe);
        };
    });
    result.summary = detail::finish_pass(pass, result.render.image);
    if (pass == Pass::shadow) {
        std::uint64_t acne = 0;
        for (const std::shared_ptr<Probe>& probe : probes) acne += probe->acne_pixels;
        result.summary += acne == 0 ? "; no shadow feeler hit the surface it starts from"
                                    : "; at " + std::to_string(acne) + " pixels a shadow feeler hit the very surface it "
                                      "starts from: shadow acne (lab 2, spawn_ray())";
    }
    return result;
}

} // namespace whitted
