// Lab 10 as a picture: scenes/10_bvh.p3f rendered at stage 10, every ray
// through your BVH, must match the reference picture.
#include "image_check.hpp"

#include <gtest/gtest.h>

using whitted::testing_helpers::ImageCheck;
using whitted::testing_helpers::expect_matches_reference;

TEST(Lab10Image, StageSceneMatchesTheReference) {
    expect_matches_reference(ImageCheck{"scenes/10_bvh.p3f", "tests/labs/10_bvh/10_bvh.png", 10});
}
