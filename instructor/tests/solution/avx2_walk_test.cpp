// The walk's AVX2 box tests (wide_ray.hpp, ray_packet.hpp, wide_bvh.hpp) must
// give the SSE2 tests' answers bit for bit: they are the same operations on the
// same numbers, eight lanes at once instead of four. Where they agree, the walks
// visit the same leaves in the same order, and the conservative box test the
// other tests prove for SSE2 holds for AVX2. Skipped on a CPU without AVX2,
// where the walk never uses them.
#include "whitted/engine/bvh.hpp"
#include "whitted/engine/ray_packet.hpp"
#include "whitted/engine/wide_bvh.hpp"
#include "whitted/engine/wide_ray.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <tuple>
#include <vector>

using namespace whitted;

#if WHITTED_AVX2_WALK

namespace {

bool cpu_has_avx2() { return __builtin_cpu_supports("avx2"); }

// Rays of every kind the walk meets: unit and far from unit length, components
// of 0 and of tiny and huge size, origins near and far, finite and infinite
// ranges; and one in sixteen with an infinite, NaN or beyond-float number, whose
// NaN distances must meet the same lane-wise rules (max and min keep their
// second operand's NaN) in AVX2 as in SSE2.
struct RayMaker {
    std::mt19937 rng{2026};
    std::uniform_real_distribution<double> unit{-1.0, 1.0}, position{-50.0, 50.0}, spread{0.98, 1.02};
    std::uniform_int_distribution<int> exponent{-40, 40}, special{0, 11}, odd{0, 15}, axis{0, 2};

    // An infinity, a NaN or a number no float holds, now and then.
    double odd_number(double usual) {
        switch (odd(rng)) {
        case 0: return std::numeric_limits<double>::infinity();
        case 1: return -std::numeric_limits<double>::infinity();
        case 2: return std::numeric_limits<double>::quiet_NaN();
        case 3: return 1e39;
        case 4: return -1e300;
        default: return usual;
        }
    }
    bool now_and_then() { return odd(rng) == 0; }

    Vec3 direction() {
        Vec3 d(unit(rng), unit(rng), unit(rng));
        switch (special(rng)) {
        case 0: d.x = 0.0; break;
        case 1: d.y = -0.0; break;
        case 2: d.z = 0x1p-1070; break;
        case 3: d = Vec3(0.0, 0.0, d.z < 0.0 ? -1.0 : 1.0); break;
        default: break;
        }
        d = std::ldexp(1.0, exponent(rng)) * d;
        if (now_and_then()) d[axis(rng)] = odd_number(d.x);
        return d;
    }
    Point3 origin() {
        Point3 o = std::ldexp(1.0, exponent(rng) / 4) * Point3(position(rng), position(rng), position(rng));
        if (now_and_then()) o[axis(rng)] = odd_number(o.y);
        return o;
    }
    Interval range() {
        const int kind = special(rng);
        if (kind < 4) return Interval{};
        const double from = kind < 8 ? 0.0 : std::abs(position(rng));
        Interval range{from, from + std::ldexp(std::abs(position(rng)), exponent(rng) / 2)};
        if (now_and_then()) range.max = odd_number(range.max);
        return range;
    }
};

// Eight boxes of all sizes around the origin, some empty (as WideBvh pads a node), some flat.
void random_boxes(std::mt19937& rng, float (&bounds)[6][8]) {
    std::uniform_real_distribution<float> place(-60.0f, 60.0f), size(0.0f, 30.0f);
    std::uniform_int_distribution<int> kind(0, 9);
    for (int k = 0; k < 8; ++k) {
        const int which = kind(rng);
        for (int axis = 0; axis < 3; ++axis) {
            const float low = place(rng), extent = which == 1 ? 0.0f : size(rng);
            bounds[2 * axis][k] = which == 0 ? std::numeric_limits<float>::infinity() : low;
            bounds[2 * axis + 1][k] = which == 0 ? -std::numeric_limits<float>::infinity() : low + extent;
        }
    }
}

// Box k spans x in [k + 1, k + 2] (y and z in [-1, 1]): a ray along +x from
// the origin enters it at t = k + 1 and leaves it at k + 2, exactly in float.
alignas(32) constexpr float kRowAlongX[6][8] = {{1, 2, 3, 4, 5, 6, 7, 8},         {2, 3, 4, 5, 6, 7, 8, 9},
                                                {-1, -1, -1, -1, -1, -1, -1, -1}, {1, 1, 1, 1, 1, 1, 1, 1},
                                                {-1, -1, -1, -1, -1, -1, -1, -1}, {1, 1, 1, 1, 1, 1, 1, 1}};

// The centre of box k of a node's bounds.
Point3 box_centre(const float (&bounds)[6][8], int k) {
    return 0.5 * Point3(bounds[0][k] + bounds[1][k], bounds[2][k] + bounds[3][k], bounds[4][k] + bounds[5][k]);
}

} // namespace

TEST(Avx2Walk, EightBoxesOfOneRayGiveTheSse2Bits) {
    if (!cpu_has_avx2()) GTEST_SKIP() << "this CPU has no AVX2: the walk tests boxes with SSE2 only";
    RayMaker make;
    std::mt19937 rng(5);
    int differing = 0, hits = 0;
    for (int i = 0; i < 200000; ++i) {
        alignas(32) float bounds[6][8];
        random_boxes(rng, bounds);
        // Every other ray aimed at a box's centre, at its own length, so that boxes are met.
        const Point3 origin = make.origin();
        Vec3 direction = make.direction();
        const int aim = i % 16;
        if (aim < 8 && bounds[0][aim] <= bounds[1][aim])
            direction = glm::length(direction) * (box_centre(bounds, aim) - origin);
        const Interval range = aim < 8 ? Interval{} : make.range();
        const WideRay wide(Ray{origin, direction}, 64.0, range.min, range.max);
        float sse2_entry[8], avx2_entry[8];
        const unsigned sse2 = wide.hit_boxes(bounds, sse2_entry);
        const unsigned avx2 = wide.hit_eight_boxes_avx2(bounds, avx2_entry);
        hits += std::popcount(sse2);
        bool same = sse2 == avx2;
        for (int k = 0; k < 8; ++k) same &= std::bit_cast<std::uint32_t>(sse2_entry[k]) == std::bit_cast<std::uint32_t>(avx2_entry[k]);
        differing += same ? 0 : 1;
    }
    // Ranges that end exactly where a box begins: entry == exit, a hit for both.
    for (const double t_max : {1.0, 2.0, 3.0, 4.5, 8.0}) {
        const WideRay wide(Ray{Point3(0.0), Vec3(1.0, 0.0, 0.0)}, 16.0, 0.0, t_max);
        float sse2_entry[8], avx2_entry[8];
        const unsigned sse2 = wide.hit_boxes(kRowAlongX, sse2_entry);
        EXPECT_EQ(sse2, wide.hit_eight_boxes_avx2(kRowAlongX, avx2_entry)) << "range (0, " << t_max << ")";
        EXPECT_NE(sse2 & (1u << (static_cast<int>(t_max) - 1)), 0u) << "the box the range ends on, t_max " << t_max;
    }
    EXPECT_EQ(differing, 0) << "node tests whose AVX2 answer differs from SSE2's";
    EXPECT_GT(hits, 100000) << "the boxes must be met often for the comparison to mean something";
}

TEST(Avx2Walk, PacketTestsGiveTheSse2Bits) {
    if (!cpu_has_avx2()) GTEST_SKIP() << "this CPU has no AVX2: the walk tests boxes with SSE2 only";
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> jitter(-0.05, 0.05), unit(0.3, 1.0), position(-20.0, 20.0);
    std::uniform_int_distribution<int> count(1, RayPacket::kMaxRays), mask(0, (1 << RayPacket::kMaxRays) - 1);
    int differing = 0, packets = 0, meetings = 0;
    for (int p = 0; p < 20000; ++p) {
        // Rays from near one point in near one direction (a coherent packet), of random length.
        const Vec3 sign(p & 1 ? -1.0 : 1.0, p & 2 ? -1.0 : 1.0, p & 4 ? -1.0 : 1.0);
        alignas(32) float bounds[6][8];
        random_boxes(rng, bounds);
        // One packet in 32 from beyond what a float holds: NaN and infinite distances in its lanes.
        const Point3 o0 = (p % 32 == 5 ? 1e39 : 1.0) * Point3(position(rng), position(rng), position(rng));
        const int aim = p % 8; // the packet aimed at a box's centre when it has one
        const Vec3 d0 = bounds[0][aim] <= bounds[1][aim] ? box_centre(bounds, aim) - o0 : sign * Vec3(unit(rng), unit(rng), 1.0);
        const int n = count(rng);
        std::vector<Ray> rays;
        std::vector<Interval> ranges;
        for (int i = 0; i < n; ++i) {
            const Vec3 d = d0 + glm::length(d0) * Vec3(jitter(rng), jitter(rng), 0.0);
            rays.push_back(Ray{o0 + Vec3(jitter(rng), jitter(rng), jitter(rng)), std::ldexp(1.0, p % 5 - 2) * d});
            ranges.push_back(p % 3 == 0 ? Interval{} : Interval{0.0, 40.0 + 80.0 * unit(rng)});
        }
        const RayPacket packet(rays, ranges, 64.0);
        if (!packet.coherent()) continue;
        ++packets;
        float sse2_entry[8], avx2_entry[8];
        const unsigned sse2 = packet.hit_boxes(bounds, sse2_entry);
        const unsigned avx2 = packet.hit_eight_boxes_avx2(bounds, avx2_entry);
        bool same = sse2 == avx2;
        for (int k = 0; k < 8; ++k) same &= std::bit_cast<std::uint32_t>(sse2_entry[k]) == std::bit_cast<std::uint32_t>(avx2_entry[k]);
        const unsigned asked = static_cast<unsigned>(mask(rng)) & ((1u << n) - 1u);
        for (int slot = 0; slot < 8; ++slot) {
            const unsigned meeting = packet.rays_meeting(bounds, slot, asked);
            same &= meeting == packet.rays_meeting_avx2(bounds, slot, asked);
            meetings += std::popcount(meeting);
        }
        differing += same ? 0 : 1;
    }
    // Ranges that end exactly where a box begins: entry == exit, a hit for both.
    for (const double t_max : {1.0, 2.0, 3.0, 4.5, 8.0}) {
        const std::vector<Ray> rays(RayPacket::kMaxRays, Ray{Point3(0.0), Vec3(1.0, 0.0, 0.0)});
        const std::vector<Interval> ranges(rays.size(), Interval{0.0, t_max});
        const RayPacket packet(rays, ranges, 16.0);
        ASSERT_TRUE(packet.coherent());
        float sse2_entry[8], avx2_entry[8];
        const unsigned sse2 = packet.hit_boxes(kRowAlongX, sse2_entry);
        EXPECT_EQ(sse2, packet.hit_eight_boxes_avx2(kRowAlongX, avx2_entry)) << "range (0, " << t_max << ")";
        const int last = static_cast<int>(t_max) - 1;
        EXPECT_NE(sse2 & (1u << last), 0u) << "the box the range ends on, t_max " << t_max;
        const unsigned all = (1u << RayPacket::kMaxRays) - 1u;
        EXPECT_EQ(all, packet.rays_meeting(kRowAlongX, last, all));
        EXPECT_EQ(all, packet.rays_meeting_avx2(kRowAlongX, last, all)) << "range (0, " << t_max << ")";
    }
    EXPECT_GT(packets, 15000);
    EXPECT_GT(meetings, 50000) << "rays must meet boxes often for the comparison to mean something";
    EXPECT_EQ(differing, 0) << "packets whose AVX2 answers differ from SSE2's";
}

TEST(Avx2Walk, WalksVisitTheLeavesTheSse2WalksVisit) {
    if (!cpu_has_avx2()) GTEST_SKIP() << "this CPU has no AVX2: the walk tests boxes with SSE2 only";
    // 3,000 small boxes in a cube: a tree some levels deep.
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> place(-30.0, 30.0), size(0.1, 3.0);
    std::vector<Aabb> boxes;
    for (int i = 0; i < 3000; ++i) {
        const Point3 low(place(rng), place(rng), place(rng));
        boxes.push_back(Aabb{low, low + Vec3(size(rng), size(rng), size(rng))});
    }
    const Bvh binary(boxes);
    const WideBvh avx2(binary), sse2(binary, WideBvh::BoxTest::sse2);
    ASSERT_TRUE(avx2.walks_with_avx2());
    ASSERT_FALSE(sse2.walks_with_avx2());
    using Visit = std::tuple<std::uint32_t, std::uint32_t, std::uint64_t>; // first, count, t_max or rays
    // The leaf callback shortens the range at some leaves, as a hit would.
    const auto walk = [](const WideBvh& bvh, const Ray& ray, Interval range, bool nearest_first) {
        std::vector<Visit> visits;
        const auto leaf = [&](std::uint32_t first, std::uint32_t count, double t_max) {
            visits.emplace_back(first, count, std::bit_cast<std::uint64_t>(t_max));
            return first % 5 == 0 ? 0.9 * t_max : t_max;
        };
        if (nearest_first) bvh.traverse<true>(ray, range.min, range.max, leaf);
        else bvh.traverse<false>(ray, range.min, range.max, leaf);
        return visits;
    };
    RayMaker make;
    std::size_t visits = 0;
    for (int i = 0; i < 20000; ++i) {
        const Ray ray{make.origin(), make.direction()};
        const Interval range = make.range();
        for (const bool nearest_first : {true, false}) {
            const std::vector<Visit> expected = walk(sse2, ray, range, nearest_first);
            ASSERT_EQ(walk(avx2, ray, range, nearest_first), expected) << "ray " << i << (nearest_first ? ", nearest first" : "");
            visits += expected.size();
        }
    }
    EXPECT_GT(visits, 20000u) << "the rays must visit leaves for the comparison to mean something";
    // Packets: the same leaves with the same rays, the callback retiring some rays as occlusion does.
    std::uniform_real_distribution<double> jitter(-0.02, 0.02);
    std::size_t packet_visits = 0;
    for (int p = 0; p < 3000; ++p) {
        const Point3 o0(place(rng), place(rng), place(rng));
        const Vec3 d0 = glm::normalize(Vec3(place(rng), place(rng), place(rng)));
        std::vector<Ray> rays;
        for (int i = 0; i < RayPacket::kMaxRays; ++i) rays.push_back(Ray{o0, d0 + Vec3(jitter(rng), jitter(rng), jitter(rng))});
        const std::vector<Interval> ranges(rays.size(), Interval{0.0, 80.0});
        for (const bool nearest_first : {true, false}) {
            std::vector<Visit> seen[2];
            for (int which = 0; which < 2; ++which) {
                RayPacket packet(rays, ranges, which == 0 ? sse2.extent() : avx2.extent());
                if (!packet.coherent()) break;
                const auto leaf = [&](std::uint32_t first, std::uint32_t count, unsigned hitting) {
                    seen[which].emplace_back(first, count, hitting);
                    if (first % 3 == 0) packet.retire(hitting & (hitting - 1)); // all but the lowest ray
                };
                const WideBvh& bvh = which == 0 ? sse2 : avx2;
                if (nearest_first) bvh.traverse_packet<true>(packet, leaf);
                else bvh.traverse_packet<false>(packet, leaf);
            }
            ASSERT_EQ(seen[1], seen[0]) << "packet " << p << (nearest_first ? ", nearest first" : "");
            packet_visits += seen[0].size();
        }
    }
    EXPECT_GT(packet_visits, 3000u) << "the packets must visit leaves for the comparison to mean something";
}

#endif // WHITTED_AVX2_WALK
