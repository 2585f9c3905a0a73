// Hidden tests of lab 8: a leaning parallelogram with a 3 x 2 grid, a lamp seen
// edge-on from the floor (its points still light it), the share of a coloured
// light, and a scene with two area lights and a point light.
#include "whitted/labs.hpp"

#include "image_check.hpp"
#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace whitted;
using namespace whitted::testing_helpers;

TEST(HiddenPointOnLight, ALeaningParallelogram) {
    AreaLight light;
    light.center = Point3(1.0, 2.0, 3.0);
    light.edge_u = Vec3(2.0, 2.0, 0.0);
    light.edge_v = Vec3(0.0, 1.0, -1.0);
    // (0.75, 0.25): 0.25 edge_u - 0.25 edge_v = (0.5, 0.5 - 0.25, 0.25).
    expect_point(point_on_light(light, Vec2(0.75, 0.25)), Point3(1.5, 2.25, 3.25), "(0.75, 0.25)");
    expect_point(point_on_light(light, Vec2(0.0, 1.0)), Point3(0.0, 1.5, 2.5), "(0, 1)");
}

TEST(HiddenLightSamples, SixPointsOnAThreeByTwoGridOfALeaningLight) {
    SceneData data;
    AreaLight other = square_light(Point3(0.0, 9.0, 0.0), 1.0, 5);
    AreaLight light;
    light.center = Point3(-1.0, 6.0, 2.0);
    light.color = Color(0.6, 0.3, 0.9);
    light.edge_u = Vec3(2.0, 0.0, 0.5);
    light.edge_v = Vec3(0.0, 0.4, 1.5);
    light.samples = 6;
    data.area_lights = {other, light};
    const Scene scene(data);
    const AreaLight& second = scene.area_lights()[1];
    ASSERT_EQ(second.first_number, 5u);
    RayStats stats;
    const RenderSettings settings = soft_shadow_settings();
    const Tracer tracer(scene, settings, stats);
    const PixelSample sample{17, 4, 5};
    tracer.begin_pixel(sample);
    const std::vector<PointLight> points = light_samples(tracer, second);
    ASSERT_EQ(points.size(), 6u);
    for (int k = 0; k < 6; ++k) {
        const PointLight& point = points[static_cast<std::size_t>(k)];
        expect_point(point.position, expected_light_point(second, sample, k), "point " + std::to_string(k));
        EXPECT_NEAR(point.color.b, 0.15, 1e-15) << "an equal share of 0.9";
    }
}

TEST(HiddenSoftShadow, TracerLightsHoldEveryPointOfEveryLight) {
    SceneData data;
    data.lights = {PointLight{Point3(0.0, 5.0, 0.0), Color(0.5)}};
    data.area_lights = {square_light(Point3(2.0, 5.0, 0.0), 1.0, 4), square_light(Point3(-2.0, 5.0, 0.0), 1.0, 9)};
    const Scene scene(data);
    RayStats stats;
    const RenderSettings settings = soft_shadow_settings();
    const Tracer tracer(scene, settings, stats);
    tracer.begin_pixel(PixelSample{1, 1, 0});
    EXPECT_EQ(tracer.lights().size(), 1u + 4u + 9u);
}

TEST(HiddenLab8Image, HiddenSceneMatchesTheReference) {
    expect_matches_reference(ImageCheck{"instructor/tests/hidden/scenes/08_soft_shadows_hidden.p3f",
                                        "instructor/tests/hidden/08_soft_shadows/08_soft_shadows_hidden.png", 8});
}
