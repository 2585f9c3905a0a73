// Hidden lab 2 picture: its own scene (instructor/tests/hidden/scenes/02_shadows_hidden.p3f) at stage 2.
#include "image_check.hpp"

#include <gtest/gtest.h>

TEST(HiddenLab2Image, HiddenSceneMatchesTheReference) {
    whitted::testing_helpers::expect_matches_reference(
        {"instructor/tests/hidden/scenes/02_shadows_hidden.p3f", "instructor/tests/hidden/02_shadows/02_shadows_hidden.png", 2, 200, 150});
}
