// Lab 6 as a picture: scenes/06_fresnel.p3f rendered at stage 6 must match the
// reference picture made by the reference solution.
#include "image_check.hpp"

#include <gtest/gtest.h>

using whitted::testing_helpers::ImageCheck;
using whitted::testing_helpers::expect_matches_reference;

TEST(Lab6Image, StageSceneMatchesTheReference) {
    expect_matches_reference(ImageCheck{"scenes/06_fresnel.p3f", "tests/labs/06_fresnel/06_fresnel.png", 6});
}
