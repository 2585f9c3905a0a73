// Spot checks of the reference labs against values derived by hand.
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;


TEST(Reflection, MirrorDirectionKeepsTheAngleAndFlipsTheTangent) {
    // r = 2 (wo . n) n - wo: for wo = (sin t, 0, cos t), r = (-sin t, 0, cos t).
    const Vec3 r = mirror_direction(direction_at(30.0), kUp);
    EXPECT_NEAR(r.x, -0.5, 1e-15);
    EXPECT_NEAR(r.z, std::sqrt(3.0) / 2.0, 1e-15);
}
