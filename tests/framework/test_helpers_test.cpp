// The comparison helpers of the lab tests: a wrong answer must never pass
// because of how NaN compares (every comparison with NaN is false, so a plain
// max of |differences| silently skips a NaN component).
#include "test_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace whitted;

TEST(TestHelpers, NearFailsOnNaNOrInfinityInAnyComponent) {
    const double nan = std::nan("");
    const double inf = std::numeric_limits<double>::infinity();
    const Vec3 expected(1.0, 2.0, 3.0);
    EXPECT_TRUE(testing_helpers::near(Vec3(1.0, 2.0, 3.0), expected));
    for (const Vec3& wrong : {Vec3(nan, 2.0, 3.0), Vec3(1.0, nan, 3.0), Vec3(1.0, 2.0, nan), Vec3(1.0, nan, nan),
                              Vec3(1.0, inf, 3.0), Vec3(1.0, 2.0, -inf)}) {
        EXPECT_FALSE(testing_helpers::near(wrong, expected, 1e9)) << wrong.x << " " << wrong.y << " " << wrong.z;
        EXPECT_FALSE(testing_helpers::near(expected, wrong, 1e9));
    }
}

TEST(TestHelpers, MaxAbsComponentKeepsNaN) {
    EXPECT_EQ(max_abs_component(Vec3(-4.0, 2.0, 3.0)), 4.0);
    EXPECT_TRUE(std::isnan(max_abs_component(Vec3(1.0, std::nan(""), 3.0))));
    EXPECT_TRUE(std::isnan(max_abs_component(Vec3(1.0, 2.0, std::nan("")))));
    EXPECT_TRUE(std::isnan(max_abs_component(Vec3(std::nan(""), 2.0, 3.0))));
}
