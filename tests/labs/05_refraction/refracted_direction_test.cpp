// Spot checks of the reference labs against values derived by hand.
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;


TEST(Refraction, SnellAngleAt45DegreesIntoGlass) {
    // sin(theta_t) = sin(45) / 1.5  =>  theta_t = 28.1255 degrees, on the other side of the surface.
    const auto wt = refracted_direction(direction_at(45.0), kUp, 1.0, 1.5);
    ASSERT_TRUE(wt.has_value());
    EXPECT_NEAR(degrees(std::acos(-wt->z)), 28.1255, 1e-4);
    EXPECT_LT(wt->x, 0.0); // continues forward: opposite tangent side from wo
    EXPECT_NEAR(glm::length(*wt), 1.0, 1e-12);
}

TEST(Refraction, SnellAngleAt80DegreesIntoGlass) {
    const auto wt = refracted_direction(direction_at(80.0), kUp, 1.0, 1.5);
    ASSERT_TRUE(wt.has_value());
    EXPECT_NEAR(degrees(std::acos(-wt->z)), 41.0364, 1e-4);
}

TEST(Refraction, NormalIncidenceGoesStraightThrough) {
    const auto wt = refracted_direction(kUp, kUp, 1.0, 1.5);
    ASSERT_TRUE(wt.has_value());
    EXPECT_NEAR(wt->z, -1.0, 1e-15);
}

TEST(Refraction, TotalInternalReflectionBeyondTheCriticalAngle) {
    // Critical angle glass -> air: asin(1 / 1.5) = 41.8103 degrees.
    EXPECT_TRUE(refracted_direction(direction_at(41.80), kUp, 1.5, 1.0).has_value());
    EXPECT_FALSE(refracted_direction(direction_at(41.82), kUp, 1.5, 1.0).has_value());
}
