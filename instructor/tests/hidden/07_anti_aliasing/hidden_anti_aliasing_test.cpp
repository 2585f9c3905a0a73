// Hidden tests of lab 7: other grids and jitters than the public tests, an edge at
// a quarter of a pixel, and a scene with 6 samples a pixel (a 3 x 2 grid).
#include "whitted/labs.hpp"

#include "image_check.hpp"
#include "lab_helpers.hpp"

#include <gtest/gtest.h>

using namespace whitted;
using namespace whitted::testing_helpers;

TEST(HiddenStratifiedSample, LargerAndOddGrids) {
    // 16 = 4 x 4: sample 13 is column 1, row 3 -> ((1 + 0.2) / 4, (3 + 0.6) / 4).
    Vec2 p = stratified_sample(13, 16, Vec2(0.2, 0.6));
    EXPECT_NEAR(p.x, 0.3, 1e-15);
    EXPECT_NEAR(p.y, 0.9, 1e-15);
    // 10 = 5 x 2: sample 7 is column 2, row 1 -> ((2 + 0.5) / 5, (1 + 0.5) / 2).
    p = stratified_sample(7, 10, Vec2(0.5, 0.5));
    EXPECT_NEAR(p.x, 0.5, 1e-15);
    EXPECT_NEAR(p.y, 0.75, 1e-15);
    // 7 is prime: 7 x 1.
    p = stratified_sample(6, 7, Vec2(0.0, 0.9));
    EXPECT_NEAR(p.x, 6.0 / 7.0, 1e-15);
    EXPECT_NEAR(p.y, 0.9, 1e-15);
    // 18 = 6 x 3 (3 is the largest divisor up to sqrt(18) = 4.24).
    p = stratified_sample(17, 18, Vec2(0.0, 0.0));
    EXPECT_NEAR(p.x, 5.0 / 6.0, 1e-15);
    EXPECT_NEAR(p.y, 2.0 / 3.0, 1e-15);
}

TEST(HiddenPixelColor, SixteenSamplesSeeAQuarterOfThePixel) {
    // The black wall left of viewport x = 2.25 (a quarter into column 2), white sky:
    // 4 of 16 samples (one column of the 4 x 4 grid) are black.
    const Scene scene(black_left_of(2.25));
    RayStats stats;
    const RenderSettings settings = with_samples(16);
    const Tracer tracer(scene, settings, stats);
    EXPECT_NEAR(pixel_color(tracer, 2, 3).g, 0.75, 1e-12);
    EXPECT_NEAR(pixel_color(tracer, 2, 4).g, 0.75, 1e-12);
}

TEST(HiddenLab7Image, HiddenSceneMatchesTheReference) {
    expect_matches_reference(ImageCheck{"instructor/tests/hidden/scenes/07_anti_aliasing_hidden.p3f",
                                        "instructor/tests/hidden/07_anti_aliasing/07_anti_aliasing_hidden.png", 7});
}
