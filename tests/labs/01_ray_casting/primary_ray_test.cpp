// The camera of the slides: the frame from eye / at / up, the view-plane size,
// and the primary rays through pixel centres (primary_ray from labs.hpp).
#include "test_helpers.hpp"
#include "whitted/camera.hpp"
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;
using whitted::testing_helpers::near;

namespace {

/// The angle in degrees between two unit vectors.
double angle_degrees(const Vec3& a, const Vec3& b) { return std::acos(glm::dot(a, b)) * 180.0 / kPi; }

} // namespace

TEST(PrimaryRay, StartsAtTheEyeWithAUnitDirection) {
    const Camera camera = Camera::create({1, 2, 3}, {4, 6, 3}, {0, 0, 1}, 50.0, 40, 30);
    const Ray ray = primary_ray(camera, 7.5, 21.5);
    EXPECT_TRUE(near(ray.origin, camera.eye)) << "every primary ray starts at the eye";
    EXPECT_NEAR(glm::length(ray.direction), 1.0, 1e-15)
        << "ray directions must have length 1 (normalize them): the intersection routines rely on it";
    // Another pixel, across the image: the same eye, another direction.
    const Ray other = primary_ray(camera, 32.5, 3.5);
    EXPECT_TRUE(near(other.origin, camera.eye)) << "every primary ray starts at the eye";
    EXPECT_NEAR(glm::length(other.direction), 1.0, 1e-15);
    EXPECT_LT(glm::dot(ray.direction, other.direction), 0.99) << "rays through pixels far apart go different ways";
}

TEST(PrimaryRay, CentrePixelOfAnOddResolutionLooksExactlyAtTheTarget) {
    // Pixel (2, 1) of 5 x 3 has its centre at (2.5, 1.5): x / ResX - 1/2 = 0 and y / ResY - 1/2 = 0,
    // so d = normalize(-df ze) = (at - eye) / df, and eye + df d = at.
    const Camera camera = Camera::create({1, 2, 3}, {4, 6, 3}, {0, 0, 1}, 50.0, 5, 3);
    const Ray ray = primary_ray(camera, 2.5, 1.5);
    EXPECT_TRUE(near(ray.direction, {0.6, 0.8, 0}, 1e-15)) << "the centre of the viewport looks straight at `at`";
    EXPECT_TRUE(near(ray.at(camera.df), camera.at, 1e-14)) << "eye + df d should be `at`";
    // The next pixel to the right, centre (3.5, 1.5), looks one pixel width (w / ResX) along xe from `at`:
    // its ray meets the view plane (df ahead along -ze) at at + (w / 5) xe.
    const Ray right = primary_ray(camera, 3.5, 1.5);
    const double ahead = camera.df / glm::dot(right.direction, -camera.ze);
    EXPECT_TRUE(near(right.at(ahead), camera.at + (camera.w / 5.0) * camera.xe, 1e-14))
        << "x one pixel past the centre moves the point on the view plane w / ResX along xe";
}

TEST(PrimaryRay, BottomLeftPixelCentreGoesDownAndLeft) {
    // df = 1, fovy = 90, 2 x 2: h = w = 2. Pixel (0, 0), centre (0.5, 0.5):
    // w (0.25 - 0.5) = -0.5 and h (0.25 - 0.5) = -0.5, so d = normalize(-0.5, -0.5, -1) (y counts upwards).
    const Camera camera = Camera::create({0, 0, 1}, {0, 0, 0}, {0, 1, 0}, 90.0, 2, 2);
    const Ray ray = primary_ray(camera, 0.5, 0.5);
    EXPECT_TRUE(near(ray.direction, glm::normalize(Vec3(-0.5, -0.5, -1.0)), 1e-15))
        << "pixel (0, 0) is the bottom-left one: its ray goes left (-xe) and down (-ye); x is already a pixel centre";
    const Ray top_right = primary_ray(camera, 1.5, 1.5);
    EXPECT_TRUE(near(top_right.direction, glm::normalize(Vec3(0.5, 0.5, -1.0)), 1e-15))
        << "pixel (1, 1) is the top-right one: its ray goes right and up";
}

TEST(PrimaryRay, TopAndBottomEdgesOfTheViewPlaneSpanTheVerticalFov) {
    // At y = 0 and y = ResY the rays meet the view plane h / 2 below and above `at`, and
    // tan(angle / 2) = (h / 2) / df = tan(fovy / 2): the angle between them is fovy.
    const Camera camera = Camera::create({3, 1, 4}, {0, 0, 0}, {0, 1, 0}, 35.0, 120, 80);
    const Ray bottom = primary_ray(camera, 60.0, 0.0);
    const Ray top = primary_ray(camera, 60.0, 80.0);
    EXPECT_NEAR(angle_degrees(bottom.direction, top.direction), 35.0, 1e-10)
        << "the view plane is h = 2 df tan(fovy / 2) high, from y = 0 to y = ResY";
    EXPECT_GT(glm::dot(top.direction - bottom.direction, camera.ye), 0.0) << "larger y must look further up (along ye)";
}

TEST(PrimaryRay, NonSquareImagesWidenTheHorizontalFov) {
    // df = 1, fovy = 90, 200 x 100: h = 2, w = 4. The left and right edges at mid height lie
    // 2 to each side of `at`: the horizontal angle is 2 atan(2 / 1), wider than the vertical 90 degrees.
    const Camera camera = Camera::create({0, 0, 1}, {0, 0, 0}, {0, 1, 0}, 90.0, 200, 100);
    const Ray left = primary_ray(camera, 0.0, 50.0);
    const Ray right = primary_ray(camera, 200.0, 50.0);
    EXPECT_NEAR(angle_degrees(left.direction, right.direction), 2.0 * std::atan(2.0) * 180.0 / kPi, 1e-10)
        << "x spans the width w = ResX / ResY h, y spans the height h: are w and h swapped or equal?";
    EXPECT_TRUE(near(left.direction, glm::normalize(Vec3(-2, 0, -1)), 1e-15));
}

TEST(PrimaryRay, NonIntegerAspectRatioSpreadsXOverTheWholeWidth) {
    // df = 1, fovy = 90, 7 x 3: h = 2 df tan 45 = 2 and w = 7 / 3 h = 14 / 3 (not 2 h: 7 / 3 is no
    // whole number). Pixel (0, 2), centre (0.5, 2.5): w (0.5 / 7 - 1/2) = (14 / 3)(-6 / 14) = -2 along xe,
    // h (2.5 / 3 - 1/2) = 2 / 3 along ye: d = normalize(-2, 2/3, -1). Pixel (6, 0), centre (6.5, 0.5),
    // mirrors it through the centre: d = normalize(2, -2/3, -1).
    const Camera camera = Camera::create({0, 0, 1}, {0, 0, 0}, {0, 1, 0}, 90.0, 7, 3);
    EXPECT_TRUE(near(primary_ray(camera, 0.5, 2.5).direction, glm::normalize(Vec3(-2.0, 2.0 / 3.0, -1.0)), 1e-14))
        << "top-left pixel of a 7 x 3 image: x spans w = ResX / ResY h (a fraction, 7 / 3), y spans h";
    EXPECT_TRUE(near(primary_ray(camera, 6.5, 0.5).direction, glm::normalize(Vec3(2.0, -2.0 / 3.0, -1.0)), 1e-14))
        << "bottom-right pixel of a 7 x 3 image";
}

TEST(Camera, WithResolutionKeepsTheVerticalFovAndWidensTheWidth) {
    // Same eye, at, up and fovy: the frame and h stay; w = 300 / 100 h.
    const Camera square = Camera::create({1, 5, 2}, {0, 1, 0}, {0, 1, 0}, 40.0, 100, 100);
    const Camera wide = square.with_resolution(300, 100);
    EXPECT_EQ(wide.res_x, 300);
    EXPECT_EQ(wide.res_y, 100);
    EXPECT_DOUBLE_EQ(wide.fovy, 40.0);
    EXPECT_DOUBLE_EQ(wide.h, square.h);
    EXPECT_NEAR(wide.w, 3.0 * square.h, 1e-12);
    EXPECT_TRUE(near(wide.xe, square.xe, 0.0));
    EXPECT_TRUE(near(wide.ze, square.ze, 0.0));
    // The centre ray still looks at `at`; the left edge at mid height is w / 2 = 1.5 h from it in the view
    // plane, df away: tan(angle) = 1.5 h / df = 3 tan(20 degrees), three times the square image's.
    EXPECT_TRUE(near(primary_ray(wide, 150.0, 50.0).direction, -square.ze, 1e-15));
    EXPECT_NEAR(angle_degrees(primary_ray(wide, 0.0, 50.0).direction, -square.ze),
                std::atan(3.0 * std::tan(radians(20.0))) * 180.0 / kPi, 1e-10);
}

TEST(PrimaryRay, MovesAlongXeAsXGrowsInWholePixelSteps) {
    // eye (0, 0, 5), at the origin, fovy 90, 4 x 2: df = 5, h = 2 df tan 45 = 10, w = 4 / 2 h = 20.
    // x = 2.5 (centre of pixel 2): w (2.5 / 4 - 1/2) = 2.5 along xe = +x; y = 1 is mid height.
    // d = normalize(2.5, 0, -5). Adding another half pixel would give 5 instead of 2.5.
    const Camera camera = Camera::create({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 90.0, 4, 2);
    EXPECT_TRUE(near(primary_ray(camera, 2.5, 1.0).direction, glm::normalize(Vec3(2.5, 0, -5)), 1e-15))
        << "x is the viewport position itself (the framework already passes pixel centres)";
    EXPECT_TRUE(near(primary_ray(camera, 0.5, 1.0).direction, glm::normalize(Vec3(-7.5, 0, -5)), 1e-15));
}

TEST(PrimaryRay, UsesTheCameraFrameNotTheWorldAxes) {
    // eye (1, 2, 3), at (4, 6, 3), up +z: ze = (eye - at) / 5 = (-0.6, -0.8, 0),
    // xe = up x ze = (0.8, -0.6, 0), ye = ze x xe = (0, 0, 1). fovy 90, 20 x 10: h = 10, w = 20.
    // (x, y) = (15, 10): w (15/20 - 1/2) = 5 along xe, h (10/10 - 1/2) = 5 along ye, -df ze = (3, 4, 0).
    // d = (3, 4, 0) + 5 (0.8, -0.6, 0) + 5 (0, 0, 1) = (7, 1, 5).
    const Camera camera = Camera::create({1, 2, 3}, {4, 6, 3}, {0, 0, 1}, 90.0, 20, 10);
    const Ray ray = primary_ray(camera, 15.0, 10.0);
    EXPECT_TRUE(near(ray.direction, glm::normalize(Vec3(7, 1, 5)), 1e-15))
        << "d = w (x / ResX - 1/2) xe + h (y / ResY - 1/2) ye - df ze, normalised";
    EXPECT_TRUE(near(ray.origin, {1, 2, 3}));
}
