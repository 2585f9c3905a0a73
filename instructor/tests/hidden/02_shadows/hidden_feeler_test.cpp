// Hidden lab 2 tests of spawn_ray and is_lit: tiny and far-away shapes, rays leaving from inside
// a sphere, lights inside boxes and very close to the surface.
#include "test_helpers.hpp"
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;

namespace {

/// A unit vector on the sphere of directions, for sample i of a spiral.
Vec3 spiral(int i) {
    const double phi = 0.3 + i * 0.0047, theta = 0.1 + i * 0.0021;
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

} // namespace

TEST(HiddenSpawnRay, GrazingRaysLeavingATinyFarAwaySphereDoNotHitIt) {
    // r = 0.05 around (5000, -3000, 2000): rounding errors (about 1e-12) are large next to the radius.
    const Sphere sphere{Point3(5000, -3000, 2000), 0.05};
    int self_hits = 0;
    for (int i = 0; i < 1000; ++i) {
        const Vec3 n = spiral(i);
        const auto hit = intersect_sphere(Ray{sphere.center + 3.0 * n, -n}, sphere, Interval{});
        ASSERT_TRUE(hit.has_value());
        const Vec3 tangent = glm::normalize(glm::cross(n, Vec3(0.6, -0.2, 0.7)));
        const Vec3 grazing = glm::normalize(tangent + 0.01 * n);
        const Ray feeler = spawn_ray(*hit, grazing);
        if (intersect_sphere(feeler, sphere, Interval{})) ++self_hits;
        if (!leaves_from(*hit, grazing, feeler)) ++self_hits; // it must start at the hit point, in its direction
    }
    EXPECT_EQ(self_hits, 0);
}

TEST(HiddenSpawnRay, RaysFromInsideASphereReflectBackOrLeave) {
    // Hits on the inner wall, seen from the centre: the normal faces the centre. A ray back towards the
    // centre (into the inside) meets the opposite wall at t = 2 r; a ray leaving outwards meets nothing.
    const Sphere sphere{Point3(-40, 25, 60), 2.0};
    int wrong = 0;
    for (int i = 0; i < 1000; ++i) {
        const Vec3 n = spiral(i);
        const auto hit = intersect_sphere(Ray{sphere.center, n}, sphere, Interval{});
        ASSERT_TRUE(hit.has_value());
        const auto across = intersect_sphere(spawn_ray(*hit, -n), sphere, Interval{});
        if (!across || std::abs(across->t - 4.0) > 5e-5) ++wrong; // the offset grows with the coordinates (about 60 here)
        if (intersect_sphere(spawn_ray(*hit, glm::normalize(n + 0.3 * spiral(i + 7))), sphere, Interval{})) ++wrong;
    }
    EXPECT_EQ(wrong, 0);
}

TEST(HiddenSpawnRay, RaysThroughAFarAwayTriangleCrossItOnce) {
    // A triangle near (12000, -8000, 3000): rays that go on through it must start on the far side,
    // rays that leave it at grazing angles must not find it again.
    const Point3 p0(12000, -8000, 3000);
    const Triangle triangle{p0, p0 + Vec3(50, 5, 0), p0 + Vec3(3, 40, 20)};
    const Vec3 n = glm::normalize(glm::cross(triangle.p1 - p0, triangle.p2 - p0));
    const Vec3 along = glm::normalize(triangle.p1 - p0);
    int wrong = 0;
    for (int i = 0; i < 500; ++i) {
        const Point3 target = p0 + (0.1 + 0.0007 * i) * (triangle.p1 - p0) + (0.1 + 0.0009 * i) * (triangle.p2 - p0);
        const Vec3 d = glm::normalize(-n + 0.002 * i * along);
        const auto hit = intersect_triangle(Ray{target - 30.0 * d, d}, triangle, Interval{});
        ASSERT_TRUE(hit.has_value());
        const Ray through = spawn_ray(*hit, d);
        if (!leaves_from(*hit, d, through)) ++wrong;
        if (glm::dot(through.origin - hit->point, n) >= 0.0) ++wrong;
        if (intersect_triangle(through, triangle, Interval{})) ++wrong;
        if (intersect_triangle(spawn_ray(*hit, glm::normalize(along + 1e-6 * n)), triangle, Interval{})) ++wrong;
        if (intersect_triangle(spawn_ray(*hit, glm::normalize(along - 1e-6 * n)), triangle, Interval{})) ++wrong;
    }
    EXPECT_EQ(wrong, 0);
}

TEST(HiddenIsLit, LightInsideABoxIsHiddenFromTheFloor) {
    // The light at (0, 1, 0) is inside the box (-1, 0.5, -1)..(1, 1.5, 1); the feeler from the floor enters the box.
    const PointLight light{Point3(0, 1, 0), Color(1.0)};
    const Scene scene = scene_of({Plane{Point3(0.0), Vec3(0, 1, 0)}, Box{{-1, 0.5, -1}, {1, 1.5, 1}}},
                                 diffuse_material(Color(1.0)), {light});
    const TestTracer t(scene, 2);
    EXPECT_FALSE(is_lit(t.tracer, surface_hit({3, 0, 0}, {0, 1, 0}), light));
    EXPECT_FALSE(is_lit(t.tracer, surface_hit({0, 0, 0}, {0, 1, 0}), light));
    // A light over the box at (0, 3, 0) is seen from (3, 0, 0): at x = 1 the feeler is already at height 2.
    const PointLight above{Point3(0, 3, 0), Color(1.0)};
    EXPECT_TRUE(is_lit(t.tracer, surface_hit({3, 0, 0}, {0, 1, 0}), above));
}

TEST(HiddenIsLit, DarkSideOfASphereIsShadowedByTheSphereItself) {
    const Sphere sphere{Point3(2, 3, -1), 1.5};
    const PointLight light{Point3(2, 10, -1), Color(1.0)};
    const Scene scene = scene_of({sphere}, diffuse_material(Color(1.0)), {light});
    const TestTracer t(scene, 2);
    const auto bottom = intersect_sphere(Ray{Point3(2, -5, -1), Vec3(0, 1, 0)}, sphere, Interval{});
    ASSERT_TRUE(bottom);
    EXPECT_FALSE(is_lit(t.tracer, *bottom, light)) << "the feeler from the bottom goes through the sphere";
    const auto top = intersect_sphere(Ray{Point3(2, 9, -1), Vec3(0, -1, 0)}, sphere, Interval{});
    ASSERT_TRUE(top);
    EXPECT_TRUE(is_lit(t.tracer, *top, light));
}

TEST(HiddenIsLit, FarAwaySceneKeepsItsShadowsAndLights) {
    // Around (1e5, 2e5, -3e5): the light 50 above the floor point, blockers at 25 and at 60.
    const Point3 p(1e5, 2e5, -3e5);
    const PointLight light{p + Vec3(0, 50, 0), Color(1.0)};
    const Hit hit = surface_hit(p, {0, 1, 0});
    const Plane floor{p, Vec3(0, 1, 0)};
    const Scene between = scene_of({floor, Sphere{p + Vec3(0, 25, 0), 1.0}}, diffuse_material(Color(1.0)), {light});
    const Scene beyond = scene_of({floor, Sphere{p + Vec3(0, 60, 0), 1.0}}, diffuse_material(Color(1.0)), {light});
    const TestTracer a(between, 2), b(beyond, 2);
    EXPECT_FALSE(is_lit(a.tracer, hit, light));
    EXPECT_TRUE(is_lit(b.tracer, hit, light));
}

TEST(HiddenIsLit, LightAMillimetreAboveTheSurfaceIsSeen) {
    const PointLight light{Point3(0.5, 1e-3, -0.25), Color(1.0)};
    const Scene scene = scene_of({Plane{Point3(0.0), Vec3(0, 1, 0)}}, diffuse_material(Color(1.0)), {light});
    const TestTracer t(scene, 2);
    EXPECT_TRUE(is_lit(t.tracer, surface_hit({0.5, 0, -0.25}, {0, 1, 0}), light));
    // A speck from height 3e-4 to 7e-4 between them hides it.
    const Scene speck = scene_of({Plane{Point3(0.0), Vec3(0, 1, 0)}, Sphere{Point3(0.5, 5e-4, -0.25), 2e-4}},
                                 diffuse_material(Color(1.0)), {light});
    const TestTracer s(speck, 2);
    EXPECT_FALSE(is_lit(s.tracer, surface_hit({0.5, 0, -0.25}, {0, 1, 0}), light));
}

TEST(HiddenIsLit, LowWallBlocksAGrazingLight) {
    // Light far away along x at height 1; a wall x = 5 up to height 0.5 (a triangle) stops feelers from
    // points before it, not from points past it.
    const PointLight light{Point3(100, 1, 0), Color(1.0)};
    const Triangle wall{{5, 0, -10}, {5, 0, 10}, {5, 0.5, 0}};
    const Scene scene = scene_of({Plane{Point3(0.0), Vec3(0, 1, 0)}, wall}, diffuse_material(Color(1.0)), {light});
    const TestTracer t(scene, 2);
    EXPECT_FALSE(is_lit(t.tracer, surface_hit({0, 0, 0}, {0, 1, 0}), light));
    EXPECT_TRUE(is_lit(t.tracer, surface_hit({6, 0, 0}, {0, 1, 0}), light));
}
