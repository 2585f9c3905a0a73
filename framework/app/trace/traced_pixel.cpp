// One pixel's ray tree, traced as `whitted render` computes the pixel (for `whitted trace` and `whitted explore`).
#include "trace/ray_tree_report.hpp"

#include "whitted/lab_table.hpp"
#include "whitted/render.hpp"

namespace whitted {

int traced_samples(const RenderSettings& settings) {
    // As render: samples from lab 7 on, one ray through the pixel's centre before.
    return settings.stage >= stage_number(Stage::anti_aliasing) ? settings.samples_per_pixel : 0;
}

TracedPixel trace_pixel_tree(const Scene& scene, const RenderSettings& settings, int x, int y, int height, int sample) {
    // The same pixel as `whitted render` computes: rows go down, the viewport's y goes up.
    const int row = height - 1 - y;
    RayStats stats;
    TracedPixel traced;
    const Tracer tracer(scene, settings, stats, &traced.tree);
    if (const int samples = traced_samples(settings); samples > 0) {
        // One sample's tree, where pixel_color() traces it; the pixel's value, the average of all its samples,
        // from a tracer that records nothing.
        const PixelSample chosen{x, row, sample};
        const Vec2 position = sample_position(chosen, samples);
        tracer.trace_sample(chosen, position.x, position.y);
        RayStats pixel_stats;
        const Tracer pixel_tracer(scene, settings, pixel_stats);
        traced.sample = ShownSample{chosen.index, samples, position - Vec2(x, row), sampled_pixel_color(pixel_tracer, x, row)};
    } else {
        tracer.trace_pixel(x + 0.5, row + 0.5);
    }
    return traced;
}

} // namespace whitted
