// spawn_ray: a new ray from a hit point that cannot find the surface it starts on, whatever
// its angle and wherever the point lies. The origin moves a tiny distance off the surface, to
// the side the direction leaves towards; the direction is kept as it is.
#include "test_helpers.hpp"
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;

namespace {

/// A hit on the floor y = 0 (normal +y) at the given point, as intersect_plane reports it.
Hit floor_hit(const Point3& point) {
    const auto hit = intersect_plane(Ray{point + Vec3(0.3, 2.0, 0.1), glm::normalize(Vec3(-0.3, -2.0, -0.1))},
                                     Plane{Point3(0.0), Vec3(0, 1, 0)}, Interval{});
    return hit.value();
}

} // namespace

TEST(SpawnRay, LeavingRayStartsJustAboveTheSurfaceWithItsDirectionUnchanged) {
    // A ray leaving upwards (+y) must start on the +y side of the floor, close to the hit point:
    // within 1e-5 (1 + |p|) of it, so that contact shadows and thin gaps are not skipped.
    const Hit hit = floor_hit({1.5, 0.0, -2.0});
    const Vec3 up_and_away = glm::normalize(Vec3(1.0, 2.0, -0.5));
    const Ray ray = spawn_ray(hit, up_and_away);
    EXPECT_GT(ray.origin.y, 0.0) << "the origin must move off the surface, to the side the ray leaves towards";
    EXPECT_LT(glm::length(ray.origin - hit.point), 1e-5 * 3.0) << "the offset must be tiny, not a visible gap";
    EXPECT_EQ(ray.direction, up_and_away) << "spawn_ray moves the origin only";
    EXPECT_FALSE(intersect_plane(ray, Plane{Point3(0.0), Vec3(0, 1, 0)}, Interval{}))
        << "the new ray must not find the floor it starts on";
}

TEST(SpawnRay, RayIntoTheSurfaceStartsJustBelowIt) {
    // A ray going into the surface (dot(direction, normal) < 0, a refracted ray) must start on
    // the other side: below the floor, where it is going.
    const Hit hit = floor_hit({-0.5, 0.0, 3.0});
    const Ray ray = spawn_ray(hit, glm::normalize(Vec3(0.2, -1.0, 0.1)));
    EXPECT_LT(ray.origin.y, 0.0) << "offset along -normal when the ray goes into the surface";
    EXPECT_LT(glm::length(ray.origin - hit.point), 1e-5 * 4.0);
}


TEST(SpawnRay, SmoothSurfacesAreLeftOnTheSideOfTheGeometricNormal) {
    // A flat triangle in z = 0 whose vertex normals lean 30 degrees towards +x, hit straight from above:
    // hit.normal = (sin 30, 0, cos 30), hit.geometric_normal = +z. direction_at(-70) leaves above the true
    // surface (its z is cos 70 > 0) though it makes 100 degrees with the shading normal; direction_at(95)
    // goes under it (z = cos 95 < 0) though it makes only 65 degrees with the shading normal. Only the
    // geometric normal tells which side of the real surface a ray leaves towards.
    const Scene scene = smooth_floor_scene(direction_at(30.0), {}, diffuse_material(Color(1.0)), {});
    const Hit hit = smooth_floor_hit(scene);
    ASSERT_TRUE(near(hit.normal, direction_at(30.0), 1e-12)) << "the framework interpolates the vertex normals";
    ASSERT_TRUE(near(hit.geometric_normal, kUp, 0.0));
    const Ray leaving = spawn_ray(hit, direction_at(-70.0));
    EXPECT_GT(leaving.origin.z, 0.0) << "offset along hit.geometric_normal, to the side the ray leaves towards";
    EXPECT_FALSE(scene.closest_hit(leaving)) << "the ray leaving above the triangle must not find it";
    const Ray entering = spawn_ray(hit, direction_at(95.0));
    EXPECT_LT(entering.origin.z, 0.0) << "the ray goes under the true surface: start it below the triangle";
    EXPECT_FALSE(scene.closest_hit(entering)) << "the ray going under the triangle must not find it";
}

TEST(SpawnRay, GrazingRaysLeavingASphereDoNotHitItAgain) {
    // Shadow feelers that leave a sphere almost tangentially (89.99 degrees from
    // the normal) must not find the sphere they start on, wherever they start.
    const Sphere sphere{Point3(3.0, -2.0, 7.0), 2.5};
    int self_hits = 0, elsewhere = 0;
    for (int i = 0; i < 2000; ++i) {
        const double phi = 0.1 + i * 0.0031, theta = 0.2 + i * 0.0017;
        const Vec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
        const Ray eye{sphere.center + 10.0 * n, -n};
        const auto hit = intersect_sphere(eye, sphere, Interval{});
        ASSERT_TRUE(hit.has_value());
        const Vec3 tangent = glm::normalize(glm::cross(n, Vec3(0.3, 0.5, 0.7)));
        const Vec3 grazing = glm::normalize(tangent + std::tan(radians(0.01)) * n);
        const Ray feeler = spawn_ray(*hit, grazing);
        if (intersect_sphere(feeler, sphere, Interval{})) ++self_hits;
        if (!leaves_from(*hit, grazing, feeler)) ++elsewhere;
    }
    EXPECT_EQ(self_hits, 0) << "feelers leaving at 89.99 degrees found the sphere they start on (shadow acne)";
    EXPECT_EQ(elsewhere, 0) << "feelers that do not start at their hit point (within 1e-5 (1 + |p|)) in its direction";
}

TEST(SpawnRay, RaysIntoTheSurfaceFindTheFarWallNotTheNearOne) {
    // Refracted rays entering a sphere straight towards its centre must travel
    // the full diameter: their first hit is the far wall, seen from inside.
    const Sphere sphere{Point3(0.3, -1.7, 2.9), 1.3};
    int wrong = 0;
    for (int i = 0; i < 2000; ++i) {
        const double phi = 0.1 + i * 0.0031, theta = 0.2 + i * 0.0017;
        const Vec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
        const auto hit = intersect_sphere(Ray{sphere.center + 7.0 * n, -n}, sphere, Interval{});
        ASSERT_TRUE(hit.has_value());
        const auto inside = intersect_sphere(spawn_ray(*hit, -n), sphere, Interval{});
        if (!inside || inside->front_face || std::abs(inside->t - 2.0 * sphere.radius) > 1e-6) ++wrong;
    }
    EXPECT_EQ(wrong, 0) << "rays into a sphere must start inside it and meet the far wall at t = 2 r (1e-6): "
                           "offset to the side the ray goes, by a tiny amount";
}

TEST(SpawnRay, GrazingRaysAlongAFarAwayTiltedPlaneDoNotHitIt) {
    // Coordinates around 1000 and a tilted plane: the computed hit point is off
    // the plane by rounding errors of about 1e-13, on either side.
    const Vec3 normal = glm::normalize(Vec3(0.1, 1.0, 0.3));
    const Plane plane{Point3(1000.1, 1000.3, -999.7), normal};
    const Vec3 tangent = glm::normalize(glm::cross(normal, Vec3(1.0, 0.0, 0.0)));
    int self_hits = 0, elsewhere = 0;
    for (int i = 0; i < 2000; ++i) {
        const Ray eye{Point3(1000.0 + i * 0.37, 1020.0, -1000.0 - i * 0.11), glm::normalize(Vec3(0.3, -1.0, 0.2 + i * 1e-3))};
        const auto hit = intersect_plane(eye, plane, Interval{});
        ASSERT_TRUE(hit.has_value());
        const Vec3 grazing = glm::normalize(tangent + 1e-7 * hit->normal);
        const Ray feeler = spawn_ray(*hit, grazing);
        if (intersect_plane(feeler, plane, Interval{})) ++self_hits;
        if (!leaves_from(*hit, grazing, feeler)) ++elsewhere;
    }
    EXPECT_EQ(self_hits, 0) << "far from the origin rounding errors grow: scale the offset with the coordinates";
    EXPECT_EQ(elsewhere, 0) << "rays that do not start at their hit point (within 1e-5 (1 + |p|)) in its direction";
}
