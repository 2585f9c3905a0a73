// Lab 7, pixel_color(): the average of the pixel's samples, each traced through
// the place stratified_sample() gives it, with the framework's numbers.
#include "whitted/labs.hpp"
#include "whitted/render.hpp"

#include "lab_helpers.hpp"
#include "test_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

using namespace whitted;
using namespace whitted::testing_helpers;

namespace {

/// A lit, tilted floor filling the lower half of the image: its shading changes
/// across every pixel, so each sample's exact place shows in the colour.
SceneData shaded_floor() {
    SceneData data;
    data.camera = eight_by_eight();
    data.background = Color(0.2, 0.4, 0.9);
    data.ambient = Color(0.1);
    data.lights = {PointLight{Point3(3.0, 5.0, 2.0), Color(1.0, 0.9, 0.8)}};
    data.materials = {diffuse_material(Color(0.9, 0.6, 0.3))};
    data.primitives.push_back({Plane{Point3(0.0, -1.0, 0.0), glm::normalize(Vec3(0.3, 1.0, 0.2))}, 0});
    return data;
}

/// The grid the handout describes.
Vec2 expected_place(int k, int count, Vec2 u) {
    const SampleGrid grid = sample_grid(count);
    return Vec2((k % grid.cols + u.x) / grid.cols, (k / grid.cols + u.y) / grid.rows);
}

} // namespace

TEST(PixelColor, APixelHalfCoveredByAnEdgeIsHalfGrey) {
    // The edge runs down the middle of the pixels of column 3 (x = 3.5): with 4 samples
    // (2 x 2 cells) exactly two fall left of it, whatever their jitter: (0 + 0 + 1 + 1) / 4.
    const Scene scene(black_left_of(3.5));
    RayStats stats;
    const RenderSettings settings = with_samples(4);
    const Tracer tracer(scene, settings, stats);
    for (int y = 3; y <= 4; ++y) {
        const Color c = pixel_color(tracer, 3, y);
        EXPECT_NEAR(c.r, 0.5, 1e-12) << "pixel (3, " << y << ")";
        EXPECT_EQ(c.r, c.b);
    }
    EXPECT_NEAR(pixel_color(tracer, 2, 4).r, 0.0, 1e-12) << "a pixel left of the edge is black";
    EXPECT_NEAR(pixel_color(tracer, 5, 4).r, 1.0, 1e-12) << "a pixel right of the edge is white";
}

TEST(PixelColor, NineSamplesSeeAThirdOfThePixelAsAThird) {
    // The edge at x = 3 + 1/3: the first of three columns of cells is black, 3 of 9 samples.
    const Scene scene(black_left_of(3.0 + 1.0 / 3.0));
    RayStats stats;
    const RenderSettings settings = with_samples(9);
    const Tracer tracer(scene, settings, stats);
    EXPECT_NEAR(pixel_color(tracer, 3, 4).r, 6.0 / 9.0, 1e-12);
}

TEST(PixelColor, EachSampleIsTracedWhereStratifiedSamplePutsIt) {
    // Sample k of pixel (x, y): the numbers sample_numbers({x, y, k}, SampleUse::pixel),
    // placed by the grid, traced through viewport position (x + place.x, y + place.y).
    const Scene scene(shaded_floor());
    for (int count : {1, 4, 6}) {
        RayStats stats;
        const RenderSettings settings = with_samples(count);
        const Tracer tracer(scene, settings, stats);
        const Tracer expected_tracer(scene, settings, stats);
        for (auto [x, y] : {std::pair{0, 0}, {3, 1}, {7, 2}, {5, 0}}) {
            Color expected(0.0);
            for (int k = 0; k < count; ++k) {
                const PixelSample sample{x, y, k};
                const Vec2 place = expected_place(k, count, sample_numbers(sample, SampleUse::pixel));
                expected += expected_tracer.trace_sample(sample, x + place.x, y + place.y);
            }
            expected /= static_cast<double>(count);
            const Color got = pixel_color(tracer, x, y);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(got[c], expected[c], 1e-12) << count << " samples, pixel (" << x << ", " << y << "), channel " << c;
            if (enough_failures()) return;
        }
    }
}

TEST(PixelColor, TracesOneEyeRayASample) {
    const Scene scene(black_left_of(3.5)); // no lights and no mirrors: eye rays only
    for (int count : {1, 4, 9}) {
        RayStats stats;
        const RenderSettings settings = with_samples(count);
        const Tracer tracer(scene, settings, stats);
        pixel_color(tracer, 3, 4);
        EXPECT_EQ(stats.eye, static_cast<std::uint64_t>(count)) << count << " samples a pixel";
    }
}

TEST(PixelColor, ThePictureIsTheSameForAnyThreadCountAndEveryRun) {
    // The numbers belong to the pixel and the sample, not to the order pixels are traced in.
    SceneData data = shaded_floor();
    data.camera = data.camera.with_resolution(40, 30);
    const Scene scene(data);
    const RenderSettings settings = with_samples(4);
    const Image one = render(scene, settings, 1).image;
    const Image two = render(scene, settings, 2).image;
    const Image again = render(scene, settings, 1).image;
    ASSERT_EQ(one.pixels.size(), two.pixels.size());
    EXPECT_EQ(0, std::memcmp(one.pixels.data(), two.pixels.data(), one.pixels.size() * sizeof(Color)));
    EXPECT_EQ(0, std::memcmp(one.pixels.data(), again.pixels.data(), one.pixels.size() * sizeof(Color)));
    // And it is the scene: the top row (the image's first) sees only the sky, every sample of it the
    // background (0.2, 0.4, 0.9); the bottom row only the lit floor, another colour.
    ASSERT_EQ(one.width, 40);
    EXPECT_TRUE(near(one.at(20, 0), Color(0.2, 0.4, 0.9), 1e-12)) << "a pixel of the sky shows the background";
    EXPECT_FALSE(near(one.at(20, 29), Color(0.2, 0.4, 0.9), 0.05)) << "a pixel of the floor shows the floor";
}
