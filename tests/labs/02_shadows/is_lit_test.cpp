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
    // A second floor at height 2, between the point and the light, is in the way: no light.
    EXPECT_FALSE(lit_with(Plane{Point3(0, 2, 0), Vec3(0, 1, 0)})) << "a plane at height 2 lies across the feeler";
}

TEST(IsLit, BlockerBetweenThePointAndTheLightCastsAShadow) {
    // A sphere of radius 0.5 at height 2 lies across the feeler (0 < t < 4).
    EXPECT_FALSE(lit_with(Sphere{Point3(0, 2, 0), 0.5})) << "the sphere at height 1.5..2.5 is between the point and the light";
    EXPECT_FALSE(lit_with(Triangle{{-1, 3, -1}, {1, 3, -1}, {0, 3, 1}})) << "a triangle at height 3 blocks the light";
    // The same blockers 3 to the side of the feeler (which runs up the y axis) are not in the way.
    EXPECT_TRUE(lit_with(Sphere{Point3(3, 2, 0), 0.5})) << "the sphere 3 to the side does not block the feeler";
    EXPECT_TRUE(lit_with(Triangle{{2, 3, -1}, {4, 3, -1}, {3, 3, 1}})) << "the triangle 3 to the side does not block it";
}

TEST(IsLit, BlockerBeyondTheLightCastsNoShadow) {
    // The sphere at height 6 is met at t = 5.5, beyond the light (t = 4).
    EXPECT_TRUE(lit_with(Sphere{Point3(0, 6, 0), 0.5}))
        << "stop the feeler at the light: occluded(ray, distance to the light)";
    // The same sphere lowered to height 3 (met at t = 2.5, before the light) blocks it.
    EXPECT_FALSE(lit_with(Sphere{Point3(0, 3, 0), 0.5})) << "at height 2.5..3.5 the sphere is before the light";
}

TEST(IsLit, BlockerBehindThePointOrBesideTheFeelerCastsNoShadow) {
    EXPECT_TRUE(lit_with(Sphere{Point3(0, -2, 0), 0.5}))
        << "the sphere is under the floor, behind the point: the feeler goes from the point towards the light";
    EXPECT_TRUE(lit_with(Sphere{Point3(2, 2, 0), 0.5})) << "the sphere is beside the feeler, not on it";
    // Moved onto the feeler, between the point and the light, the same sphere blocks it.
    EXPECT_FALSE(lit_with(Sphere{Point3(0, 2, 0), 0.5})) << "the sphere around (0, 2, 0) is on the feeler";
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
    // The points facing away from the light (n . L < -0.05) are the sphere's own shadow: their feeler
    // goes into the sphere and meets its far side, between the point and the light.
    int shadowed = 0, tested = 0, lit_behind = 0, behind = 0;
    for (int i = 0; i < 1000; ++i) {
        const double phi = 0.1 + i * 0.0063, theta = 0.05 + i * 0.0029;
        const Vec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
        const auto hit = intersect_sphere(Ray{sphere.center + 5.0 * n, -n}, sphere, Interval{});
        ASSERT_TRUE(hit.has_value());
        const double facing = glm::dot(hit->normal, glm::normalize(light.position - hit->point));
        if (facing < -0.05) {
            ++behind;
            if (is_lit(t.tracer, *hit, light)) ++lit_behind;
        }
        if (facing < 0.05) continue;
        ++tested;
        if (!is_lit(t.tracer, *hit, light)) ++shadowed;
    }
    ASSERT_GT(tested, 100);
    ASSERT_GT(behind, 100);
    EXPECT_EQ(shadowed, 0) << "of " << tested << " points facing the light, " << shadowed
                           << " were in shadow: the feeler found the sphere it starts on (shadow acne)";
    EXPECT_EQ(lit_behind, 0) << "of " << behind << " points facing away from the light, " << lit_behind
                             << " were lit: the feeler from the dark side must cross the sphere";
}

TEST(IsLit, AThinBlockerAHairAboveTheSurfaceCastsAContactShadow) {
    // A triangle with millimetre edges lies flat 5e-5 above the floor, right over the point: the feeler
    // from the point meets it at t = 5e-5. A feeler that starts a visible distance (1e-4) along L skips it.
    EXPECT_FALSE(lit_with(Triangle{{-5e-4, 5e-5, -5e-4}, {5e-4, 5e-5, -5e-4}, {0, 5e-5, 5e-4}}))
        << "start the feeler with spawn_ray: a tiny offset off the surface, not a fixed step along the ray";
    // A sphere of radius 2e-5 around height 4e-5 (from 2e-5 to 6e-5) blocks it too.
    EXPECT_FALSE(lit_with(Sphere{Point3(0, 4e-5, 0), 2e-5})) << "a speck of dust on the surface still casts a shadow";
    // The same speck 1e-4 to the side (from x = 8e-5 to 1.2e-4) is beside the feeler: lit.
    EXPECT_TRUE(lit_with(Sphere{Point3(1e-4, 4e-5, 0), 2e-5})) << "a speck beside the point casts no shadow on it";
}

TEST(IsLit, SmoothSurfaceSeesALightAboveItsTrueSurface) {
    // A flat triangle in z = 0 with vertex normals leaning 30 degrees towards +x (shading normal
    // (sin 30, 0, cos 30), geometric normal +z). A light at direction_at(-70) is above the true surface and
    // nothing is in the way: lit, though it is 100 degrees from the shading normal. The feeler must leave
    // on the geometric normal's side, or it finds the triangle it starts on.
    const PointLight light{4.0 * direction_at(-70.0), Color(1.0)};
    const Scene scene = smooth_floor_scene(direction_at(30.0), {}, diffuse_material(Color(1.0)), {light});
    const TestTracer t(scene, 2);
    EXPECT_TRUE(is_lit(t.tracer, smooth_floor_hit(scene), light))
        << "the feeler found the smooth triangle it starts on: spawn_ray must use hit.geometric_normal";
    // A ball of radius 0.5 halfway to that light, 2 along direction_at(-70), is in the way.
    const Scene blocked = smooth_floor_scene(direction_at(30.0), {Sphere{2.0 * direction_at(-70.0), 0.5}},
                                             diffuse_material(Color(1.0)), {light});
    const TestTracer b(blocked, 2);
    EXPECT_FALSE(is_lit(b.tracer, smooth_floor_hit(blocked), light)) << "a ball halfway to the light shadows the point";
}

TEST(IsLit, SceneTenMillionFromTheOriginKeepsItsShadows) {
    // A tilted plane through P = (1e7, -1e7, 1e7) with unit normal n; hit points from eye rays near P are
    // off the plane by rounding errors of about 1e-9. The light is 100 along n, a sphere of radius 2 sits
    // 50 along n: the feeler from every point within 0.3 of P passes it within 0.3 of its centre (shadow);
    // without the sphere nothing but the plane the point lies on is there (lit).
    const Point3 p(1e7, -1e7, 1e7);
    const Vec3 n = glm::normalize(Vec3(0.1, 1.0, 0.3));
    const Plane plane{p, n};
    const PointLight light{p + 100.0 * n, Color(1.0)};
    const Scene open = scene_of({plane}, diffuse_material(Color(1.0)), {light});
    const Scene blocked = scene_of({plane, Sphere{p + 50.0 * n, 2.0}}, diffuse_material(Color(1.0)), {light});
    const TestTracer a(open, 2), b(blocked, 2);
    const Vec3 u = glm::normalize(glm::cross(n, Vec3(1, 0, 0))), v = glm::cross(n, u);
    int wrong = 0;
    for (int i = 0; i < 200; ++i) {
        const Point3 target = p + 0.2 * std::sin(i * 0.7) * u + 0.2 * std::cos(i * 1.3) * v;
        const Vec3 d = glm::normalize(-n + 0.3 * std::sin(i * 0.9) * u);
        const auto hit = intersect_plane(Ray{target - 20.0 * d, d}, plane, Interval{});
        ASSERT_TRUE(hit.has_value());
        if (!is_lit(a.tracer, *hit, light)) ++wrong;
        if (is_lit(b.tracer, *hit, light)) ++wrong;
    }
    EXPECT_EQ(wrong, 0) << "of 200 points 1e7 from the origin, " << wrong
                        << " answers were wrong (self-shadowed without the sphere, or lit through it)";
}

TEST(IsLit, TheUndersideOfAFloorSeesTheLightsBelowIt) {
    // The floor y = 0 seen from below: the eye ray from (0, -5, 0) going up meets its back face at the
    // origin (front_face false, hit.normal turned down to -y). A light at (0, -4, 0), on the side the
    // point is seen from, lights it: the feeler goes down from the point and nothing is in its way. A
    // sphere of radius 0.5 around (0, -2, 0) lies across that feeler (t from 1.5 to 2.5 < 4): shadow.
    // Surfaces are two-sided: the back of one is lit like its front.
    const Hit underside = intersect_plane(Ray{Point3(0, -5, 0), Vec3(0, 1, 0)}, kFloor, Interval{}).value();
    ASSERT_FALSE(underside.front_face);
    const PointLight below{Point3(0, -4, 0), Color(1.0)};
    const Scene open = scene_of({kFloor}, diffuse_material(Color(1.0)), {below});
    const TestTracer a(open, 2);
    EXPECT_TRUE(is_lit(a.tracer, underside, below)) << "a light on the side a surface is seen from lights it, front or back";
    const Scene blocked = scene_of({kFloor, Sphere{Point3(0, -2, 0), 0.5}}, diffuse_material(Color(1.0)), {below});
    const TestTracer b(blocked, 2);
    EXPECT_FALSE(is_lit(b.tracer, underside, below)) << "the sphere between the underside and the light shadows it";
}
