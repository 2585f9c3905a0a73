#include "whitted/passes.hpp"

#include "whitted/labs.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>

namespace whitted {
namespace {

const Color kBackground(0.0);                 // the eye ray hit nothing
const Color kNotApplicable(0.05, 0.05, 0.3);  // dark blue: the pass says nothing here
const Color kShadowBackground(0.0, 0.3, 0.3); // teal: black means "in shadow" in the shadow pass

const std::array<PassInfo, 9> kPasses = {{
    {Pass::normal, "normal", 1,
     "the eye ray's hit normal: red, green, blue = its x, y, z from -1..1 mapped to 0..1; background black"},
    {Pass::depth, "depth", 1, "the eye ray's distance to its hit: nearest white, farthest dark grey; background black"},
    {Pass::albedo, "albedo", 1,
     "the diffuse colour Kd x C at the eye ray's hit (checkerboards included); background black"},
    {Pass::shadow, "shadow", 2,
     "is_lit() at the eye ray's hit for the lights in front of the surface: white = every one reaches it, "
     "black = none, grey = some; dark blue = no light in front; teal = background"},
    {Pass::reflectance, "reflectance", 4,
     "the weight of the eye ray's reflected ray (Ks x specular colour, or Kr with Fresnel); black = none"},
    {Pass::fresnel, "fresnel", 6,
     "fresnel_reflectance() at the eye ray's hit on transparent surfaces, black 0 to white 1; "
     "dark blue = not transparent; background black"},
    {Pass::ray_depth, "ray-depth", 1,
     "the deepest ray of each pixel's ray tree: dark blue = the eye ray only, then green, yellow, red = max depth"},
    {Pass::object_id, "object-id", 1, "one colour per object (per line of the scene file); background black"},
    {Pass::cost, "cost", 1,
     "intersection tests per pixel (ray-box + ray-primitive, every ray of the pixel's tree), log scale: "
     "dark blue = fewest, red = most in this image"},
}};

// A scale for counts: dark blue, light blue, green, yellow, red, from s = 0 to 1.
Color ramp(double s) {
    static const std::array<Color, 5> stops = {Color(0.05, 0.05, 0.45), Color(0.0, 0.55, 0.9), Color(0.0, 0.8, 0.0),
                                               Color(1.0, 0.9, 0.0), Color(1.0, 0.0, 0.0)};
    s = std::clamp(s, 0.0, 1.0) * (stops.size() - 1);
    const std::size_t i = std::min(static_cast<std::size_t>(s), stops.size() - 2);
    return stops[i] + (stops[i + 1] - stops[i]) * (s - static_cast<double>(i));
}

// A bright colour for a number, the same every time.
Color id_color(std::uint32_t key) {
    std::uint32_t h = key * 2654435761u;
    h ^= h >> 15;
    h *= 2246822519u;
    h ^= h >> 13;
    return Color(0.25 + 0.75 * ((h & 0xff) / 255.0), 0.25 + 0.75 * (((h >> 8) & 0xff) / 255.0),
                 0.25 + 0.75 * (((h >> 16) & 0xff) / 255.0));
}

// One thread's tracers: one records each pixel's ray tree; the other, which
// records nothing, casts the shadow pass's feelers (recording them would grow
// the tree while the pass still reads the eye ray's hit from it).
struct Probe {
    RayTree tree;
    Tracer tracer;
    Tracer feelers;
    Probe(const Scene& scene, const RenderSettings& settings, RayStats& stats)
        : tracer(scene, settings, stats, &tree), feelers(scene, settings, stats) {}
};

// At the eye ray's hit: white when every light in front of the surface reaches it, black when none does.
Color shadow_pixel(const Tracer& tracer, const Hit& hit) {
    int facing = 0, lit = 0;
    for (const PointLight& light : tracer.scene().lights()) {
        if (glm::dot(hit.normal, light.position - hit.point) <= 0.0) continue;
        ++facing;
        if (is_lit(tracer, hit, light)) ++lit;
    }
    return facing == 0 ? kNotApplicable : Color(static_cast<double>(lit) / facing);
}

Color fresnel_pixel(const Scene& scene, const RayNode& eye) {
    const Hit& hit = *eye.hit;
    const Material& material = scene.material(hit);
    if (material.transmittance <= 0.0) return kNotApplicable;
    const double eta_i = hit.front_face ? 1.0 : material.ior;
    const double eta_t = hit.front_face ? material.ior : 1.0;
    return Color(fresnel_reflectance(glm::dot(-eye.ray.direction, hit.normal), eta_i, eta_t));
}

// The pixel's value; depth and cost give raw numbers that finish() turns into colours.
Color pass_pixel(Pass pass, const Scene& scene, const RenderSettings& settings, const Probe& probe) {
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
    case Pass::shadow: return shadow_pixel(probe.feelers, hit);
    case Pass::fresnel: return fresnel_pixel(scene, eye);
    case Pass::object_id: {
        const Primitive& primitive = scene.primitives()[hit.primitive];
        return id_color(primitive.line > 0 ? primitive.line : (1u << 24) + primitive.id);
    }
    default: return kBackground;
    }
}

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
    char line[256];
    std::snprintf(line, sizeof line, pattern, a, b, c);
    return line;
}

// Turns raw numbers into colours, and says what the picture holds.
std::string finish(Pass pass, Image& image) {
    std::vector<Color>& pixels = image.pixels;
    const double n = static_cast<double>(std::max<std::size_t>(1, pixels.size()));
    if (pass == Pass::depth) {
        double near = kInfinity, far = 0.0;
        for (const Color& c : pixels)
            if (c.y > 0.0) near = std::min(near, c.x), far = std::max(far, c.x);
        for (Color& c : pixels) {
            if (c.y == 0.0) continue;
            const double s = far > near ? (c.x - near) / (far - near) : 0.0;
            c = Color(1.0 - 0.85 * s);
        }
        return near <= far ? format("distances from %.4g (white) to %.4g (dark grey)", near, far)
                           : "the eye rays hit nothing";
    }
    if (pass == Pass::cost) {
        double most = 0.0, sum = 0.0;
        for (const Color& c : pixels) most = std::max(most, c.x), sum += c.x;
        for (Color& c : pixels) c = ramp(most > 0.0 ? std::log1p(c.x) / std::log1p(most) : 0.0);
        return format("intersection tests per pixel: %.1f on average, %.0f at most", sum / n, most);
    }
    if (pass == Pass::shadow) {
        double none = 0.0, some = 0.0, all = 0.0;
        for (const Color& c : pixels) {
            if (c == kNotApplicable || c == kShadowBackground) continue;
            (c.x == 0.0 ? none : c.x == 1.0 ? all : some) += 1.0;
        }
        // A real shadow covers an area; a lone dark pixel among fully lit ones
        // is almost always a feeler that hit its own surface.
        int speckles = 0;
        const Color lit(1.0);
        for (int y = 1; y + 1 < image.height; ++y)
            for (int x = 1; x + 1 < image.width; ++x)
                speckles += image.at(x, y).x < 1.0 && image.at(x, y) != kNotApplicable &&
                            image.at(x, y) != kShadowBackground && image.at(x - 1, y) == lit &&
                            image.at(x + 1, y) == lit && image.at(x, y - 1) == lit && image.at(x, y + 1) == lit;
        if (none + some + all == 0.0) return "no point the eye rays hit has a light in front of it";
        const double lit_from_front = none + some + all;
        return format("of the points with a light in front: %.1f %% see every such light, %.1f %% some, %.1f %% none",
                      100.0 * all / lit_from_front, 100.0 * some / lit_from_front, 100.0 * none / lit_from_front) +
               (speckles == 0 ? "; no lone dark pixels among lit ones"
                              : "; " + std::to_string(speckles) +
                                    " lone dark pixels among lit ones: speckles, the sign of shadow acne (lab 2)");
    }
    return {};
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
    if (!whole_tree) traced.stage = 1;
    PassResult result;
    result.render = render_pixels(scene.camera(), threads, progress, [&](RayStats& stats) -> PixelFunction {
        auto probe = std::make_shared<Probe>(scene, traced, stats);
        return [&scene, &settings, pass, probe](double x, double y) {
            probe->tracer.trace_pixel(x, y);
            return pass_pixel(pass, scene, settings, *probe);
        };
    });
    result.summary = finish(pass, result.render.image);
    return result;
}

} // namespace whitted
