// The tracer's eye ray and the thin lens: the lens is used from the depth-of-field
// stage on and only by a camera with an aperture, so that every pinhole picture
// (and every picture before lab 9) stays bit for bit what it was.
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

using namespace whitted;
using namespace whitted::testing_helpers;

namespace {

/// The eye ray the tracer casts for sample `sample` through viewport position (x, y).
Ray traced_eye_ray(const Scene& scene, int stage, const PixelSample& sample, double x, double y) {
    RenderSettings settings;
    settings.stage = stage;
    RayStats stats;
    RayTree tree;
    const Tracer tracer(scene, settings, stats, &tree);
    tracer.trace_sample(sample, x, y);
    return tree.nodes.at(0).ray;
}

void expect_identical(const Ray& got, const Ray& expected, const char* what) {
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(got.origin[i], expected.origin[i]) << what << ": origin, coordinate " << i;
        EXPECT_EQ(got.direction[i], expected.direction[i]) << what << ": direction, coordinate " << i;
    }
}

} // namespace

TEST(DepthOfFieldStage, APinholeCameraTracesPrimaryRaysAtEveryStage) {
    SceneData data = black_left_of(3.5);
    data.camera = tilted_lens_camera(0.0, 2.5, 8, 8);
    const Scene scene(data);
    for (int stage = 1; stage <= kLabCount; ++stage)
        expect_identical(traced_eye_ray(scene, stage, PixelSample{2, 5, 3}, 2.3, 5.9), primary_ray(scene.camera(), 2.3, 5.9),
                         "aperture 0");
}

TEST(DepthOfFieldStage, BeforeLab9ALensCameraIsAPinhole) {
    SceneData data = black_left_of(3.5);
    data.camera = tilted_lens_camera(0.4, 2.5, 8, 8);
    const Scene scene(data);
    for (int stage = 1; stage < stage_number(Stage::depth_of_field); ++stage)
        expect_identical(traced_eye_ray(scene, stage, PixelSample{2, 5, 3}, 2.3, 5.9), primary_ray(scene.camera(), 2.3, 5.9),
                         "before the depth-of-field stage");
}

TEST(DepthOfFieldStage, FromLab9EachSampleTakesTheLensRayOfItsLensNumbers) {
    SceneData data = black_left_of(3.5);
    data.camera = tilted_lens_camera(0.4, 2.5, 8, 8);
    const Scene scene(data);
    const int stage = stage_number(Stage::depth_of_field);
    for (const PixelSample& sample : {PixelSample{2, 5, 3}, PixelSample{2, 5, 4}, PixelSample{6, 0, 0}}) {
        const Vec2 lens_u = sample_numbers(sample, SampleUse::lens);
        expect_identical(traced_eye_ray(scene, stage, sample, 2.3, 5.9), thin_lens_ray(scene.camera(), 2.3, 5.9, lens_u),
                         "the depth-of-field stage");
    }
    // Different samples of one pixel start from different points of the lens.
    const Ray a = traced_eye_ray(scene, stage, PixelSample{2, 5, 3}, 2.3, 5.9);
    const Ray b = traced_eye_ray(scene, stage, PixelSample{2, 5, 4}, 2.3, 5.9);
    EXPECT_GT(glm::length(a.origin - b.origin), 1e-6);
}
