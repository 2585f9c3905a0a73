// The recursive ray tracer of the slides, `trace(ray, depth)`, and the
// per-render settings it follows.
//
// Why: the framework owns the recursion's skeleton (find the closest hit, add
// the local colour, then the reflected and refracted contributions) so that
// each lab can replace one piece of it. The labs receive a `Tracer` to cast
// shadow feelers and to call `trace()` again for secondary rays; it also counts
// rays for `--stats` and, when given a RayTree, records every ray it casts.
#pragma once

#include "whitted/lab_table.hpp"
#include "whitted/ray_tree.hpp"
#include "whitted/scene.hpp"

#include <cstdint>

namespace whitted {

/// Rays cast during a render, by kind.
struct RayStats {
    std::uint64_t eye = 0;
    std::uint64_t shadow = 0;
    std::uint64_t reflected = 0;
    std::uint64_t refracted = 0;
    std::uint64_t pixels_cut_short = 0; // pixels whose ray tree reached RenderSettings::max_rays_per_pixel

    std::uint64_t total() const { return eye + shadow + reflected + refracted; }
    /// Counts one ray of the given kind.
    void count(RayKind kind);
    RayStats& operator+=(const RayStats& other);
};

/// Which labs' features a render uses: stage k renders with labs 1..k.
struct RenderSettings {
    int stage = kLabCount; // 1..kLabCount: whitted/lab_table.hpp names the stages
    int max_depth = 5;  // deepest ray in the ray tree; the eye ray is depth 1
    // Whitted's adaptive depth control: a secondary ray whose accumulated weight
    // (the product of the coefficients on its path from the eye) is below this in
    // every channel is not traced. 1/1024 cannot move an 8-bit pixel by half a
    // step for colours up to 2; 0 traces every ray down to max_depth.
    double min_weight = 1.0 / 1024.0;
    // A last guard for ray trees that would grow without bound (glass at a huge
    // depth with min_weight 0): once a pixel has cast this many rays, its
    // further secondary rays see black and the pixel is counted as cut short.
    std::uint32_t max_rays_per_pixel = 10000;
};

/// What a tracer carries from ray to ray within one pixel: handed across the
/// grading link (instructor/link/) so that a lab function run in another process
/// continues exactly where this one stands.
struct TracerState {
    RayStats stats;
    Color path_weight{1.0};
    std::uint32_t pixel_rays = 0;
    bool pixel_cut_short = false;
};

class Tracer {
  public:
    /// A tracer for one thread: `stats` receives this thread's ray counts and
    /// `tree`, when given, the ray tree of the last pixel traced.
    Tracer(const Scene& scene, const RenderSettings& settings, RayStats& stats, RayTree* tree = nullptr)
        : scene_(scene), settings_(settings), stats_(stats), tree_(tree) {}

    const Scene& scene() const { return scene_; }
    const RenderSettings& settings() const { return settings_; }

    /// The colour seen along `ray`, which is at `depth` in the ray tree (eye ray:
    /// 1), multiplied by `weight`: the coefficient (Ks, T, Kr...) with which this
    /// ray adds to the colour of the ray it came from. Black when the ray's
    /// accumulated weight is too small to matter (see RenderSettings::min_weight).
    Color trace(const Ray& ray, int depth, RayKind kind, const Color& weight) const;

    /// The colour of the pixel sample at viewport position (x, y) (see primary_ray).
    Color trace_pixel(double x, double y) const;

    /// Starts a new pixel: its ray budget, path weight and cut-short mark from
    /// the start. trace_pixel() does this itself; code that casts a pixel's rays
    /// another way (the shadow pass's feelers) calls it at each pixel.
    void begin_pixel() const;

    /// True when something lies along the shadow feeler `ray` with 0 < t < distance.
    /// The range stops a hair (a millionth) short of `distance`, so that a surface
    /// passing through the light itself (a lamp on a wall) does not shadow it.
    bool occluded(const Ray& ray, double distance) const;

    /// This tracer's state (ray counts included) and a way to set it back.
    TracerState state() const { return {stats_, path_weight_, pixel_rays_, pixel_cut_short_}; }
    void restore(const TracerState& state) const {
        stats_ = state.stats;
        path_weight_ = state.path_weight;
        pixel_rays_ = state.pixel_rays;
        pixel_cut_short_ = state.pixel_cut_short;
    }
    /// True when this tracer writes a ray tree.
    bool records_tree() const { return tree_ != nullptr; }

  private:
    Color shade(const Ray& ray, int depth) const;

    // Ray tree recording: only with a tree, and kept out of the way of renders without one.
    [[gnu::cold, gnu::noinline]] int record_ray(const Ray& ray, Interval t_range, int depth, RayKind kind,
                                                const Color& weight) const;
    [[gnu::cold, gnu::noinline]] void record_feeler(const Ray& ray, Interval t_range, double distance, RayFate fate,
                                                    bool blocked) const;
    [[gnu::cold, gnu::noinline]] void note(std::optional<Color> RayNode::*part, const Color& color) const;
    [[gnu::noinline]] Color trace_recorded(const Ray& ray, int depth, RayKind kind, const Color& weight) const;
    [[gnu::noinline]] bool occluded_recorded(const Ray& ray, double distance) const;
    /// Whitted's adaptive depth control: a secondary ray too weak to change the pixel.
    bool too_weak(RayKind kind, const Color& path_weight) const {
        return kind != RayKind::eye && glm::all(glm::lessThan(path_weight, Color(settings_.min_weight)));
    }
    /// Returns `color` after writing it into the ray being shaded as one of its parts.
    Color noted(std::optional<Color> RayNode::*part, const Color& color) const {
        if (tree_) [[unlikely]]
            note(part, color);
        return color;
    }

    const Scene& scene_;
    const RenderSettings& settings_;
    RayStats& stats_;
    RayTree* tree_ = nullptr;
    mutable int current_node_ = -1;         // the ray being shaded, in tree_
    /// Counts one more ray for the current pixel; false once the pixel is over budget.
    bool within_budget() const;

    mutable Color path_weight_{1.0};        // accumulated weight of the ray being traced
    mutable std::uint32_t pixel_rays_ = 0;  // rays cast so far for the current pixel
    mutable bool pixel_cut_short_ = false;
};

} // namespace whitted
