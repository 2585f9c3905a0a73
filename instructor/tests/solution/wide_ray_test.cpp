// The float box test must never reject a box the exact slab test accepts
// (wide_ray.hpp): cases found by an exact (GMP) fuzzer in review: directions
// far from unit length, and a unit ray from the world origin along a face at 0.
#include "whitted/labs.hpp"
#include "whitted/engine/leaf_kernels.hpp"
#include "whitted/scene.hpp"
#include "whitted/engine/ray_packet.hpp"
#include "whitted/engine/wide_ray.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <cstring>
#include <cstdint>
#include <vector>

using namespace whitted;

namespace {

// One real box in lane 0, the three other lanes empty (as WideBvh fills them).
unsigned test_one_box(const WideRay& wide, Vec3 lo, Vec3 hi) {
    alignas(16) float bounds[6][4];
    for (int axis = 0; axis < 3; ++axis) {
        for (int lane = 1; lane < 4; ++lane) {
            bounds[2 * axis][lane] = std::numeric_limits<float>::infinity();
            bounds[2 * axis + 1][lane] = -std::numeric_limits<float>::infinity();
        }
        // As WideBvh stores them: moved outwards by 2^-20 of themselves, then rounded outwards.
        const double low = lo[axis] - 0x1p-20 * std::abs(lo[axis]), high = hi[axis] + 0x1p-20 * std::abs(hi[axis]);
        float f = static_cast<float>(low), g = static_cast<float>(high);
        if (static_cast<double>(f) > low) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
        if (static_cast<double>(g) < high) g = std::nextafter(g, std::numeric_limits<float>::infinity());
        bounds[2 * axis][0] = f;
        bounds[2 * axis + 1][0] = g;
    }
    float t_entry[4];
    return wide.hit_boxes(bounds, t_entry);
}

// Eight unit-ish boxes along x so that the root of the BVH is not a leaf.
SceneData row_of_boxes() {
    SceneData data;
    data.materials.push_back(Material{});
    for (int i = 0; i < 8; ++i)
        data.primitives.push_back({Box{Point3(1.0 + 4.0 * i, -1.0, -2.0), Point3(2.0 + 4.0 * i, 0.015625, 2.0)}});
    return data;
}

} // namespace

// A tiny direction: flooring its components at a fixed 1e-30 would shrink an
// axis's exit distance by up to that ratio; WideRay scales the direction first.
// Exact: x in [1e30, 2e30], y exit = 0.015625 / 1e-40 = 1.6e38, z unconstrained: accepted.
// Float: y exit = (0.015625 + m) * 1e30 = 1.6e28 < x entry ~1e30: rejected.
TEST(WideRay, DirectionComponentBelowTheFloorLosesABox) {
    const Ray ray{Point3(0.0), Vec3(1e-30, 1e-40, 0.0)};
    const WideRay wide(ray, 2.0, 0.0, kInfinity); // extent: the box's largest coordinate
    EXPECT_EQ(1u, test_one_box(wide, Vec3(1.0, -1.0, -2.0), Vec3(2.0, 0.015625, 2.0)));
}

// A huge direction: a component beyond FLT_MAX would become +inf in float, its
// reciprocal 0, every distance on that axis 0, and t_min > 0 would reject the box.
// Exact: x in [1e-39, 2e-39], y, z unconstrained; range (5e-40, inf): accepted.
TEST(WideRay, DirectionComponentBeyondFloatMaxLosesABox) {
    const Ray ray{Point3(0.0), Vec3(1e39, 0.0, 0.0)};
    const WideRay wide(ray, 2.0, 5e-40, kInfinity);
    EXPECT_EQ(1u, test_one_box(wide, Vec3(1.0, -1.0, -1.0), Vec3(2.0, 1.0, 1.0)));
}

// The same two holes seen through Scene (labs path and kernels path), against
// the labs' closest_hit over every primitive without a BVH.
TEST(WideRay, SceneMissesWhatTestingEveryPrimitiveFinds) {
    const Scene labs(row_of_boxes());
    const Scene fast(row_of_boxes(), linked_leaf_kernels());
    struct Case {
        Ray ray;
        Interval range;
    };
    const Case cases[] = {{Ray{Point3(0.0), Vec3(1e-30, 1e-40, 0.0)}, Interval{0.0, kInfinity}},
                          {Ray{Point3(0.0), Vec3(1e39, 0.0, 0.0)}, Interval{5e-40, kInfinity}}};
    for (const Case& c : cases) {
        const auto expected = closest_hit(c.ray, labs.primitives(), c.range);
        ASSERT_TRUE(expected.has_value());
        for (const Scene* scene : {&labs, &fast}) {
            const auto found = scene->closest_hit(c.ray, c.range);
            EXPECT_TRUE(found.has_value()) << (scene == &fast ? "kernels" : "labs") << " d.x=" << c.ray.direction.x;
            EXPECT_TRUE(scene->occluded(c.ray, c.range)) << (scene == &fast ? "kernels" : "labs");
        }
    }
}

// A unit direction with a zero component (replaced by a tiny one): that axis's
// exit distance is about (face - origin + m) / tiny. With the origin and the
// face both at 0, a margin without the scene's size (2^-20 |origin| + 1e-30)
// made it 1e-30 * 2^62 = 4.6e-12, and every farther box was rejected although
// the axis does not constrain t.
// Exact: x unconstrained (0 in [-1, 0]), z in [4, 5]: accepted.
TEST(WideRay, UnitRayFromTheWorldOriginAlongABoxFaceAtZero) {
    const Ray ray{Point3(0.0), Vec3(0.0, 0.0, -1.0)};
    const WideRay wide(ray, 5.0, 0.0, kInfinity);
    EXPECT_EQ(1u, test_one_box(wide, Vec3(-1.0, -1.0, -5.0), Vec3(0.0, 1.0, -4.0)));
}

// The same through Scene: a triangle with an edge on the plane x = 0, met by a
// camera ray from the world origin exactly along that edge (b2 == 0: a hit for
// the labs' Moller-Trumbore), among fillers that keep every box at x <= 0.
TEST(WideRay, SceneLosesAnEdgeHitOnTheRayFromTheWorldOrigin) {
    SceneData data;
    data.materials.push_back(Material{});
    for (int i = 0; i < 12; ++i) {
        const double y = 10.0 * i; // i == 0: the triangle the ray meets
        data.primitives.push_back({Triangle{Point3(0.0, y - 1.0, -5.0), Point3(0.0, y + 1.0, -5.0), Point3(-1.0, y, -5.0)}});
    }
    const Scene labs(data);
    const Scene fast(data, linked_leaf_kernels());
    const Ray ray{Point3(0.0), Vec3(0.0, 0.0, -1.0)};
    const auto expected = closest_hit(ray, labs.primitives(), Interval{});
    ASSERT_TRUE(expected.has_value());
    EXPECT_EQ(5.0, expected->t);
    EXPECT_TRUE(labs.closest_hit(ray).has_value()) << "labs path";
    EXPECT_TRUE(fast.closest_hit(ray).has_value()) << "kernels path";
    EXPECT_TRUE(labs.occluded(ray, Interval{0.0, 10.0}));
    EXPECT_TRUE(fast.occluded(ray, Interval{0.0, 10.0}));
}

// A node's eight boxes are tested four at a time: a box in the second four
// answers in its own bit with its own entry distance. The ray runs along +x from
// the origin; box k spans x in [k + 1, k + 1.5], so the ray enters it at t = k + 1,
// which WideRay gives along its direction scaled to [0.5, 1), here (0.5, 0, 0):
// 2 (k + 1). Boxes 2 and 5 lie above the ray (y in [1, 2]).
TEST(WideRay, EightBoxesAnswerInTheirOwnBits) {
    const WideRay wide(Ray{Point3(0.0), Vec3(1.0, 0.0, 0.0)}, 16.0, 0.0, kInfinity);
    alignas(64) float bounds[6][8];
    for (int k = 0; k < 8; ++k) {
        const bool above = k == 2 || k == 5;
        bounds[0][k] = static_cast<float>(k + 1);
        bounds[1][k] = static_cast<float>(k + 1.5);
        bounds[2][k] = above ? 1.0f : -1.0f;
        bounds[3][k] = above ? 2.0f : 1.0f;
        bounds[4][k] = -1.0f;
        bounds[5][k] = 1.0f;
    }
    float t_entry[8];
    EXPECT_EQ(wide.hit_boxes(bounds, t_entry), 0b1101'1011u);
    for (int k : {0, 1, 3, 4, 6, 7}) EXPECT_NEAR(t_entry[k], 2.0 * (k + 1), 1e-5) << "box " << k;
}

TEST(WideRay, PacketLanesHoldWhatEachRayAloneComputes) {
    // RayPacket computes its lanes four rays at a time; each lane must hold the
    // very numbers WideRay::numbers() gives its ray (a margin that is too small
    // errs towards "miss" and no answer-level test would see it). Directions of
    // random binary exponents, with components of +-0, subnormals and 2^-62 or so.
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> unit(0.5, 1.0), position(-40.0, 40.0);
    std::uniform_int_distribution<int> exponent(-60, 60), count(1, RayPacket::kMaxRays), special(0, 9);
    const auto bits = [](auto value) {
        std::uint64_t b = 0;
        std::memcpy(&b, &value, sizeof value);
        return b;
    };
    int packets = 0;
    for (int p = 0; p < 20000; ++p) {
        const int e = exponent(rng), n = count(rng);
        const Vec3 sign(p & 1 ? -1.0 : 1.0, p & 2 ? -1.0 : 1.0, p & 4 ? -1.0 : 1.0);
        std::vector<Ray> rays;
        std::vector<Interval> ranges;
        for (int i = 0; i < n; ++i) {
            Vec3 d = sign * Vec3(unit(rng), unit(rng), unit(rng));
            d[i % 3] = sign[i % 3]; // the largest component sets the packet's one scale
            const int odd = special(rng);
            if (odd == 0) d[(i + 1) % 3] = sign[(i + 1) % 3] * 0.0;
            if (odd == 1) d[(i + 2) % 3] = sign[(i + 2) % 3] * 0x1p-1070;
            if (odd == 2) d[(i + 1) % 3] = sign[(i + 1) % 3] * std::ldexp(1.0, -62 - e);
            rays.push_back(Ray{std::ldexp(position(rng), p % 7) * Point3(unit(rng), -unit(rng), unit(rng)), std::ldexp(1.0, e) * d});
            ranges.push_back(p % 3 == 0 ? Interval{} : Interval{0.25 * unit(rng), std::ldexp(unit(rng), 4 - e)});
        }
        const double extent = std::ldexp(1.0, p % 11);
        const RayPacket packet(rays, ranges, extent);
        ASSERT_TRUE(packet.coherent()) << "packet " << p;
        ++packets;
        for (int i = 0; i < n; ++i) {
            const WideRay::Numbers alone = WideRay::numbers(rays[i], extent, ranges[i].min, ranges[i].max);
            const WideRay::Numbers lane = packet.lane(i);
            ASSERT_EQ(bits(alone.inverse_scale), bits(lane.inverse_scale)) << "packet " << p << " ray " << i;
            ASSERT_EQ(bits(alone.t_min), bits(lane.t_min)) << "packet " << p << " ray " << i;
            ASSERT_EQ(bits(alone.t_max), bits(lane.t_max)) << "packet " << p << " ray " << i;
            for (int axis = 0; axis < 3; ++axis) {
                ASSERT_EQ(alone.negative[axis], lane.negative[axis]) << "packet " << p << " ray " << i;
                ASSERT_EQ(bits(alone.inv[axis]), bits(lane.inv[axis])) << "packet " << p << " ray " << i << " axis " << axis;
                ASSERT_EQ(bits(alone.origin_entry[axis]), bits(lane.origin_entry[axis])) << "packet " << p << " ray " << i;
                ASSERT_EQ(bits(alone.origin_exit[axis]), bits(lane.origin_exit[axis])) << "packet " << p << " ray " << i;
            }
        }
    }
    EXPECT_EQ(packets, 20000);
}

TEST(WideRay, AnInfiniteOriginInAPacketCostsTheOtherRaysNoBox) {
    // An infinite origin moved by its (infinite) margin is a NaN, and a NaN in
    // the packet's ranges failed every box test of the packet (found in review):
    // the other rays lost their hits. Such a packet now goes one ray at a time.
    int tested = 0;
    for (int count = 1; count <= RayPacket::kMaxRays; ++count)
        for (int bad = 0; bad < count; ++bad)
            for (int axis = 0; axis < 3; ++axis) {
                std::vector<Ray> rays;
                for (int i = 0; i < count; ++i) rays.push_back(Ray{Point3(0.0), glm::normalize(Vec3(0.01 * i, 0.01, 1.0))});
                rays[bad].origin[axis] = std::numeric_limits<double>::infinity();
                const std::vector<Interval> ranges(count, Interval{0.0, 1e3});
                const RayPacket packet(rays, ranges, 30.0);
                ASSERT_FALSE(packet.coherent()) << count << " rays, origin[" << axis << "] infinite in lane " << bad;
                ++tested;
            }
    EXPECT_EQ(tested, 3 * RayPacket::kMaxRays * (RayPacket::kMaxRays + 1) / 2);
}

TEST(WideRay, RangeEndsRoundOutwardsToTheNearestFloats) {
    // numbers() rounds t_min down and t_max up to floats (a unit-size direction
    // keeps t in its own units): the float range must hold the double one, and
    // be the tightest that does. Checked against std::nextafter on doubles of
    // every size, both signs, zeros, floats exactly, halfway cases and beyond FLT_MAX.
    const double max = std::numeric_limits<float>::max();
    const float inf = std::numeric_limits<float>::infinity();
    const auto below = [](float f) { return std::nextafter(f, -std::numeric_limits<float>::infinity()); };
    const auto above = [](float f) { return std::nextafter(f, std::numeric_limits<float>::infinity()); };
    const auto down = [&](double t) -> float {
        if (t < -max) return -inf;
        if (t > max) return std::numeric_limits<float>::max();
        const float f = static_cast<float>(t);
        return static_cast<double>(f) > t ? below(f) : f;
    };
    const auto up = [&](double t) -> float {
        if (t > max) return inf;
        if (t < -max) return -std::numeric_limits<float>::max();
        const float f = static_cast<float>(t);
        return static_cast<double>(f) < t ? above(f) : f;
    };
    std::vector<double> values{0.0, -0.0, 1.0, -1.0, 0x1p-149, -0x1p-149, 0x1p-150, -0x1p-150, 0x1p-160, -0x1p-160,
                               0x1p-126, -0x1p-126, max, -max, 0x1.fffffefffffffp127, 0x1p128, -0x1p128, 1e300, -1e300,
                               kInfinity, -kInfinity, 1.0 + 0x1p-24, 1.0 - 0x1p-25, -1.0 - 0x1p-24};
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(1.0, 2.0);
    std::uniform_int_distribution<int> exponent(-160, 130);
    for (int i = 0; i < 200000; ++i) {
        const double t = std::ldexp(unit(rng), exponent(rng));
        values.push_back(i % 2 ? t : -t);
        values.push_back(static_cast<double>(static_cast<float>(t))); // a float exactly
    }
    const Ray ray{Point3(0.0), Vec3(0.75, 0.5, -0.25)};
    for (const double t : values) {
        const WideRay::Numbers n = WideRay::numbers(ray, 1.0, t, t);
        ASSERT_EQ(n.inverse_scale, 1.0);
        const float low = down(t), high = up(t);
        ASSERT_EQ(std::memcmp(&n.t_min, &low, sizeof low), 0) << std::hexfloat << t << " down: " << n.t_min << " not " << low;
        ASSERT_EQ(std::memcmp(&n.t_max, &high, sizeof high), 0) << std::hexfloat << t << " up: " << n.t_max << " not " << high;
    }
    // A packet rounds four range ends at a time, in SSE2: the same floats, in
    // every lane position and packet size (the values in their order, then shuffled).
    std::vector<double> shuffled = values;
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    values.insert(values.end(), shuffled.begin(), shuffled.end());
    for (std::size_t first = 0, size = 1; first < values.size(); first += size, size = size % RayPacket::kMaxRays + 1) {
        const std::size_t n = std::min(size, values.size() - first);
        const std::vector<Ray> rays(n, ray);
        std::vector<Interval> ranges;
        for (std::size_t i = 0; i < n; ++i) ranges.push_back(Interval{values[first + i], values[first + (i + 1) % n]});
        const RayPacket packet(rays, ranges, 1.0);
        for (std::size_t i = 0; i < n; ++i) {
            const WideRay::Numbers lane = packet.lane(static_cast<int>(i));
            const float low = down(ranges[i].min), high = up(ranges[i].max);
            ASSERT_EQ(std::memcmp(&lane.t_min, &low, sizeof low), 0) << std::hexfloat << ranges[i].min << " down in lane " << i;
            ASSERT_EQ(std::memcmp(&lane.t_max, &high, sizeof high), 0) << std::hexfloat << ranges[i].max << " up in lane " << i;
        }
    }
}
