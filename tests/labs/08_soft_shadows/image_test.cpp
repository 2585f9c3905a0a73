// Lab 8 as a picture: scenes/08_soft_shadows.p3f (an area light of 16 points)
// rendered at stage 8 must match the reference picture made by the reference solution.
#include "image_check.hpp"

#include <gtest/gtest.h>

using whitted::testing_helpers::ImageCheck;
using whitted::testing_helpers::expect_matches_reference;

TEST(Lab8Image, StageSceneMatchesTheReference) {
    expect_matches_reference(ImageCheck{"scenes/08_soft_shadows.p3f", "tests/labs/08_soft_shadows/08_soft_shadows.png", 8});
}
