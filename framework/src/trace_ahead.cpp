// Tracing a block of pixels with packets of rays: look ahead, then trace.
//
// Why: the scene answers rays that travel together faster as packets (the
// reference renderer's leaf kernels), but the shading, the labs' code, asks for
// one ray at a time, in the order of the recursion. So trace_pixels() first
// looks ahead: it finds the hits of the block's eye rays as one packet, runs
// the labs' local shading (lab 2 or 3) at each hit with occluded() noting each
// shadow feeler instead of tracing it (and answering "not blocked"), and finds
// those feelers, light by light, as packets too. Then it traces each pixel
// exactly as trace_pixel() does, and a query is answered from what was found
// only when it is the very same query, bit for bit: the same eye ray, the same
// feeler, or the same hit's local colour when none of its feelers turned out
// blocked (the shading then gets the very answers it got ahead). A guess that
// turns out wrong costs time, never a different image. A pixel whose eye ray
// met nothing is not traced: it gets what trace_pixel() would give it, the
// colour escaping rays see, counted as one ray (Engine::escaped_eye_ray()).
//
// Only the eye rays and their feelers: the secondary rays of neighbouring
// pixels part ways, and looking ahead for them (measured with reflections,
// refractions and their feelers down to depth 5) cost more than their packets
// saved: 15-19 % slower on balls4, flake5 and mount6, 1 % faster on teapot6.
#include "lab_call.hpp"
#include "tracer_engine.hpp"

#include "whitted/engine/remote_queries.hpp"
#include "whitted/labs.hpp"

#include <algorithm>
#include <memory>
#include <utility>

namespace whitted {

std::optional<Hit> Tracer::Engine::closest_hit(const Ray& ray, int depth) const {
    if (depth == 1 && ahead && same_bits(ahead->eye, ray)) return ahead->hit;
    return scene.closest_hit(ray);
}

std::optional<bool> Tracer::Engine::blocked_ahead(const Ray& ray, double distance) const {
    if (ahead)
        for (const Feeler& feeler : ahead->feelers)
            if (same_bits(feeler.ray, ray) && same_bits(feeler.distance, distance)) return feeler.blocked;
    return std::nullopt;
}

std::optional<Color> Tracer::Engine::local_ahead(const Ray& ray, int depth) {
    if (depth != 1 || !ahead || !ahead->local_if_lit || !same_bits(ahead->eye, ray)) return std::nullopt;
    for (const Feeler& feeler : ahead->feelers)
        if (feeler.blocked) return std::nullopt; // the colour differs: shade again, with the answers
    // Sent again, the feelers would count against the pixel's budget: only when all fit.
    const std::size_t sent = ahead->feelers.size();
    if (pixel_rays + sent > settings.max_rays_per_pixel) return std::nullopt;
    pixel_rays += static_cast<std::uint32_t>(sent);
    stats.shadow += sent;
    return ahead->local_if_lit;
}

namespace {

// Points `slot` at `value` while it lives, and at nothing after (even when the
// labs' code in between throws): occluded() noting feelers, a pixel's answers.
template <class T>
class PointingWhileAlive {
  public:
    PointingWhileAlive(T*& slot, T* value) : slot_(slot) { slot_ = value; }
    ~PointingWhileAlive() { slot_ = nullptr; }
    PointingWhileAlive(const PointingWhileAlive&) = delete;
    PointingWhileAlive& operator=(const PointingWhileAlive&) = delete;

  private:
    T*& slot_;
};

// Computes the local colour of `hit` (seen along wo) as shade() will, with
// every shadow feeler taken as unblocked, and notes the feelers it sends, each
// with the light it goes to; returns the colour and how many lights there are.
std::pair<Color, std::size_t> shade_as_if_lit(const Tracer& tracer, Tracer::Engine& e, const Hit& hit, const Vec3& wo,
                                              std::vector<Tracer::Engine::Feeler>& feelers) {
    const std::span<const PointLight> lights = tracer.lights();
    Color local;
    {
        const PointingWhileAlive collecting(e.collecting_feelers, &feelers);
        local = e.local_colour(tracer, hit, wo);
    }
    // The labs send at most one feeler a light, in the order of the lights, each
    // as far as its light: that names the light, which groups feelers into
    // packets. A feeler that matches no light joins the next light's group (or
    // the last one's): a less coherent packet, the same answers.
    std::size_t next = 0; // the lights before it have had their feeler
    std::size_t groups = 0;
    for (Tracer::Engine::Feeler& feeler : feelers) {
        std::size_t l = next;
        while (l < lights.size() && !same_bits(glm::length(lights[l].position - hit.point), feeler.distance)) ++l;
        if (l >= lights.size()) l = lights.empty() ? 0 : std::min(next, lights.size() - 1);
        feeler.light = l;
        next = l + 1;
        groups = std::max(groups, l + 1); // find_blockers() must trace every group
    }
    return {local, std::max(lights.size(), groups)};
}

// Finds whether the noted feelers are blocked, those towards one light together.
void find_blockers(Tracer::Engine& e, std::size_t light_count) {
    Tracer::Engine::Scratch& s = e.scratch;
    for (std::size_t l = 0; l < light_count; ++l) {
        s.rays.clear();
        s.ranges.clear();
        s.feelers.clear();
        for (Tracer::Engine::Ahead& ahead : s.block) {
            for (Tracer::Engine::Feeler& feeler : ahead.feelers) {
                if (feeler.light != l) continue;
                s.rays.push_back(feeler.ray);
                s.ranges.push_back(feeler_range(feeler.distance));
                s.feelers.push_back(&feeler);
            }
        }
        if (s.blocked_room < s.rays.size()) {
            s.blocked_room = std::max<std::size_t>(s.rays.size(), 64);
            s.blocked = std::make_unique<bool[]>(s.blocked_room);
        }
        // The light's slot of the former blockers: what blocked the last feeler towards it is tried first.
        std::uint32_t& former = e.blockers[l % Tracer::Engine::kBlockerSlots];
        e.scene.occluded_rays(s.rays, s.ranges, std::span(s.blocked.get(), s.rays.size()), former);
        for (std::size_t f = 0; f < s.feelers.size(); ++f) s.feelers[f]->blocked = s.blocked[f];
    }
}

} // namespace

void Tracer::trace_pixels(std::span<const Vec2> positions, std::span<Color> colors) const {
    Engine& e = *engine_;
    if (const RemoteSceneQueries* remote = remote_scene_queries(); remote && remote->trace_pixels && !e.tree) [[unlikely]] {
        remote->trace_pixels(*this, positions, colors);
        return;
    }
    const Camera& camera = e.scene.camera();
    const bool lens = camera.aperture > 0.0 && e.settings.stage >= stage_number(Stage::depth_of_field);
    if (e.tree || lens || !e.scene.queries_packets()) {
        for (std::size_t i = 0; i < positions.size(); ++i) colors[i] = trace_pixel(positions[i].x, positions[i].y);
        return;
    }
    // The eye rays, as shade() asks for their hits (closest_hit(ray): any t).
    Engine::Scratch& s = e.scratch;
    const std::size_t count = positions.size();
    s.block.resize(count);
    // Each eye ray made in its place: a Ray returned and then copied is read back
    // in 16-byte pieces from 8-byte stores, which stalls on every ray.
    s.rays.resize(count);
    {
        const detail::LabCall running("primary_ray");
        for (std::size_t i = 0; i < count; ++i) ::new (&s.rays[i]) Ray(primary_ray(camera, positions[i].x, positions[i].y));
    }
    s.ranges.assign(count, Interval{});
    s.hits.assign(count, std::nullopt);
    e.scene.closest_hits(s.rays, s.ranges, s.hits);
    // Their feelers.
    std::size_t light_count = 0;
    for (std::size_t i = 0; i < count; ++i) {
        Engine::Ahead& ahead = s.block[i];
        ahead.eye = s.rays[i];
        ahead.hit = s.hits[i];
        ahead.feelers.clear();
        ahead.local_if_lit.reset();
        if (!ahead.hit || e.settings.stage < stage_number(Stage::shadows)) continue;
        e.begin_pixel(pixel_at(positions[i].x), pixel_at(positions[i].y), 0); // the lights of this pixel's sample
        const auto [local, lights] = shade_as_if_lit(*this, e, *ahead.hit, -ahead.eye.direction, ahead.feelers);
        ahead.local_if_lit = local;
        light_count = std::max(light_count, lights);
    }
    find_blockers(e, light_count);
    // Each pixel as trace_pixel() traces it, its queries answered from above
    // (or, where its eye ray met nothing, with what that trace would give).
    for (std::size_t i = 0; i < count; ++i) {
        if (!s.block[i].hit) { // it met nothing: no query of its recursion to answer
            e.begin_pixel(pixel_at(positions[i].x), pixel_at(positions[i].y), 0);
            ::new (&colors[i]) Color(e.escaped_eye_ray(s.block[i].eye));
            continue;
        }
        const PointingWhileAlive answering(e.ahead, &std::as_const(s.block[i]));
        ::new (&colors[i]) Color(trace_pixel(positions[i].x, positions[i].y)); // written in place, as the rays above
    }
}

} // namespace whitted
