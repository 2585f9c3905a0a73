// Lab 9, thin_lens_ray(): the eye ray from a point of the lens (a disk of diameter
// camera.aperture around the eye, in the xe, ye plane) through the focal point
// eye + focal_ratio p, where p is the view-plane point primary_ray aims at.
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace whitted;
using namespace whitted::testing_helpers;

namespace {

/// Viewport positions (in pixels) of a 64 x 48 image: centre, corners, off-centre.
const Vec2 kPositions[] = {{32.0, 24.0}, {0.5, 0.5}, {63.5, 47.5}, {10.25, 40.75}, {50.0, 3.0}};
/// Lens numbers spread over [0, 1)^2, centre and edges included.
const Vec2 kLensNumbers[] = {{0.5, 0.5}, {0.0, 0.0}, {0.0, 0.5}, {0.5, 0.0}, {0.999, 0.5}, {0.75, 0.625},
                             {0.125, 0.625}, {0.6, 0.9}, {0.31, 0.07}, {0.93, 0.88}};

void expect_same_point(const Point3& got, const Point3& expected, double tolerance, const std::string& what) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], expected[i], tolerance) << what << ", coordinate " << i;
}

} // namespace

TEST(ThinLensRay, EveryLensRayOfAViewportPositionPassesThroughItsFocalPoint) {
    // The focal point eye + focal_ratio p (focal_ratio 2.5: in focus 2.5 view distances away).
    const Camera camera = tilted_lens_camera(0.4, 2.5);
    for (const Vec2& xy : kPositions) {
        const Point3 focus = focal_point(camera, xy.x, xy.y);
        for (const Vec2& u : kLensNumbers) {
            const Ray ray = thin_lens_ray(camera, xy.x, xy.y, u);
            EXPECT_LT(distance_to_ray(focus, ray), 1e-12)
                << "viewport (" << xy.x << ", " << xy.y << "), lens numbers (" << u.x << ", " << u.y << ")";
            EXPECT_GT(glm::dot(focus - ray.origin, ray.direction), 0.0) << "the focal point lies ahead of the ray";
            if (enough_failures()) return;
        }
    }
}

TEST(ThinLensRay, TheDirectionIsAUnitVector) {
    const Camera camera = tilted_lens_camera(0.4, 2.5);
    for (const Vec2& xy : kPositions)
        for (const Vec2& u : kLensNumbers) {
            const Ray ray = thin_lens_ray(camera, xy.x, xy.y, u);
            EXPECT_NEAR(glm::length(ray.direction), 1.0, 1e-14);
            // It is the unit vector from the ray's origin towards its focal point.
            const Vec3 towards = glm::normalize(focal_point(camera, xy.x, xy.y) - ray.origin);
            EXPECT_NEAR(glm::length(ray.direction - towards), 0.0, 1e-12)
                << "viewport (" << xy.x << ", " << xy.y << "), lens numbers (" << u.x << ", " << u.y << ")";
            if (enough_failures()) return;
        }
}

TEST(ThinLensRay, TheRayStartsOnTheLensDiskAroundTheEye) {
    // In the plane through the eye spanned by xe and ye (perpendicular to ze), at most
    // aperture / 2 from the eye: the aperture is the lens's diameter.
    const Camera camera = tilted_lens_camera(0.4, 2.5);
    for (const Vec2& u : kLensNumbers) {
        const Vec3 offset = thin_lens_ray(camera, 20.0, 30.0, u).origin - camera.eye;
        EXPECT_NEAR(glm::dot(offset, camera.ze), 0.0, 1e-14) << "lens numbers (" << u.x << ", " << u.y << ")";
        EXPECT_LE(glm::length(offset), 0.2 + 1e-14) << "lens numbers (" << u.x << ", " << u.y << ")";
        // Where the handout puts it: eye + (aperture / 2) (d.x xe + d.y ye), d = concentric_disk(u).
        expect_same_point(camera.eye + offset, expected_lens_point(camera, u), 1e-14,
                          "lens numbers (" + std::to_string(u.x) + ", " + std::to_string(u.y) + ")");
        if (enough_failures()) return;
    }
}

TEST(ThinLensRay, TheEdgesOfTheLensLieAlongTheCamerasAxes) {
    // concentric_disk(0, 1/2) = (-1, 0): the lens's left edge, eye - (aperture / 2) xe;
    // concentric_disk(1/2, 0) = (0, -1): its bottom edge, eye - (aperture / 2) ye. The camera
    // is tilted: its xe and ye are not the world's x and y.
    const Camera camera = tilted_lens_camera(0.4, 2.5);
    expect_same_point(thin_lens_ray(camera, 20.0, 30.0, Vec2(0.0, 0.5)).origin, camera.eye - 0.2 * camera.xe, 1e-14,
                      "lens numbers (0, 0.5): eye - 0.2 xe");
    expect_same_point(thin_lens_ray(camera, 20.0, 30.0, Vec2(0.5, 0.0)).origin, camera.eye - 0.2 * camera.ye, 1e-14,
                      "lens numbers (0.5, 0): eye - 0.2 ye");
}

TEST(ThinLensRay, TheLensPointIsTheConcentricMappingOfTheNumbers) {
    // lens numbers (0.75, 0.625): d = (0.5 cos 22.5, 0.5 sin 22.5) (see the concentric_disk tests),
    // so the ray starts at eye + (aperture / 2) (d.x xe + d.y ye).
    const Camera camera = tilted_lens_camera(0.4, 2.5);
    const double dx = 0.5 * std::cos(kPi / 8.0), dy = 0.5 * std::sin(kPi / 8.0);
    expect_same_point(thin_lens_ray(camera, 7.0, 11.0, Vec2(0.75, 0.625)).origin,
                      camera.eye + 0.2 * (dx * camera.xe + dy * camera.ye), 1e-14, "lens numbers (0.75, 0.625)");
}

TEST(ThinLensRay, TheCentreOfTheLensIsThePinhole) {
    // lens numbers (1/2, 1/2): the lens's centre, the eye; the ray is primary_ray's (the
    // focal point lies on the pinhole ray whatever focal_ratio is).
    const Camera camera = tilted_lens_camera(0.4, 2.5);
    for (const Vec2& xy : kPositions) {
        const Ray ray = thin_lens_ray(camera, xy.x, xy.y, Vec2(0.5, 0.5));
        const Vec3 pinhole = glm::normalize(view_plane_offset(camera, xy.x, xy.y));
        expect_same_point(ray.origin, camera.eye, 1e-15, "origin");
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(ray.direction[i], pinhole[i], 1e-15) << "direction, coordinate " << i;
        if (enough_failures()) return;
    }
}

TEST(ThinLensRay, FocalRatioOneFocusesOnTheViewPlane) {
    // focal 1: the rays of (x, y) meet where primary_ray's ray crosses the view plane, eye + p.
    const Camera camera = tilted_lens_camera(0.6, 1.0);
    for (const Vec2& xy : kPositions) {
        const Point3 on_view_plane = camera.eye + view_plane_offset(camera, xy.x, xy.y);
        for (const Vec2& u : kLensNumbers) {
            EXPECT_LT(distance_to_ray(on_view_plane, thin_lens_ray(camera, xy.x, xy.y, u)), 1e-12)
                << "viewport (" << xy.x << ", " << xy.y << "), lens numbers (" << u.x << ", " << u.y << ")";
            if (enough_failures()) return;
        }
    }
}

TEST(ThinLensRay, RaysFromOppositeSidesOfTheLensCrossAtTheFocalPoint) {
    // From the left and the right edge of the lens, both rays reach the focal point
    // after the same distance: they cross there, and beyond it they swap sides.
    const Camera camera = tilted_lens_camera(0.4, 3.0);
    const Ray left = thin_lens_ray(camera, 32.0, 24.0, Vec2(0.0, 0.5));
    const Ray right = thin_lens_ray(camera, 32.0, 24.0, Vec2(0.999999, 0.5));
    const Point3 focus = focal_point(camera, 32.0, 24.0);
    EXPECT_NEAR(glm::length(focus - left.origin), glm::length(focus - right.origin), 1e-5);
    const double t = 2.0 * glm::length(focus - left.origin); // twice as far: mirrored about the focal point
    EXPECT_GT(glm::dot(left.at(t) - right.at(t), camera.xe), 0.0) << "past the focus the left ray is on the right";
    EXPECT_LT(glm::dot(left.origin - right.origin, camera.xe), 0.0) << "at the lens the left ray is on the left";
}
