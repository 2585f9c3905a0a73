// Lab 2 as a picture: scenes/02_shadows.p3f rendered at stage 2 must match the
// reference picture made by the reference solution.
#include "image_check.hpp"

#include <gtest/gtest.h>

using whitted::testing_helpers::ImageCheck;
using whitted::testing_helpers::expect_matches_reference;

TEST(Lab2Image, StageSceneMatchesTheReference) {
    expect_matches_reference(ImageCheck{"scenes/02_shadows.p3f", "tests/labs/02_shadows/02_shadows.png", 2});
}
