// Hidden tests of lab 9: other points of the concentric mapping, a lens focused in
// front of the view plane on a camera looking down, and a hidden scene with the
// focus on the far wall and 9 samples a pixel.
#include "whitted/labs.hpp"

#include "image_check.hpp"
#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;

TEST(HiddenConcentricDisk, OtherWedgesByHand) {
    // u = (0.9, 0.3): a = (0.8, -0.4), the right wedge: r = 0.8, angle (pi/4)(-1/2) = -pi/8.
    Vec2 d = concentric_disk(Vec2(0.9, 0.3));
    EXPECT_NEAR(d.x, 0.8 * std::cos(kPi / 8.0), 1e-15);
    EXPECT_NEAR(d.y, -0.8 * std::sin(kPi / 8.0), 1e-15);
    // u = (0.25, 0.0625): a = (-0.5, -0.875), the lower wedge: r = -0.875,
    // angle pi/2 - (pi/4)(0.5 / 0.875) = pi/2 - pi/7 = 5 pi / 14.
    d = concentric_disk(Vec2(0.25, 0.0625));
    EXPECT_NEAR(d.x, -0.875 * std::cos(5.0 * kPi / 14.0), 1e-15);
    EXPECT_NEAR(d.y, -0.875 * std::sin(5.0 * kPi / 14.0), 1e-15);
    // u = (0.75, 0.75): a = (0.5, 0.5) on the diagonal: r = 0.5, angle pi/4.
    d = concentric_disk(Vec2(0.75, 0.75));
    EXPECT_NEAR(d.x, 0.5 * std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(d.y, 0.5 * std::sqrt(0.5), 1e-15);
}

TEST(HiddenThinLensRay, FocusInFrontOfTheViewPlaneOnACameraLookingDown) {
    // focal 0.4: the plane in focus lies between the eye and the view plane.
    Camera camera = Camera::create(Point3(0.0, 6.0, 1.0), Point3(0.5, 0.0, -1.0), Vec3(0.0, 0.0, -1.0), 35.0, 30, 50);
    camera.aperture = 0.9;
    camera.focal_ratio = 0.4;
    for (const Vec2& xy : {Vec2(15.0, 25.0), Vec2(2.5, 47.0), Vec2(29.0, 1.0)}) {
        const Point3 focus = camera.eye + 0.4 * view_plane_offset(camera, xy.x, xy.y);
        for (const Vec2& u : {Vec2(0.05, 0.95), Vec2(0.7, 0.2), Vec2(0.5, 0.5), Vec2(0.33, 0.66)}) {
            const Ray ray = thin_lens_ray(camera, xy.x, xy.y, u);
            EXPECT_LT(distance_to_ray(focus, ray), 1e-12);
            const Point3 lens = expected_lens_point(camera, u);
            for (int i = 0; i < 3; ++i) EXPECT_NEAR(ray.origin[i], lens[i], 1e-14);
            EXPECT_NEAR(glm::length(ray.direction), 1.0, 1e-14);
        }
    }
}

TEST(HiddenLab9Image, HiddenSceneMatchesTheReference) {
    expect_matches_reference(ImageCheck{"instructor/tests/hidden/scenes/09_depth_of_field_hidden.p3f",
                                        "instructor/tests/hidden/09_depth_of_field/09_depth_of_field_hidden.png", 9});
}
