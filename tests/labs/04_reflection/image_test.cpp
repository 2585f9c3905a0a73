// Lab 4 as a picture: scenes/04_reflection.p3f rendered at stage 4 must match the
// reference picture made by the reference solution.
#include "image_check.hpp"

#include <gtest/gtest.h>

using whitted::testing_helpers::ImageCheck;
using whitted::testing_helpers::expect_matches_reference;

TEST(Lab4Image, StageSceneMatchesTheReference) {
    expect_matches_reference(ImageCheck{"scenes/04_reflection.p3f", "tests/labs/04_reflection/04_reflection.png", 4});
}
