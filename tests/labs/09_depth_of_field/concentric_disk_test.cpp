// Lab 9, concentric_disk(): Shirley and Chiu's mapping of the square [0, 1)^2 onto
// the unit disk. a = 2u - 1; the wedges left and right of the diagonals take the
// radius a.x and the angle (pi / 4) (a.y / a.x), those above and below the radius
// a.y and the angle pi / 2 - (pi / 4) (a.x / a.y).
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace whitted;
using namespace whitted::testing_helpers;

TEST(ConcentricDisk, TheCentreOfTheSquareIsTheCentreOfTheDisk) {
    // u = (1/2, 1/2): a = (0, 0), which has no angle: the centre itself.
    const Vec2 d = concentric_disk(Vec2(0.5, 0.5));
    EXPECT_EQ(d.x, 0.0);
    EXPECT_EQ(d.y, 0.0);
    // A quarter of the way from it to the right edge, u = (0.625, 0.5): a = (0.25, 0), the right wedge,
    // r = 0.25 at angle 0: (0.25, 0).
    expect_vec2(concentric_disk(Vec2(0.625, 0.5)), 0.25, 0.0, "u = (0.625, 0.5)");
}

TEST(ConcentricDisk, TheMiddlesOfTheSquaresEdgesGoToTheCircle) {
    // u = (0, 1/2): a = (-1, 0), the left wedge: r = -1, angle 0 -> (-1, 0).
    expect_vec2(concentric_disk(Vec2(0.0, 0.5)), -1.0, 0.0, "left edge");
    // u = (1/2, 0): a = (0, -1), the lower wedge: r = -1, angle pi/2 -> (0, -1).
    expect_vec2(concentric_disk(Vec2(0.5, 0.0)), 0.0, -1.0, "bottom edge");
    // The right and top edges (u = 1, the limit of [0, 1)): (1, 0) and (0, 1).
    expect_vec2(concentric_disk(Vec2(1.0, 0.5)), 1.0, 0.0, "right edge");
    expect_vec2(concentric_disk(Vec2(0.5, 1.0)), 0.0, 1.0, "top edge");
}

TEST(ConcentricDisk, TheCornerGoesToTheCircleOnItsDiagonal) {
    // u = (0, 0): a = (-1, -1), |a.x| = |a.y|: r = a.y = -1, angle pi/2 - pi/4 = pi/4
    // -> -(cos 45, sin 45) = (-0.7071068, -0.7071068).
    expect_vec2(concentric_disk(Vec2(0.0, 0.0)), -std::sqrt(0.5), -std::sqrt(0.5), "corner (0, 0)");
}

TEST(ConcentricDisk, InteriorPointsComputedByHand) {
    // u = (0.75, 0.625): a = (0.5, 0.25), the right wedge: r = 0.5, angle (pi/4)(0.5) = pi/8
    // -> (0.5 cos 22.5, 0.5 sin 22.5) = (0.4619398, 0.1913417).
    expect_vec2(concentric_disk(Vec2(0.75, 0.625)), 0.5 * std::cos(kPi / 8.0), 0.5 * std::sin(kPi / 8.0),
                      "u = (0.75, 0.625)");
    // u = (0.125, 0.625): a = (-0.75, 0.25), the left wedge: r = -0.75, angle (pi/4)(-1/3) = -15 degrees
    // -> -0.75 (cos 15, -sin 15) = (-0.7244444, 0.1941143).
    expect_vec2(concentric_disk(Vec2(0.125, 0.625)), -0.75 * std::cos(kPi / 12.0), 0.75 * std::sin(kPi / 12.0),
                      "u = (0.125, 0.625)");
    // u = (0.6, 0.9): a = (0.2, 0.8), the upper wedge: r = 0.8, angle pi/2 - (pi/4)(1/4) = 78.75 degrees
    // -> (0.8 cos 78.75, 0.8 sin 78.75) = (0.1560723, 0.7846282).
    expect_vec2(concentric_disk(Vec2(0.6, 0.9)), 0.8 * std::cos(7.0 * kPi / 16.0), 0.8 * std::sin(7.0 * kPi / 16.0),
                      "u = (0.6, 0.9)");
    // u = (0.375, 0.125): a = (-0.25, -0.75), the lower wedge: r = -0.75, angle pi/2 - (pi/4)(1/3) = 75 degrees
    // -> -0.75 (cos 75, sin 75) = (-0.1941143, -0.7244444).
    expect_vec2(concentric_disk(Vec2(0.375, 0.125)), -0.75 * std::cos(5.0 * kPi / 12.0),
                      -0.75 * std::sin(5.0 * kPi / 12.0), "u = (0.375, 0.125)");
}

TEST(ConcentricDisk, EachSquareAroundTheCentreBecomesACircleOfTheSameRadius) {
    // The points with max(|a.x|, |a.y|) = s land at distance s from the centre, in the
    // quadrant of a: walking round the square walks round the circle.
    for (double s : {0.1, 0.5, 0.9}) {
        for (int k = 0; k < 64; ++k) {
            const double t = -1.0 + 2.0 * (k + 0.5) / 64.0; // along each edge, -1..1
            const Vec2 edges[] = {{s, s * t}, {-s, s * t}, {s * t, s}, {s * t, -s}};
            for (const Vec2& a : edges) {
                const Vec2 d = concentric_disk((a + Vec2(1.0)) / 2.0);
                EXPECT_NEAR(glm::length(d), s, 1e-12) << "a = (" << a.x << ", " << a.y << ")";
                EXPECT_TRUE(d.x * a.x >= -1e-12 && d.y * a.y >= -1e-12)
                    << "a = (" << a.x << ", " << a.y << ") went to another quadrant: (" << d.x << ", " << d.y << ")";
                if (enough_failures()) return;
            }
        }
    }
}

TEST(ConcentricDisk, EveryPointLiesInTheUnitDisk) {
    for (int i = 0; i <= 100; ++i)
        for (int j = 0; j <= 100; ++j) {
            const Vec2 d = concentric_disk(Vec2(i / 100.0, j / 100.0));
            ASSERT_LE(glm::length(d), 1.0 + 1e-12) << "u = (" << i / 100.0 << ", " << j / 100.0 << ")";
        }
    // And the square's border fills the circle: u with a coordinate 0 has |a.x| or |a.y| = 1, so r = 1.
    for (int k = 0; k <= 100; ++k) {
        EXPECT_NEAR(glm::length(concentric_disk(Vec2(0.0, k / 100.0))), 1.0, 1e-12) << "u = (0, " << k / 100.0 << ")";
        EXPECT_NEAR(glm::length(concentric_disk(Vec2(k / 100.0, 0.0))), 1.0, 1e-12) << "u = (" << k / 100.0 << ", 0)";
    }
}

TEST(ConcentricDisk, AFractionRSquaredOfTheSquareLandsWithinRadiusR) {
    // Area preserved: the disk of radius r has r^2 of the unit disk's area, so r^2 of
    // the square's points land in it. The centres of a 400 x 400 grid of u: within
    // 0.01 of r^2 (the grid's own error is below 2 / 400). A map with the radius u.x
    // (the naive polar map) puts a fraction r there: 0.5 instead of 0.25 for r = 1/2.
    constexpr int n = 400;
    std::vector<double> radii; // each point's distance from the centre, mapped once (a grader's call is not free)
    radii.reserve(n * n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) radii.push_back(glm::length(concentric_disk(Vec2((i + 0.5) / n, (j + 0.5) / n))));
    for (double r : {0.25, 0.5, 0.75, 0.9}) {
        const auto inside = std::count_if(radii.begin(), radii.end(), [r](double radius) { return radius < r; });
        EXPECT_NEAR(static_cast<double>(inside) / (n * n), r * r, 0.01) << "within radius " << r;
    }
}

TEST(ConcentricDisk, EverySmallSquareOfUCoversPiTimesItsArea) {
    // The square (area 1) onto the disk (area pi) with no stretching anywhere: the
    // image of a small square of side e around u has area pi e^2, the determinant of
    // the map's derivative (by finite differences), away from the diagonals and axes.
    const double e = 1e-6;
    const Vec2 places[] = {{0.8, 0.6}, {0.9, 0.95}, {0.3, 0.55}, {0.1, 0.2}, {0.55, 0.15}, {0.62, 0.93}, {0.2, 0.9}};
    for (const Vec2& u : places) {
        const Vec2 du = (concentric_disk(u + Vec2(e, 0.0)) - concentric_disk(u - Vec2(e, 0.0))) / (2.0 * e);
        const Vec2 dv = (concentric_disk(u + Vec2(0.0, e)) - concentric_disk(u - Vec2(0.0, e))) / (2.0 * e);
        EXPECT_NEAR(std::abs(du.x * dv.y - du.y * dv.x), kPi, 1e-4) << "u = (" << u.x << ", " << u.y << ")";
    }
}

TEST(ConcentricDisk, ManyLensSamplesAverageToTheCentreAndFillTheDisk) {
    // The framework's lens numbers of 64 x 64 pixels, 4 samples each, mapped onto the
    // disk: uniform points of the disk average to its centre and have mean square
    // radius 1/2 (the integral of r^2 over the disk, over its area pi). 16384 points:
    // the averages are within about 0.005 (one standard error); 0.02 is four of them.
    Vec2 sum(0.0);
    double sum_r2 = 0.0;
    int count = 0;
    for (int x = 0; x < 64; ++x)
        for (int y = 0; y < 64; ++y)
            for (int k = 0; k < 4; ++k) {
                const Vec2 d = concentric_disk(sample_numbers(PixelSample{x, y, k}, SampleUse::lens));
                sum += d;
                sum_r2 += glm::dot(d, d);
                ++count;
            }
    EXPECT_NEAR(sum.x / count, 0.0, 0.02);
    EXPECT_NEAR(sum.y / count, 0.0, 0.02);
    EXPECT_NEAR(sum_r2 / count, 0.5, 0.02);
}
