// lambert: for every light that reaches the point, light colour x kd x (n . L), where
// kd = Kd x colour_at(point), L is the unit vector towards the light, and lights behind the
// surface or in shadow give nothing. The floor z = 0 faces +z, so direction_at(theta) is
// theta degrees from its normal.
#include "test_helpers.hpp"
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;

namespace {

// Diffuse colour C = (0.5, 1, 0.25) with weight Kd = 0.6: kd = (0.3, 0.6, 0.15).
const Material kMaterial = shiny_material(Color(0.5, 1.0, 0.25), 0.6);
const Color kKd(0.3, 0.6, 0.15);
const Hit kOrigin = surface_hit(Point3(0.0), kUp);

/// lambert() at the floor's origin with these lights (and any extra shapes).
Color lambert_at_origin(std::vector<PointLight> lights, std::vector<Shape> extra = {}) {
    extra.push_back(floor_z0());
    const Scene scene = scene_of(std::move(extra), kMaterial, std::move(lights));
    const TestTracer t(scene, 2);
    return lambert(t.tracer, kOrigin);
}

} // namespace

TEST(Lambert, LightAt60DegreesGivesHalfOfKdTimesTheLight) {
    // n . L = cos 60 = 0.5: (0.8, 0.6, 0.4) x (0.3, 0.6, 0.15) x 0.5 = (0.12, 0.18, 0.03).
    const Color c = lambert_at_origin({{2.0 * direction_at(60.0), Color(0.8, 0.6, 0.4)}});
    EXPECT_TRUE(near(c, {0.12, 0.18, 0.03}, 1e-12))
        << "expected light colour x Kd x C x (n . L) with n . L = 0.5; L must be a unit vector";
}

TEST(Lambert, LightStraightAboveGivesKdTimesTheLight) {
    // n . L = 1: (0.8, 0.6, 0.4) x (0.3, 0.6, 0.15) = (0.24, 0.36, 0.06).
    const Color c = lambert_at_origin({{3.0 * kUp, Color(0.8, 0.6, 0.4)}});
    EXPECT_TRUE(near(c, {0.24, 0.36, 0.06}, 1e-12)) << "kd = Kd (the material's `diffuse`) x its colour";
}

TEST(Lambert, DistanceToTheLightDoesNotMatter) {
    // Whitted's point lights do not fade with distance: only the angle counts.
    const Color close = lambert_at_origin({{0.5 * direction_at(60.0), Color(1.0)}});
    const Color far = lambert_at_origin({{70.0 * direction_at(60.0), Color(1.0)}});
    EXPECT_TRUE(near(close, 0.5 * kKd, 1e-12)) << "normalise L: n . L must be cos 60 = 0.5 at any distance";
    EXPECT_TRUE(near(far, 0.5 * kKd, 1e-12)) << "normalise L: n . L must be cos 60 = 0.5 at any distance";
}

TEST(Lambert, ColouredLightsAddChannelByChannel) {
    // Red (1, 0, 0) overhead: (0.3, 0, 0). Blue (0, 0, 1) at 60 degrees: (0, 0, 0.075).
    // Green (0, 0.5, 0) at 45 degrees: (0, 0.3 cos 45, 0). Sum: (0.3, 0.3 cos 45, 0.075).
    const Color c = lambert_at_origin({{4.0 * kUp, Color(1, 0, 0)},
                                       {5.0 * direction_at(-60.0), Color(0, 0, 1)},
                                       {2.0 * direction_at(45.0), Color(0, 0.5, 0)}});
    EXPECT_TRUE(near(c, {0.3, 0.3 * std::cos(radians(45.0)), 0.075}, 1e-12))
        << "each light adds its own colour x kd x (n . L), channel by channel";
}

TEST(Lambert, LightBehindTheSurfaceGivesNothing) {
    // At 120 degrees from the normal n . L = -0.5: the light is under the floor and adds nothing,
    // it must not take light away either.
    EXPECT_TRUE(near(lambert_at_origin({{3.0 * direction_at(120.0), Color(1.0)}}), Color(0.0), 0.0))
        << "n . L < 0: no light from behind the surface (and never negative light)";
    const Color with_both = lambert_at_origin({{3.0 * kUp, Color(1.0)}, {3.0 * direction_at(-150.0), Color(1.0)}});
    EXPECT_TRUE(near(with_both, kKd, 1e-12)) << "the light overhead gives kd; the one below must add nothing";
}

TEST(Lambert, ShadowedLightGivesNothingWhileTheOtherStillShines) {
    // A sphere halfway to the overhead light shadows it; the light at 60 degrees still reaches the point.
    const Color c = lambert_at_origin({{4.0 * kUp, Color(1.0)}, {4.0 * direction_at(60.0), Color(1.0)}},
                                      {Sphere{Point3(0, 0, 2), 0.5}});
    EXPECT_TRUE(near(c, 0.5 * kKd, 1e-12)) << "only lights that is_lit() says reach the point count";
}

TEST(Lambert, LightsBehindTheSurfaceGetNoShadowFeeler) {
    // Lights at 0, 120 and -100 degrees from the normal: only the first faces the point (n . L = 1 > 0), so
    // lambert() gives kd and casts one shadow feeler (tracer statistics count it): the other two lights give
    // nothing whatever a feeler would say, and need none.
    const Scene scene = scene_of({floor_z0()}, kMaterial,
                                 {{3.0 * kUp, Color(1.0)}, {3.0 * direction_at(120.0), Color(1.0)},
                                  {3.0 * direction_at(-100.0), Color(1.0)}});
    const TestTracer t(scene, 2);
    EXPECT_TRUE(near(lambert(t.tracer, kOrigin), kKd, 1e-12));
    EXPECT_EQ(t.stats.shadow, 1u) << "test n . L > 0 first: lights behind the surface (n . L <= 0) get no feeler";
}

TEST(Lambert, SmoothSurfaceIsShadedWithItsShadingNormal) {
    // A flat triangle in z = 0 whose vertex normals lean 30 degrees towards +x: hit.normal = n =
    // (sin 30, 0, cos 30), hit.geometric_normal = +z. A tinted light (0.8, 0.6, 0.4) straight above: n . L = cos 30,
    // so (0.8, 0.6, 0.4) x kd x cos 30. A white light at direction_at(-70) is above the flat triangle but
    // 100 degrees from n: n . L < 0, nothing. (The geometric normal would give kd x (0.8, 0.6, 0.4) + kd cos 70.)
    const Scene scene = smooth_floor_scene(direction_at(30.0), {}, kMaterial,
                                           {{3.0 * kUp, Color(0.8, 0.6, 0.4)}, {4.0 * direction_at(-70.0), Color(1.0)}});
    const TestTracer t(scene, 2);
    const Color c = lambert(t.tracer, smooth_floor_hit(scene));
    EXPECT_TRUE(near(c, Color(0.8, 0.6, 0.4) * kKd * std::cos(radians(30.0)), 1e-12))
        << "n . L uses hit.normal, the shading normal (hit.geometric_normal is for offsetting rays)";
}

TEST(Lambert, CheckerboardReplacesTheDiffuseColour) {
    // Checker cubes of side 1: (0.5, 0.5, 0) is in cube (0, 0, 0), colour a; (1.5, 0.5, 0) in cube
    // (1, 0, 0), colour b. Each point has a white light straight above it: Kd x colour_at(p).
    Material checkered = shiny_material(Color(1.0), 0.5);
    checkered.checker = Checker{Color(1.0, 0.5, 0.0), Color(0.0, 0.5, 1.0), 1.0};
    const Scene scene = scene_of({floor_z0()}, checkered, {{Point3(0.5, 0.5, 2), Color(1.0)}});
    const Scene shifted = scene_of({floor_z0()}, checkered, {{Point3(1.5, 0.5, 2), Color(1.0)}});
    const TestTracer t(scene, 2), u(shifted, 2);
    EXPECT_TRUE(near(lambert(t.tracer, surface_hit({0.5, 0.5, 0}, kUp)), {0.5, 0.25, 0.0}, 1e-12))
        << "use material.color_at(hit.point), not material.color: checkers replace the colour";
    EXPECT_TRUE(near(lambert(u.tracer, surface_hit({1.5, 0.5, 0}, kUp)), {0.0, 0.25, 0.5}, 1e-12))
        << "use material.color_at(hit.point), not material.color: checkers replace the colour";
}

TEST(Lambert, TracedEyeRayAtStage2SeesLambertLight) {
    // The whole stage: an eye ray straight down onto the floor at the origin, one light at 60 degrees.
    const Scene scene = scene_of({floor_z0()}, kMaterial, {{3.0 * direction_at(60.0), Color(0.8)}});
    const Color c = trace_one(scene, Ray{Point3(0, 0, 1), -kUp}, 2);
    EXPECT_TRUE(near(c, 0.8 * 0.5 * kKd, 1e-12));
}

TEST(Lambert, TracedEyeRaySeesTheShadowOfASphere) {
    // A small sphere halfway between the floor point and the light: no light arrives. One unit to
    // the side the feeler passes the sphere: n . L = 4 / sqrt(17).
    const Scene scene = scene_of({floor_z0(), Sphere{Point3(0, 0, 2), 0.2}}, shiny_material(Color(1.0), 1.0),
                                 {{Point3(0, 0, 4), Color(1.0)}});
    EXPECT_TRUE(near(trace_one(scene, Ray{Point3(0.5, 0.5, 1), glm::normalize(Vec3(-0.5, -0.5, -1))}, 2), Color(0.0), 0.0))
        << "the point under the sphere is in its shadow";
    EXPECT_TRUE(near(trace_one(scene, Ray{Point3(1, 0, 1), -kUp}, 2), Color(4.0 / std::sqrt(17.0)), 1e-12));
}

TEST(Lambert, LightsComeFromTheTracer) {
    // A lamp with a size (`arealight`) lights through tracer.lights(); before lab 8 it is one
    // point light at its centre with all its colour. Straight above the origin: n . L = 1, so
    // (0.8, 0.6, 0.4) x kd = (0.24, 0.36, 0.06).
    SceneData data = scene_data_of({floor_z0()}, kMaterial, {});
    data.area_lights = {AreaLight{Point3(0.0, 0.0, 4.0), Color(0.8, 0.6, 0.4), Vec3(1.0, 0.0, 0.0), Vec3(0.0, 1.0, 0.0), 4}};
    const Scene scene(data);
    const TestTracer t(scene, 2);
    EXPECT_TRUE(near(lambert(t.tracer, kOrigin), {0.24, 0.36, 0.06}, 1e-12))
        << "loop over tracer.lights(): scene.point_lights() leaves out the scene's area lights";
}
