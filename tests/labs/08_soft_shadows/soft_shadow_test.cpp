// Lab 8 with labs 2 and 3: an area light lights a point through the point
// lights light_samples() makes of it (Tracer::lights()), so a point in the
// penumbra gets the light of the points it sees and no more.
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;

namespace {

// A white diffuse floor y = 0 under a 2 x 2 square light at height 10 (4 points,
// a 2 x 2 grid); with `blocker`, a roof at height 5 over everything left of x = 0.
// Seen from the origin, the roof hides exactly the light's points with x < 0 (the
// line to (x, 10, z) crosses height 5 at x / 2): the left column of the grid,
// whatever the jitter.
SceneData penumbra_scene(bool blocker) {
    SceneData data;
    data.materials = {diffuse_material(Color(1.0))};
    data.primitives.push_back({Plane{Point3(0.0), Vec3(0.0, 1.0, 0.0)}, 0});
    if (blocker)
        data.primitives.push_back({Triangle{Point3(0.0, 5.0, -100.0), Point3(0.0, 5.0, 100.0), Point3(-100.0, 5.0, 0.0)}, 0});
    data.area_lights = {square_light(Point3(0.0, 10.0, 0.0), 2.0, 4)};
    return data;
}

/// Lambert's sum over the light's points that `visible` keeps: (1/4) x kd x cos theta each.
template <class Visible>
double expected_lambert(const AreaLight& light, const PixelSample& sample, Visible visible) {
    double sum = 0.0;
    for (int k = 0; k < light.samples; ++k) {
        const Point3 p = expected_light_point(light, sample, k);
        if (visible(p)) sum += 0.25 * p.y / glm::length(p); // cos theta = (p - 0) . (0, 1, 0) / |p|
    }
    return sum;
}

} // namespace

TEST(SoftShadow, AFullyLitPointGetsTheLightOfEveryPoint) {
    const Scene scene(penumbra_scene(false));
    const RenderSettings settings = soft_shadow_settings();
    RayStats stats;
    const Tracer tracer(scene, settings, stats);
    const PixelSample sample{4, 6, 0};
    tracer.begin_pixel(sample);
    ASSERT_EQ(tracer.lights().size(), 4u) << "Tracer::lights(): the area light as its 4 points";
    const Color c = lambert(tracer, surface_hit(Point3(0.0), Vec3(0.0, 1.0, 0.0)));
    EXPECT_NEAR(c.g, expected_lambert(scene.area_lights()[0], sample, [](const Point3&) { return true; }), 1e-12);
    EXPECT_EQ(stats.shadow, 4u) << "one shadow feeler to each point";
}

TEST(SoftShadow, InThePenumbraOnlyTheVisiblePointsLight) {
    const Scene scene(penumbra_scene(true));
    const RenderSettings settings = soft_shadow_settings();
    RayStats stats;
    const Tracer tracer(scene, settings, stats);
    for (const PixelSample sample : {PixelSample{0, 0, 0}, PixelSample{9, 1, 2}}) {
        tracer.begin_pixel(sample);
        const Color c = lambert(tracer, surface_hit(Point3(0.0), Vec3(0.0, 1.0, 0.0)));
        const double expected = expected_lambert(scene.area_lights()[0], sample, [](const Point3& p) { return p.x > 0.0; });
        EXPECT_NEAR(c.g, expected, 1e-12) << "half the light is hidden: the two points right of x = 0 light the floor";
        EXPECT_GT(c.g, 0.0);
    }
}

TEST(SoftShadow, BlinnPhongLightsWithThePointsToo) {
    // The same penumbra with lab 3: ambient plus the diffuse light of the visible points.
    SceneData data = penumbra_scene(true);
    data.ambient = Color(0.1);
    const Scene scene(data);
    const RenderSettings settings = soft_shadow_settings();
    RayStats stats;
    const Tracer tracer(scene, settings, stats);
    const PixelSample sample{3, 3, 0};
    tracer.begin_pixel(sample);
    const Color c = blinn_phong(tracer, surface_hit(Point3(0.0), Vec3(0.0, 1.0, 0.0)), Vec3(0.0, 1.0, 0.0));
    const double diffuse = expected_lambert(scene.area_lights()[0], sample, [](const Point3& p) { return p.x > 0.0; });
    EXPECT_NEAR(c.g, 0.1 + diffuse, 1e-12);
}
