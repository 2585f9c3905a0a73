// Hidden lab 1 tests of primary_ray: cameras looking along other axes, far from the origin,
// with tall images.
#include "test_helpers.hpp"
#include "whitted/camera.hpp"
#include "whitted/labs.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using whitted::testing_helpers::near;

TEST(HiddenPrimaryRay, CameraLookingStraightDownWithUpAlongX) {
    // eye (10, 20, 30), at (10, 0, 30), up +x: ze = (0, 1, 0), xe = up x ze = (0, 0, 1), ye = ze x xe = (1, 0, 0).
    // fovy 60, 3 x 1: df = 20, h = 40 tan 30 = 40 / sqrt(3), w = 3 h.
    // Pixel 0, centre (0.5, 0.5): w (1/6 - 1/2) = -h along xe, 0 along ye: d ~ (0, -20, -h).
    const double h = 40.0 / std::sqrt(3.0);
    const Camera camera = Camera::create({10, 20, 30}, {10, 0, 30}, {1, 0, 0}, 60.0, 3, 1);
    EXPECT_TRUE(near(primary_ray(camera, 0.5, 0.5).direction, glm::normalize(Vec3(0, -20, -h)), 1e-15));
    EXPECT_TRUE(near(primary_ray(camera, 2.5, 0.5).direction, glm::normalize(Vec3(0, -20, h)), 1e-15));
    EXPECT_TRUE(near(primary_ray(camera, 1.5, 0.5).direction, {0, -1, 0}, 1e-15)) << "the centre looks at `at`";
    // The top edge (y = 1) is h / 2 along ye = +x: 30 degrees (fovy / 2) from straight down.
    EXPECT_TRUE(near(primary_ray(camera, 1.5, 1.0).direction, glm::normalize(Vec3(h / 2.0, -20, 0)), 1e-15));
    EXPECT_TRUE(near(primary_ray(camera, 1.5, 1.0).origin, {10, 20, 30}, 0.0));
}

TEST(HiddenPrimaryRay, CameraFarFromTheOrigin) {
    // eye (1e6, -2e6, 5e5) looking 100 along -z, up +y, fovy 50, 640 x 480: h = 200 tan 25, w = 4/3 h.
    // The bottom-left corner (0, 0) looks along (-w/2, -h/2, -100).
    const Point3 eye(1e6, -2e6, 5e5);
    const Camera camera = Camera::create(eye, eye - Vec3(0, 0, 100), {0, 1, 0}, 50.0, 640, 480);
    const double h = 200.0 * std::tan(radians(25.0)), w = 4.0 / 3.0 * h;
    EXPECT_TRUE(near(primary_ray(camera, 320.0, 240.0).direction, {0, 0, -1}, 1e-12));
    EXPECT_TRUE(near(primary_ray(camera, 0.0, 0.0).direction, glm::normalize(Vec3(-w / 2, -h / 2, -100)), 1e-12));
    EXPECT_TRUE(near(primary_ray(camera, 0.0, 0.0).origin, eye, 0.0));
    EXPECT_NEAR(glm::length(primary_ray(camera, 17.5, 400.5).direction), 1.0, 1e-15);
}

TEST(HiddenPrimaryRay, TallImageNarrowsTheHorizontalView) {
    // df = 2, fovy 90, 100 x 300: h = 4, w = 100 / 300 h = 4 / 3. The left edge at mid height is w / 2 = 2/3 to the left.
    const Camera camera = Camera::create({0, 0, 2}, {0, 0, 0}, {0, 1, 0}, 90.0, 100, 300);
    EXPECT_TRUE(near(primary_ray(camera, 0.0, 150.0).direction, glm::normalize(Vec3(-2.0 / 3.0, 0, -2)), 1e-15));
    EXPECT_TRUE(near(primary_ray(camera, 50.0, 300.0).direction, glm::normalize(Vec3(0, 2, -2)), 1e-15));
    // Pixel (99, 299), the top-right one: centre (99.5, 299.5).
    const Vec3 corner(4.0 / 3.0 * (99.5 / 100 - 0.5), 4.0 * (299.5 / 300 - 0.5), -2.0);
    EXPECT_TRUE(near(primary_ray(camera, 99.5, 299.5).direction, glm::normalize(corner), 1e-15));
}
