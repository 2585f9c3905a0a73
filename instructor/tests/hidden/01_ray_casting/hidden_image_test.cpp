// Hidden lab 1 picture: its own scene (instructor/tests/hidden/scenes/01_ray_casting_hidden.p3f) at stage 1.
#include "image_check.hpp"

#include <gtest/gtest.h>

TEST(HiddenLab1Image, HiddenSceneMatchesTheReference) {
    whitted::testing_helpers::expect_matches_reference({"instructor/tests/hidden/scenes/01_ray_casting_hidden.p3f",
                                                        "instructor/tests/hidden/01_ray_casting/01_ray_casting_hidden.png", 1, 200, 150});
}
