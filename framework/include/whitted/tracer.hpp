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
#include "whitted/sampling.hpp"
#include "whitted/scene.hpp"

#include <cstdint>
#include <memory>
#include <span>

namespace whitted {

/// Rays cast during a render, by kind.
struct RayStats {
    std::uint64_t eye = 0;
    std::uint64_t shadow = 0;
    std::uint64_t reflected = 0;
    std::uint64_t refracted = 0;
    std::uint64_t pixels_cut_short = 0; // pixels (or pixel samples) whose ray tree reached RenderSettings::max_rays_per_pixel

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
    // Distribution ray tracing (P3F `spp`), from the anti-aliasing stage on:
    // 0 traces one ray through each pixel centre (Whitted); n > 0 averages n
    // samples a pixel (lab 7's pixel_color), each with its own ray budget.
    int samples_per_pixel = 0;
};

/// What a tracer carries from ray to ray within one pixel: handed across the
/// grading link (instructor/link/) so that a lab function run in another process
/// continues exactly where this one stands.
struct TracerState {
    RayStats stats;
    Color path_weight{1.0};
    std::uint32_t pixel_rays = 0;
    bool pixel_cut_short = false;
    PixelSample sample;            // the pixel sample being traced (its random numbers)
};

class Tracer;

/// Where a tracer's recursion runs when another program holds the labs it
/// calls. Only the grader uses it: it runs your lab code in a program of its
/// own and sends each trace() and trace_sample() your code makes to the
/// program that holds the other labs, in one message instead of one per
/// shading call inside it. Your code never needs it.
class TraceForwarding {
  public:
    virtual Color trace(const Tracer& tracer, const Ray& ray, int depth, RayKind kind, const Color& weight) const = 0;
    virtual Color trace_sample(const Tracer& tracer, const PixelSample& sample, double x, double y) const = 0;

  protected:
    ~TraceForwarding() = default;
};

class Tracer {
  public:
    /// A tracer for one thread: `stats` receives this thread's ray counts and
    /// `tree`, when given, the ray tree of the last pixel traced.
    Tracer(const Scene& scene, const RenderSettings& settings, RayStats& stats, RayTree* tree = nullptr);
    Tracer(const Tracer& other);
    Tracer& operator=(const Tracer& other);
    ~Tracer();

    const Scene& scene() const;
    const RenderSettings& settings() const;

    /// The colour seen along `ray`, which is at `depth` in the ray tree (eye ray:
    /// 1), multiplied by `weight`: the coefficient (Ks, T, Kr...) with which this
    /// ray adds to the colour of the ray it came from. Black when the ray's
    /// accumulated weight is too small to matter (see RenderSettings::min_weight).
    Color trace(const Ray& ray, int depth, RayKind kind, const Color& weight) const;

    /// The colour seen through viewport position (x, y) (see primary_ray): one
    /// eye ray, with a ray budget of its own, as sample 0 of the pixel that
    /// contains (x, y). Whitted ray tracing calls it with each pixel's centre.
    Color trace_pixel(double x, double y) const;

    /// trace_pixel() for each of several viewport positions (colors[i] for
    /// positions[i]), bit for bit: with a scene that walks packets of rays, the
    /// pixels' eye rays go together, and so do the shadow feelers from their
    /// hits towards each light. The render loop calls it for 4 x 4 pixel blocks.
    void trace_pixels(std::span<const Vec2> positions, std::span<Color> colors) const;

    /// The colour of one sample of a pixel, seen through viewport position (x, y)
    /// inside that pixel: like trace_pixel, and the sample's random numbers (for
    /// the lens, the lights) are those of `sample`.
    Color trace_sample(const PixelSample& sample, double x, double y) const;

    /// The pixel sample being traced (set by trace_sample, and by trace_pixel to
    /// sample 0 of the pixel it traces; pixel (0, 0), sample 0 before).
    const PixelSample& pixel_sample() const;

    /// The lights that light this pixel sample, as point lights: the scene's
    /// point lights, then each area light as the points lab 8's light_samples()
    /// takes on it (before the soft-shadows stage, one point at its centre with
    /// all its colour). Shading code loops over these.
    std::span<const PointLight> lights() const;

    /// Starts pixel sample `sample`: its ray budget, path weight and cut-short
    /// mark from the start. trace_sample() does this itself; code that casts a
    /// pixel's rays another way (the shadow pass's feelers) calls it at each pixel.
    void begin_pixel(const PixelSample& sample) const;

    /// True when something lies along the shadow feeler `ray` with 0 < t < distance.
    /// The range stops a hair (a millionth) short of `distance`, so that a surface
    /// passing through the light itself (a lamp on a wall) does not shadow it.
    bool occluded(const Ray& ray, double distance) const;

    /// This tracer's state (ray counts included) and a way to set it back.
    TracerState state() const;
    void restore(const TracerState& state) const;
    /// True when this tracer writes a ray tree.
    bool records_tree() const;
    /// Sends trace() and trace_sample() to `forwarding` from now on (nullptr: traced here). The grader's only.
    void forward_to(const TraceForwarding* forwarding);

    /// The recursion's machinery (pixel budget, path weight, ray-tree recording), in tracer.cpp.
    struct Engine;

  private:
    std::unique_ptr<Engine> engine_;
};

} // namespace whitted
