// Hidden lab 2 tests of lambert: spheres seen through whole eye rays, small checkers at negative
// coordinates, far lights, grazing lights and mixtures of lit, shadowed and hidden lights.
#include "test_helpers.hpp"
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;

TEST(HiddenLambert, SphereLitAt45DegreesThroughAnEyeRay) {
    // Sphere (2, 1, -3) r 1.5; the eye ray along -z meets (2, 1, -1.5) with normal +z. The light at
    // (7, 1, 3.5) is along (1, 0, 1) / sqrt 2: n . L = cos 45. C = (0.2, 0.9, 0.6), Kd = 0.7, light (1, 0.5, 2).
    const Scene scene = scene_of({Sphere{{2, 1, -3}, 1.5}}, shiny_material(Color(0.2, 0.9, 0.6), 0.7),
                                 {{Point3(7, 1, 3.5), Color(1, 0.5, 2)}});
    const Color c = trace_one(scene, Ray{Point3(2, 1, 10), Vec3(0, 0, -1)}, 2);
    EXPECT_TRUE(near(c, 0.7 * std::cos(radians(45.0)) * Color(0.2, 0.45, 1.2), 1e-12));
}

TEST(HiddenLambert, SmallCheckersAtNegativeCoordinates) {
    // Cubes of side 0.25 on the floor y = 0: (-0.1, 0, -0.3) is in cube (-1, 0, -2), odd: colour b;
    // (-0.3, 0, -0.3) is in cube (-2, 0, -2), even: colour a. Kd = 0.9, a white light straight above.
    Material m = shiny_material(Color(1.0), 0.9);
    m.checker = Checker{Color(0.2, 0.4, 0.6), Color(0.9, 0.1, 0.3), 0.25};
    const Vec3 up(0, 1, 0);
    const Scene odd = scene_of({Plane{Point3(0.0), up}}, m, {{Point3(-0.1, 5, -0.3), Color(1.0)}});
    const Scene even = scene_of({Plane{Point3(0.0), up}}, m, {{Point3(-0.3, 5, -0.3), Color(1.0)}});
    const TestTracer t(odd, 2), u(even, 2);
    EXPECT_TRUE(near(lambert(t.tracer, surface_hit({-0.1, 0, -0.3}, up)), 0.9 * Color(0.9, 0.1, 0.3), 1e-12));
    EXPECT_TRUE(near(lambert(u.tracer, surface_hit({-0.3, 0, -0.3}, up)), 0.9 * Color(0.2, 0.4, 0.6), 1e-12));
}

TEST(HiddenLambert, VeryFarLightAt30Degrees) {
    const Scene scene = scene_of({floor_z0()}, shiny_material(Color(0.6, 0.3, 0.9), 0.5),
                                 {{1e4 * direction_at(30.0), Color(0.4, 0.8, 1.0)}});
    const TestTracer t(scene, 2);
    EXPECT_TRUE(near(lambert(t.tracer, surface_hit(Point3(0.0), kUp)),
                     std::cos(radians(30.0)) * 0.5 * Color(0.24, 0.24, 0.9), 1e-12));
}

TEST(HiddenLambert, GrazingLightGivesAlmostNothing) {
    const Scene scene = scene_of({floor_z0()}, shiny_material(Color(1.0), 1.0), {{3.0 * direction_at(89.0), Color(1.0)}});
    const TestTracer t(scene, 2);
    EXPECT_TRUE(near(lambert(t.tracer, surface_hit(Point3(0.0), kUp)), Color(std::cos(radians(89.0))), 1e-12));
}

TEST(HiddenLambert, OnlyTheLightThatIsInFrontAndUnblockedCounts) {
    // Red light at 20 degrees (blocked by a sphere on its way), green at 100 degrees (behind the floor),
    // blue at -50 degrees (reaches the point): only blue counts.
    const Scene scene = scene_of({floor_z0(), Sphere{2.0 * direction_at(20.0), 0.4}}, shiny_material(Color(0.5), 0.8),
                                 {{4.0 * direction_at(20.0), Color(1, 0, 0)},
                                  {4.0 * direction_at(100.0), Color(0, 1, 0)},
                                  {4.0 * direction_at(-50.0), Color(0, 0, 1)}});
    const TestTracer t(scene, 2);
    EXPECT_TRUE(near(lambert(t.tracer, surface_hit(Point3(0.0), kUp)), Color(0, 0, 0.4 * std::cos(radians(50.0))), 1e-12));
}

TEST(HiddenLambert, ZeroDiffuseWeightIsBlack) {
    const Scene scene = scene_of({floor_z0()}, shiny_material(Color(0.7, 0.8, 0.9), 0.0), {{3.0 * kUp, Color(1.0)}});
    const TestTracer t(scene, 2);
    EXPECT_TRUE(near(lambert(t.tracer, surface_hit(Point3(0.0), kUp)), Color(0.0), 0.0));
    // With Kd = 0.5 the light straight above (n . L = 1, white) shows half the colour.
    const Scene half = scene_of({floor_z0()}, shiny_material(Color(0.7, 0.8, 0.9), 0.5), {{3.0 * kUp, Color(1.0)}});
    const TestTracer h(half, 2);
    EXPECT_TRUE(near(lambert(h.tracer, surface_hit(Point3(0.0), kUp)), Color(0.35, 0.4, 0.45), 1e-12));
}

TEST(HiddenLambert, InsideOfAHollowSphereIsLitByALightInside) {
    // An inward sphere r 4 around the origin with a light at its centre: at the point (0, -4, 0) the
    // normal faces the centre and n . L = 1.
    const Scene scene = scene_of({Sphere{Point3(0.0), 4.0, true}}, shiny_material(Color(0.3, 0.6, 0.9), 1.0),
                                 {{Point3(0.0), Color(1.0)}});
    const Color c = trace_one(scene, Ray{Point3(0, 1, 0), Vec3(0, -1, 0)}, 2);
    EXPECT_TRUE(near(c, {0.3, 0.6, 0.9}, 1e-12));
}
