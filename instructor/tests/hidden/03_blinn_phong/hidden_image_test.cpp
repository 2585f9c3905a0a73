// Hidden lab 3 picture: its own scene (instructor/tests/hidden/scenes/03_blinn_phong_hidden.p3f) at stage 3.
#include "image_check.hpp"

#include <gtest/gtest.h>

TEST(HiddenLab3Image, HiddenSceneMatchesTheReference) {
    whitted::testing_helpers::expect_matches_reference(
        {"instructor/tests/hidden/scenes/03_blinn_phong_hidden.p3f", "instructor/tests/hidden/03_blinn_phong/03_blinn_phong_hidden.png", 3, 200, 150});
}
