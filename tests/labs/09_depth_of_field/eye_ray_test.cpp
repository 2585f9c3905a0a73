// Lab 9 in the renderer: from the depth-of-field stage on, a camera with an
// aperture traces each pixel sample's eye ray with thin_lens_ray(), from the lens
// point of the sample's own lens numbers; points in the plane in focus stay
// sharp, points off it blur.
#include "whitted/labs.hpp"
#include "whitted/render.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <cstring>

using namespace whitted;
using namespace whitted::testing_helpers;

namespace {

/// lab 7's black wall at depth 10, left of viewport x = edge, seen through a lens
/// `aperture` across focused at depth 10 focal_ratio (the view plane is 1 away).
Scene wall_through_lens(double edge, double aperture, double focal_ratio) {
    SceneData data = black_left_of(edge);
    data.camera.aperture = aperture;
    data.camera.focal_ratio = focal_ratio;
    return Scene(data);
}

} // namespace

TEST(DepthOfFieldEyeRay, EachSampleIsTracedFromTheLensPointOfItsLensNumbers) {
    // The eye ray the tracer records is the ray of the handout: from the lens point of
    // sample_numbers(sample, SampleUse::lens) through the focal point of (x, y).
    SceneData data = black_left_of(3.5);
    data.camera = tilted_lens_camera(0.4, 2.5, 8, 8);
    const Scene scene(data);
    const RenderSettings settings = depth_of_field_settings(4);
    RayStats stats;
    RayTree tree;
    const Tracer tracer(scene, settings, stats, &tree);
    for (const PixelSample& sample : {PixelSample{0, 0, 0}, PixelSample{3, 5, 2}, PixelSample{7, 1, 3}}) {
        const double x = sample.x + 0.3, y = sample.y + 0.8;
        tracer.trace_sample(sample, x, y);
        ASSERT_FALSE(tree.nodes.empty());
        const Ray& traced = tree.nodes[0].ray;
        const Point3 lens = expected_lens_point(scene.camera(), sample_numbers(sample, SampleUse::lens));
        const Vec3 direction = glm::normalize(focal_point(scene.camera(), x, y) - lens);
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(traced.origin[i], lens[i], 1e-14) << "pixel (" << sample.x << ", " << sample.y << ") sample "
                                                          << sample.index << ": origin, coordinate " << i;
            EXPECT_NEAR(traced.direction[i], direction[i], 1e-14) << "pixel (" << sample.x << ", " << sample.y
                                                                  << ") sample " << sample.index << ": direction, coordinate " << i;
        }
    }
}

TEST(DepthOfFieldEyeRay, AnEdgeInTheFocalPlaneStaysSharp) {
    // Focused on the wall (depth 10 = 10 view distances): every lens ray of a sample meets
    // the wall where the pinhole ray does, so a pixel halved by the edge is exactly half
    // grey with 4 samples (2 x 2 cells) and its neighbours are black and white, through a
    // lens 4 units across.
    const Scene scene = wall_through_lens(3.5, 4.0, 10.0);
    RayStats stats;
    const RenderSettings settings = depth_of_field_settings(4);
    const Tracer tracer(scene, settings, stats);
    EXPECT_NEAR(pixel_color(tracer, 3, 4).r, 0.5, 1e-9);
    EXPECT_NEAR(pixel_color(tracer, 2, 4).r, 0.0, 1e-9);
    EXPECT_NEAR(pixel_color(tracer, 4, 4).r, 1.0, 1e-9);
}

TEST(DepthOfFieldEyeRay, AnEdgeOutOfFocusIsBlurredOverItsCircleOfConfusion) {
    // Focused at depth 5, half-way to the wall: a lens ray through the focal point F
    // reaches the wall at 2 F - lens point, a disk of the lens's radius 3 around the
    // pinhole's point: 1.2 pixels (a pixel is 2.5 units wide at depth 10). The neighbours
    // of the edge pixel now see both sides (about 7 % of the other one, by the areas of
    // the disk's segments); pixels 1.5 or more from the edge are untouched.
    const Scene scene = wall_through_lens(3.5, 6.0, 5.0);
    RayStats stats;
    const RenderSettings settings = depth_of_field_settings(64);
    const Tracer tracer(scene, settings, stats);
    const double left = pixel_color(tracer, 2, 4).r, right = pixel_color(tracer, 4, 4).r;
    EXPECT_GT(left, 0.02) << "the pixel left of the edge pixel sees some of the white beyond it";
    EXPECT_LT(right, 0.98) << "the pixel right of the edge pixel sees some of the black wall";
    EXPECT_NEAR(pixel_color(tracer, 1, 4).r, 0.0, 1e-12);
    EXPECT_NEAR(pixel_color(tracer, 6, 4).r, 1.0, 1e-12);
    // Blur moves light around, it does not make or lose any: the row still averages the
    // fraction of the wall left of the edge (3.5 of 8 columns black).
    double sum = 0.0;
    for (int x = 0; x < 8; ++x) sum += pixel_color(tracer, x, 4).r;
    EXPECT_NEAR(sum / 8.0, 4.5 / 8.0, 0.03);
}

TEST(DepthOfFieldEyeRay, OneEyeRayASampleAndThePictureIsTheSameForAnyThreadCount) {
    SceneData data = black_left_of(3.5);
    data.camera = tilted_lens_camera(0.4, 2.5, 24, 16);
    const Scene scene(data);
    const RenderSettings settings = depth_of_field_settings(4);
    const RenderResult one = render(scene, settings, 1);
    const RenderResult two = render(scene, settings, 2);
    EXPECT_EQ(one.stats.eye, 24u * 16u * 4u);
    ASSERT_EQ(one.image.pixels.size(), two.image.pixels.size());
    EXPECT_EQ(0, std::memcmp(one.image.pixels.data(), two.image.pixels.data(), one.image.pixels.size() * sizeof(Color)));
    // And the picture is the lens's: the wall in focus (as in AnEdgeInTheFocalPlaneStaysSharp) keeps its
    // edge sharp, so in row 4 (from the bottom; the image's rows start at the top) pixel 2 is black,
    // pixel 3 half grey and pixel 4 white.
    const Image sharp = render(wall_through_lens(3.5, 4.0, 10.0), settings, 2).image;
    ASSERT_EQ(sharp.height, 8);
    EXPECT_NEAR(sharp.at(2, 3).r, 0.0, 1e-9);
    EXPECT_NEAR(sharp.at(3, 3).r, 0.5, 1e-9);
    EXPECT_NEAR(sharp.at(4, 3).r, 1.0, 1e-9);
}
