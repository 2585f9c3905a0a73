// Lab 1 as a picture: scenes/01_ray_casting.p3f rendered at stage 1 must match the
// reference picture made by the reference solution.
#include "image_check.hpp"

#include <gtest/gtest.h>

using whitted::testing_helpers::ImageCheck;
using whitted::testing_helpers::expect_matches_reference;

TEST(Lab1Image, StageSceneMatchesTheReference) {
    expect_matches_reference(ImageCheck{"scenes/01_ray_casting.p3f", "tests/labs/01_ray_casting/01_ray_casting.png", 1});
}
