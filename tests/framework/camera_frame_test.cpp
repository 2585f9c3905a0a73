// The camera of the slides: the frame from eye / at / up, the view-plane size,
// and the primary rays through pixel centres (primary_ray from labs.hpp).
#include "test_helpers.hpp"
#include "whitted/camera.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using whitted::testing_helpers::near;

TEST(Camera, FrameLooksDownMinusZWhenTheEyeIsOnThePositiveZAxis) {
    // eye - at = (0, 0, 5): ze = (0, 0, 1); xe = y x z = (1, 0, 0); ye = z x x = (0, 1, 0).
    const Camera camera = Camera::create({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 45.0, 64, 64);
    EXPECT_TRUE(near(camera.ze, {0, 0, 1}));
    EXPECT_TRUE(near(camera.xe, {1, 0, 0}));
    EXPECT_TRUE(near(camera.ye, {0, 1, 0}));
    EXPECT_DOUBLE_EQ(camera.df, 5.0);
}

TEST(Camera, FrameFollowsTheSlidesForAnObliqueView) {
    // eye - at = (-3, -4, 0), |.| = 5: ze = (-0.6, -0.8, 0).
    // xe = normalize(up x ze) with up = (0, 0, 1): (0*0 - 1*(-0.8), 1*(-0.6) - 0*0, 0) = (0.8, -0.6, 0).
    // ye = ze x xe = (0, 0, 0.36 + 0.64) = (0, 0, 1).
    const Camera camera = Camera::create({1, 2, 3}, {4, 6, 3}, {0, 0, 1}, 45.0, 64, 64);
    EXPECT_DOUBLE_EQ(camera.df, 5.0);
    EXPECT_TRUE(near(camera.ze, {-0.6, -0.8, 0}));
    EXPECT_TRUE(near(camera.xe, {0.8, -0.6, 0}));
    EXPECT_TRUE(near(camera.ye, {0, 0, 1}));
}

TEST(Camera, UpNeedNotBePerpendicularNorUnitLength) {
    // up = (0, 2, 3) tilts towards the eye; only its part across ze matters:
    // up x ze = (2, 0, 0) -> xe = (1, 0, 0), ye = (0, 1, 0): the frame is orthonormal and right-handed.
    const Camera camera = Camera::create({0, 0, 5}, {0, 0, 0}, {0, 2, 3}, 45.0, 64, 64);
    EXPECT_TRUE(near(camera.xe, {1, 0, 0}));
    EXPECT_TRUE(near(camera.ye, {0, 1, 0}));
    EXPECT_TRUE(near(glm::cross(camera.xe, camera.ye), camera.ze));
    EXPECT_NEAR(glm::length(camera.ye), 1.0, 1e-15);
    EXPECT_NEAR(glm::dot(camera.ye, camera.ze), 0.0, 1e-15);
}

TEST(Camera, ViewPlaneHeightIsTwiceTheDistanceTimesTanHalfFov) {
    // df = 3, fovy = 60: h = 2 * 3 * tan(30 deg) = 6 / sqrt(3) = 2 sqrt(3); square image: w = h.
    const Camera camera = Camera::create({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 60.0, 100, 100);
    EXPECT_NEAR(camera.h, 2.0 * std::sqrt(3.0), 1e-12);
    EXPECT_NEAR(camera.w, camera.h, 1e-12);
}

TEST(Camera, ViewPlaneWidthFollowsTheAspectRatio) {
    // df = 2, fovy = 90: h = 2 * 2 * tan(45 deg) = 4; 200 x 100 pixels: w = 200 / 100 * 4 = 8.
    const Camera camera = Camera::create({0, 0, 2}, {0, 0, 0}, {0, 1, 0}, 90.0, 200, 100);
    EXPECT_NEAR(camera.h, 4.0, 1e-12);
    EXPECT_NEAR(camera.w, 8.0, 1e-12);
}

TEST(Camera, AnotherResolutionKeepsTheLens) {
    // `--width` re-makes the camera: the thin lens (scene units) and its focus stay.
    Camera camera = Camera::create({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 45.0, 64, 48);
    camera.aperture = 0.25;
    camera.focal_ratio = 1.75;
    const Camera wider = camera.with_resolution(200, 100);
    EXPECT_EQ(wider.res_x, 200);
    EXPECT_EQ(wider.aperture, 0.25);
    EXPECT_EQ(wider.focal_ratio, 1.75);
}
