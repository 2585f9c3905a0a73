// Lab 9 as a picture: scenes/09_depth_of_field.p3f (a thin lens focused on the
// middle sphere, 16 samples a pixel) rendered at stage 9 must match the
// reference picture made by the reference solution.
#include "image_check.hpp"

#include <gtest/gtest.h>

using whitted::testing_helpers::ImageCheck;
using whitted::testing_helpers::expect_matches_reference;

TEST(Lab9Image, StageSceneMatchesTheReference) {
    expect_matches_reference(ImageCheck{"scenes/09_depth_of_field.p3f", "tests/labs/09_depth_of_field/09_depth_of_field.png", 9});
}
