// Lab 3 as a picture: scenes/03_blinn_phong.p3f rendered at stage 3 must match the
// reference picture made by the reference solution.
#include "image_check.hpp"

#include <gtest/gtest.h>

using whitted::testing_helpers::ImageCheck;
using whitted::testing_helpers::expect_matches_reference;

TEST(Lab3Image, StageSceneMatchesTheReference) {
    expect_matches_reference(ImageCheck{"scenes/03_blinn_phong.p3f", "tests/labs/03_blinn_phong/03_blinn_phong.png", 3});
}
