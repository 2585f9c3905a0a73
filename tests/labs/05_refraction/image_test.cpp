// Lab 5 as a picture: scenes/05_refraction.p3f rendered at stage 5 must match the
// reference picture made by the reference solution.
#include "image_check.hpp"

#include <gtest/gtest.h>

using whitted::testing_helpers::ImageCheck;
using whitted::testing_helpers::expect_matches_reference;

TEST(Lab5Image, StageSceneMatchesTheReference) {
    expect_matches_reference(ImageCheck{"scenes/05_refraction.p3f", "tests/labs/05_refraction/05_refraction.png", 5});
}
