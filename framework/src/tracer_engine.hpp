// What a tracer holds (private to tracer.cpp and trace_ahead.cpp; the framework's
// own tests include it too).
#pragma once

#include "whitted/tracer.hpp"

#include <bit>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace whitted {

// What a tracer holds: the scene and settings it follows, where its counts go,
// where it stands within the current pixel, and the answers trace_pixels()
// found ahead for it.
struct Tracer::Engine {
    const Scene& scene;
    const RenderSettings& settings;
    RayStats& stats;
    RayTree* tree = nullptr;
    const TraceForwarding* forwarding = nullptr; // where trace() and trace_sample() run, if not here
    Color path_weight{1.0};         // accumulated weight of the ray being traced
    std::uint32_t pixel_rays = 0;   // rays cast so far for the current pixel
    bool pixel_cut_short = false;
    PixelSample sample{};           // the pixel sample being traced
    int current_node = -1;          // the ray being shaded, in tree
    std::vector<PointLight> lights{}; // lights() with area lights, for the sample `lights_for`
    std::optional<PixelSample> lights_for{};
    // What blocked the last feeler towards each light (kNoBlocker: nothing),
    // which the next one tests first: neighbouring points in a shadow are mostly
    // in the shadow of one primitive. The labs send a hit's feelers light by
    // light, so the n-th feeler of a hit takes slot n; the look-ahead's packets
    // take their light's. A wrong slot costs time, never an answer.
    static constexpr std::size_t kBlockerSlots = 4;
    std::uint32_t blockers[kBlockerSlots] = {kNoBlocker, kNoBlocker, kNoBlocker, kNoBlocker};
    std::size_t feelers_sent = 0; // by the hit being shaded

    // Answers found ahead for a pixel by trace_pixels() (trace_ahead.cpp): the
    // hit of its eye ray and the shadow feelers sent from there. A query is
    // answered from here only when it is the very same query, bit for bit, so
    // the image cannot change.
    struct Feeler {
        Ray ray;
        double distance = 0.0;
        std::size_t light = 0; // which of lights()
        bool blocked = false;
    };
    struct Ahead {
        Ray eye;
        std::optional<Hit> hit;
        std::vector<Feeler> feelers;
        // The local colour of `hit`, as shade() computes it when none of the
        // feelers is blocked (the look-ahead ran it with every feeler unblocked).
        std::optional<Color> local_if_lit;
    };
    // trace_pixels()'s working lists; scratch, so a copy of the tracer starts without them.
    struct Scratch {
        Scratch() = default;
        Scratch(const Scratch&) {}
        Scratch& operator=(const Scratch&) { return *this; }
        std::vector<Ahead> block; // one per pixel of the block
        std::vector<Ray> rays;
        std::vector<Interval> ranges;
        std::vector<std::optional<Hit>> hits;
        std::vector<Feeler*> feelers;
        std::unique_ptr<bool[]> blocked; // not vector<bool>: occluded_rays() writes a span of bool
        std::size_t blocked_room = 0;
    };
    Scratch scratch{};
    const Ahead* ahead = nullptr; // the current pixel's answers, while trace_pixels() traces it
    // Set while looking ahead: occluded() notes its feeler here instead of tracing it.
    std::vector<Feeler>* collecting_feelers = nullptr;

    /// Whitted's adaptive depth control: a secondary ray too weak to change the pixel.
    bool too_weak(RayKind kind, const Color& weight) const {
        return kind != RayKind::eye && glm::all(glm::lessThan(weight, Color(settings.min_weight)));
    }
    /// Counts one more ray for the current pixel; false once the pixel is over budget.
    bool within_budget() {
        if (++pixel_rays <= settings.max_rays_per_pixel) return true;
        pixel_cut_short = true;
        return false;
    }
    /// Returns `color` after writing it into the ray being shaded as one of its parts.
    Color noted(std::optional<Color> RayNode::*part, const Color& color) {
        if (tree && current_node >= 0) [[unlikely]]
            tree->nodes[current_node].*part = color;
        return color;
    }

    /// The closest hit along `ray` (any t), which is at `depth`: answered ahead, or asked of the scene.
    std::optional<Hit> closest_hit(const Ray& ray, int depth) const;
    /// Whether the feeler is blocked, if it was answered ahead.
    std::optional<bool> blocked_ahead(const Ray& ray, double distance) const;
    /// The local colour of the hit of `ray` at `depth`, if the look-ahead found
    /// it: counted as the shadow feelers it sends, as if it ran again.
    std::optional<Color> local_ahead(const Ray& ray, int depth);

    /// Tracer::begin_pixel() and trace_sample(), with the sample as three ints:
    /// g++ builds a PixelSample it hands on in memory, with 4-byte stores, and
    /// reads it back 8 bytes at a time before they land (a stall, once a pixel).
    void begin_pixel(int x, int y, int index) {
        sample = PixelSample{x, y, index};
        path_weight = Color(1.0);
        pixel_rays = 0;
        pixel_cut_short = false;
    }
    Color trace_sample(const Tracer& tracer, int px, int py, int index, double x, double y);
    Color escaped_eye_ray(const Ray& eye);

    Color shade(const Tracer& tracer, const Ray& ray, int depth);
    /// The labs' local colour of `hit` seen along wo: Lambert with shadows (lab 2) or Blinn-Phong (lab 3).
    Color local_colour(const Tracer& tracer, const Hit& hit, const Vec3& wo) const;
    // Ray tree recording: only with a tree, and kept out of the way of renders without one.
    [[gnu::noinline]] Color trace_recorded(const Tracer& tracer, const Ray& ray, int depth, RayKind kind, const Color& weight);
    [[gnu::noinline]] bool occluded_recorded(const Ray& ray, double distance);
    [[gnu::cold, gnu::noinline]] int record_ray(const Ray& ray, Interval t_range, int depth, RayKind kind, const Color& weight);
    [[gnu::cold, gnu::noinline]] void record_feeler(const Ray& ray, Interval t_range, double distance, RayFate fate, bool blocked);
};

/// The range of a shadow feeler towards a light `distance` away: it stops a hair
/// (a millionth) short of the light (Tracer::occluded()).
inline Interval feeler_range(double distance) { return Interval{0.0, distance * (1.0 - 1e-6)}; }

/// True when both are the very same bits (a query answered ahead must be this one).
inline bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }
inline bool same_bits(const Ray& a, const Ray& b) {
    bool same = true;
    for (int axis = 0; axis < 3; ++axis) { // no && : every comparison made, no branch between them
        same &= same_bits(a.origin[axis], b.origin[axis]);
        same &= same_bits(a.direction[axis], b.direction[axis]);
    }
    return same;
}

/// The pixel that contains viewport coordinate v, along one axis: sample 0 of
/// that pixel is what trace_pixel() traces (pixel 0 for a coordinate no pixel has).
/// (std::floor without SSE4.1 is a long chain of conversions, on every pixel:
/// this truncates, then steps down where that went up.)
inline int pixel_at(double v) {
    if (!(v > -1e9 && v < 1e9)) return 0;
    const int truncated = static_cast<int>(v); // towards zero
    return v < truncated ? truncated - 1 : truncated;
}

} // namespace whitted
