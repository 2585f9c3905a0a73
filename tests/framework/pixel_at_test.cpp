// The pixel trace_pixel() traces for a viewport coordinate: std::floor of it
// (so -0.5 is in pixel -1, not 0), and pixel 0 for coordinates no int holds.
// pixel_at() computes it without std::floor; this holds it to std::floor.
#include "tracer_engine.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using whitted::pixel_at;

TEST(PixelAt, IsTheFloorOfTheCoordinate) {
    const std::vector<double> values = {0.0,  -0.0, 0.5,  1.0,   1.5,     -0.5,     -1.0,    -1.5,     2.9999999999999996,
                                        -2.0000000000000004, 511.5, 1e9 - 0.5, -1e9 + 0.5, std::nextafter(1.0, 0.0),
                                        std::nextafter(-1.0, 0.0), std::numeric_limits<double>::denorm_min(),
                                        -std::numeric_limits<double>::denorm_min()};
    for (const double v : values) EXPECT_EQ(pixel_at(v), static_cast<int>(std::floor(v))) << v;
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> anywhere(-1e6, 1e6);
    for (int i = 0; i < 100000; ++i) {
        const double v = anywhere(random);
        ASSERT_EQ(pixel_at(v), static_cast<int>(std::floor(v))) << v;
    }
}

TEST(PixelAt, IsPixelZeroWhereNoIntHoldsTheCoordinate) {
    for (const double v : {1e9, -1e9, 1e300, -1e300, std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()})
        EXPECT_EQ(pixel_at(v), 0) << v;
}
