// Spot checks of the reference labs against values derived by hand.
#include "whitted/labs.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;


TEST(Fresnel, FourPercentAtNormalIncidenceOnGlass) {
    // ((1 - 1.5) / (1 + 1.5))^2 = 0.04
    EXPECT_NEAR(fresnel_reflectance(1.0, 1.0, 1.5), 0.04, 1e-12);
}

TEST(Fresnel, SpotValuesAt45And80Degrees) {
    EXPECT_NEAR(fresnel_reflectance(std::cos(radians(45.0)), 1.0, 1.5), 0.050240, 1e-6);
    EXPECT_NEAR(fresnel_reflectance(std::cos(radians(80.0)), 1.0, 1.5), 0.387704, 1e-6);
}

TEST(Fresnel, TotalInternalReflectionReflectsEverything) {
    EXPECT_EQ(fresnel_reflectance(std::cos(radians(60.0)), 1.5, 1.0), 1.0);
}

TEST(Fresnel, SameOnBothSidesAtMatchingAngles) {
    // Reciprocity: light entering at 45 degrees and leaving along the refracted path reflect alike.
    const double theta_t = std::asin(std::sin(radians(45.0)) / 1.5);
    EXPECT_NEAR(fresnel_reflectance(std::cos(radians(45.0)), 1.0, 1.5),
                fresnel_reflectance(std::cos(theta_t), 1.5, 1.0), 1e-12);
}
