// Lab 7 as a picture: scenes/07_anti_aliasing.p3f (9 samples a pixel) rendered
// at stage 7 must match the reference picture made by the reference solution.
#include "image_check.hpp"

#include <gtest/gtest.h>

using whitted::testing_helpers::ImageCheck;
using whitted::testing_helpers::expect_matches_reference;

TEST(Lab7Image, StageSceneMatchesTheReference) {
    expect_matches_reference(ImageCheck{"scenes/07_anti_aliasing.p3f", "tests/labs/07_anti_aliasing/07_anti_aliasing.png", 7});
}
