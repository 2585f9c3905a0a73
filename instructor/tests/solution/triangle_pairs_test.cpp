// The leaf kernels' two-triangles-at-once test (solution/leaf_kernels/screens.hpp)
// must say exactly what lab 1's triangle_distance says of each triangle: hit or
// not, and where, bit for bit, also for rays that graze an edge or a corner,
// triangles without area and ranges that end at the hit.
#include "../../../solution/leaf_kernels/screens.hpp"

#include "whitted/engine/hit_distances.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

using namespace whitted;

namespace {

[[maybe_unused]] bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// A triangle of random size and place; every fifth without area (a corner on the opposite edge's line).
[[maybe_unused]] Triangle random_triangle(std::mt19937& rng, int i) {
    std::uniform_real_distribution<double> position(-5.0, 5.0), fraction(0.0, 1.0);
    const double scale = std::ldexp(1.0, static_cast<int>(fraction(rng) * 40.0) - 20);
    Triangle triangle{scale * Point3(position(rng), position(rng), position(rng)),
                      scale * Point3(position(rng), position(rng), position(rng)),
                      scale * Point3(position(rng), position(rng), position(rng))};
    if (i % 5 == 0) triangle.p2 = triangle.p0 + fraction(rng) * (triangle.p1 - triangle.p0);
    return triangle;
}

// A ray at a point of the triangle: inside, on an edge, or at a corner, from a random side.
[[maybe_unused]] Ray ray_at(std::mt19937& rng, const Triangle& triangle, int i) {
    std::uniform_real_distribution<double> position(-5.0, 5.0), fraction(0.0, 1.0);
    double b1 = fraction(rng), b2 = fraction(rng) * (1.0 - b1);
    if (i % 3 == 1) b2 = 0.0;                  // on the edge p0-p1
    if (i % 3 == 2) b1 = 1.0 - b2;             // on the edge p1-p2
    if (i % 7 == 0) b1 = i % 2, b2 = 0.0;      // at a corner
    const Point3 target = triangle.p0 + b1 * (triangle.p1 - triangle.p0) + b2 * (triangle.p2 - triangle.p0);
    const double size = glm::length(triangle.p1 - triangle.p0) + 1e-300;
    const Point3 origin = target + size * Vec3(position(rng), position(rng), position(rng));
    return Ray{origin, glm::normalize(target - origin)};
}

} // namespace

TEST(TrianglePairs, SayWhatLabOnesTriangleTestSaysOfEach) {
#if !WHITTED_PAIR_LANES
    GTEST_SKIP() << "the pairs are SSE2 code; without SSE2 arithmetic the kernels test one triangle at a time";
#else
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> fraction(0.0, 1.0);
    int hits = 0, misses = 0, cut_by_range = 0;
    for (int i = 0; i < 200000; ++i) {
        const Triangle a = random_triangle(rng, i), b = random_triangle(rng, i + 1);
        const Ray ray = ray_at(rng, i % 2 == 0 ? a : b, i);
        // Ranges that end anywhere, also exactly at the hit.
        Interval t_range{};
        if (const auto aimed = triangle_distance(ray, i % 2 == 0 ? a : b, Interval{}); aimed && i % 4 != 0)
            t_range = i % 4 == 1 ? Interval{0.0, aimed->t} : i % 4 == 2 ? Interval{aimed->t, 1e300} : Interval{0.0, fraction(rng) * 2.0 * aimed->t};
        const screens::TrianglePair pair = screens::triangle_pair_distances(ray, a, b, t_range);
        for (int lane = 0; lane < 2; ++lane) {
            const auto expected = triangle_distance(ray, lane == 0 ? a : b, t_range);
            ASSERT_EQ(expected.has_value(), (pair.hit >> lane & 1u) != 0) << "case " << i << " lane " << lane;
            if (!expected) {
                ++misses;
                cut_by_range += triangle_distance(ray, lane == 0 ? a : b, Interval{}).has_value();
                continue;
            }
            ++hits;
            ASSERT_TRUE(same_bits(expected->t, pair.t[lane])) << "case " << i << " lane " << lane;
            ASSERT_TRUE(same_bits(expected->b1, pair.b1[lane])) << "case " << i << " lane " << lane;
            ASSERT_TRUE(same_bits(expected->b2, pair.b2[lane])) << "case " << i << " lane " << lane;
        }
    }
    // The comparison means something only if all three outcomes are common.
    EXPECT_GT(hits, 50000);
    EXPECT_GT(misses, 50000);
    EXPECT_GT(cut_by_range, 20000);
#endif
}
