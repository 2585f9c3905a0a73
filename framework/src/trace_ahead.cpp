// Tracing a block of pixels with packets of rays: look ahead, then trace.
//
// Why: the scene answers rays that travel together faster as packets (the
// reference renderer's leaf kernels), but the shading, the labs' code, asks for
// one ray at a time, in the order of the recursion. So trace_pixels() first
// looks ahead: it finds the hits of the block's eye rays as one packet, asks
// lab 2's own is_lit which shadow feeler each hit sends towards each light
// (with occluded() noting the feeler instead of tracing it), and finds those,
// light by light, as packets too. Then it traces each pixel exactly as
// trace_pixel() does, and a query is answered from what was found only when it
// is the very same query, bit for bit: a guess that turns out wrong costs
// time, never a different image.
//
// Only the eye rays and their feelers: the secondary rays of neighbouring
// pixels part ways, and looking ahead for them (measured with reflections,
// refractions and their feelers down to depth 5) cost more than their packets
// saved: 15-19 % slower on balls4, flake5 and mount6, 1 % faster on teapot6.
#include "tracer_engine.hpp"

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

// Notes the feelers the shading of `hit` will send (the labs send none towards
// a light behind the surface), with the light each goes to; returns how many lights there are.
std::size_t note_feelers(const Tracer& tracer, Tracer::Engine& e, const Hit& hit,
                         std::vector<Tracer::Engine::Feeler>& feelers) {
    const std::span<const PointLight> lights = tracer.lights();
    const PointingWhileAlive collecting(e.collecting_feelers, &feelers);
    for (std::size_t l = 0; l < lights.size(); ++l) {
        if (glm::dot(hit.normal, lights[l].position - hit.point) <= 0.0) continue;
        const std::size_t before = feelers.size();
        is_lit(tracer, hit, lights[l]);
        for (std::size_t f = before; f < feelers.size(); ++f) feelers[f].light = l;
    }
    return lights.size();
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
        e.scene.occluded_rays(s.rays, s.ranges, std::span(s.blocked.get(), s.rays.size()));
        for (std::size_t f = 0; f < s.feelers.size(); ++f) s.feelers[f]->blocked = s.blocked[f];
    }
}

} // namespace

void Tracer::trace_pixels(std::span<const Vec2> positions, std::span<Color> colors) const {
    Engine& e = *engine_;
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
    s.rays.clear();
    for (std::size_t i = 0; i < count; ++i) s.rays.push_back(primary_ray(camera, positions[i].x, positions[i].y));
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
        if (!ahead.hit || e.settings.stage < stage_number(Stage::shadows)) continue;
        begin_pixel(sample_at(positions[i].x, positions[i].y)); // the lights of this pixel's sample
        light_count = std::max(light_count, note_feelers(*this, e, *ahead.hit, ahead.feelers));
    }
    find_blockers(e, light_count);
    // Each pixel as trace_pixel() traces it, its queries answered from above.
    for (std::size_t i = 0; i < count; ++i) {
        const PointingWhileAlive answering(e.ahead, &std::as_const(s.block[i]));
        colors[i] = trace_pixel(positions[i].x, positions[i].y);
    }
}

} // namespace whitted
