// is_lit: a shadow feeler from the hit point towards the light, which only counts blockers
// strictly between the point and the light.
#include "test_helpers.hpp"
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;

namespace {

// The floor y = 0, the point at its origin and a white light 4 above it.
const Plane kFloor{Point3(0.0), Vec3(0, 1, 0)};
const Hit kPoint = surface_hit(Point3(0.0), Vec3(0, 1, 0));
const PointLight kLight{Point3(0, 4, 0), Color(1.0)};

/// is_lit for kPoint and kLight, with the floor and `blocker` in the scene.
bool lit_with(const Shape& blocker) {
    const Scene scene = scene_of({kFloor, blocker}, diffuse_material(Color(1.0)), {kLight});
    const TestTracer t(scene, 2);
    return is_lit(t.tracer, kPoint, kLight);
}

} // namespace

TEST(IsLit, NothingInTheWayMeansLit) {
    const Scene scene = scene_of({kFloor}, diffuse_material(Color(1.0)), {kLight});
    const TestTracer t(scene, 2);
    EXPECT_TRUE(is_lit(t.tracer, kPoint, kLight))
        << "the point lies on the floor: the feeler must not find the floor it starts on (use spawn_ray)";
}

TEST(IsLit, BlockerBetweenThePointAndTheLightCastsAShadow) {
    // A sphere of radius 0.5 at height 2 lies across the feeler (0 < t < 4).
    EXPECT_FALSE(lit_with(Sphere{Point3(0, 2, 0), 0.5})) << "the sphere at height 1.5..2.5 is between the point and the light";
    EXPECT_FALSE(lit_with(Triangle{{-1, 3, -1}, {1, 3, -1}, {0, 3, 1}})) << "a triangle at height 3 blocks the light";
}

TEST(IsLit, BlockerBeyondTheLightCastsNoShadow) {
    // The sphere at height 6 is met at t = 5.5, beyond the light (t = 4).
    EXPECT_TRUE(lit_with(Sphere{Point3(0, 6, 0), 0.5}))
        << "stop the feeler at the light: occluded(ray, distance to the light)";
}

TEST(IsLit, BlockerBehindThePointOrBesideTheFeelerCastsNoShadow) {
    EXPECT_TRUE(lit_with(Sphere{Point3(0, -2, 0), 0.5}))
        << "the sphere is under the floor, behind the point: the feeler goes from the point towards the light";
    EXPECT_TRUE(lit_with(Sphere{Point3(2, 2, 0), 0.5})) << "the sphere is beside the feeler, not on it";
}

TEST(IsLit, TheFeelerStopsExactlyAtTheLightDistance) {
    // Spheres around (0, 4.5, 0): with radius 0.501 the near side is at height 3.999 (just before the
    // light, a shadow); with radius 0.499 it is at 4.001 (just beyond the light, no shadow).
    EXPECT_FALSE(lit_with(Sphere{Point3(0, 4.5, 0), 0.501})) << "a blocker 0.001 before the light still blocks it";
    EXPECT_TRUE(lit_with(Sphere{Point3(0, 4.5, 0), 0.499}))
        << "a blocker 0.001 beyond the light does not: the feeler's range is the distance |light - p|";
}

TEST(IsLit, EveryPointOfASphereFacingTheLightIsLit) {
    // A sphere alone with a light: every point whose normal leans towards the light sees it.
    // Feelers that start exactly on the surface, or that start at the light and stop at the
    // point, find the sphere itself about half of the time because of rounding.
    const Sphere sphere{Point3(0.3, -1.7, 2.9), 1.3};
    const PointLight light{sphere.center + 6.0 * glm::normalize(Vec3(0.2, 0.9, 0.4)), Color(1.0)};
    const Scene scene = scene_of({sphere}, diffuse_material(Color(1.0)), {light});
    const TestTracer t(scene, 2);
    int shadowed = 0, tested = 0;
    for (int i = 0; i < 1000; ++i) {
        const double phi = 0.1 + i * 0.0063, theta = 0.05 + i * 0.0029;
        const Vec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
        const auto hit = intersect_sphere(Ray{sphere.center + 5.0 * n, -n}, sphere, Interval{});
        ASSERT_TRUE(hit.has_value());
        if (glm::dot(hit->normal, glm::normalize(light.position - hit->point)) < 0.05) continue;
        ++tested;
        if (!is_lit(t.tracer, *hit, light)) ++shadowed;
    }
    ASSERT_GT(tested, 100);
    EXPECT_EQ(shadowed, 0) << "of " << tested << " points facing the light, " << shadowed
                           << " were in shadow: the feeler found the sphere it starts on (shadow acne)";
}
