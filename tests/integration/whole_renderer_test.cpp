// The integration tier: every lab of one implementation together, rendering
// whole scenes at stage 6 against reference pictures made by the reference
// solution. A lab that passes its own tests but breaks when combined with the
// others (a wrong convention at an interface, say) shows up here.
#include "image_check.hpp"

#include <gtest/gtest.h>

using whitted::testing_helpers::ImageCheck;
using whitted::testing_helpers::expect_matches_reference;

TEST(Integration, ClassicWhittedSceneMatchesTheReference) {
    // Hollow glass shell, mirror sphere, shadows and checkerboard at 128 x 128.
    expect_matches_reference(ImageCheck{"scenes/whitted_1980.p3f", "tests/images/whitted_1980.png", 6, 128, 128});
}

TEST(Integration, ReflectionSceneMatchesTheReferenceAtStageSix) {
    expect_matches_reference(ImageCheck{"scenes/04_reflection.p3f", "tests/images/04_reflection_stage6.png", 6});
}

TEST(Integration, RefractionSceneMatchesTheReferenceAtStageSix) {
    expect_matches_reference(ImageCheck{"scenes/05_refraction.p3f", "tests/images/05_refraction_stage6.png", 6});
}

TEST(Integration, FresnelSceneMatchesTheReferenceAtStageSix) {
    expect_matches_reference(ImageCheck{"scenes/06_fresnel.p3f", "tests/images/06_fresnel_stage6.png", 6});
}
