// The BVH must find exactly what testing every primitive finds.
#include "whitted/engine/bvh.hpp"
#include "whitted/labs.hpp"
#include "whitted/scene.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>

using namespace whitted;

namespace {

// A cloud of random spheres, triangles and boxes, plus one infinite plane.
SceneData random_scene(unsigned seed, int count) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> position(-10.0, 10.0), size(0.05, 1.5);
    SceneData data;
    data.materials.push_back(Material{});
    for (int i = 0; i < count; ++i) {
        const Point3 c(position(rng), position(rng), position(rng));
        switch (i % 3) {
        case 0: data.primitives.push_back({Sphere{c, size(rng)}}); break;
        case 1:
            data.primitives.push_back({Triangle{c, c + Vec3(size(rng), 0.0, size(rng)), c + Vec3(0.0, size(rng), size(rng))}});
            break;
        default: data.primitives.push_back({Box{c, c + Vec3(size(rng), size(rng), size(rng))}}); break;
        }
    }
    data.primitives.push_back({Plane{Point3(0.0, -12.0, 0.0), Vec3(0.0, 1.0, 0.0)}});
    return data;
}

Ray random_ray(std::mt19937& rng) {
    std::uniform_real_distribution<double> position(-15.0, 15.0), unit(-1.0, 1.0);
    Vec3 d;
    do d = Vec3(unit(rng), unit(rng), unit(rng));
    while (glm::length(d) < 0.1);
    return Ray{Point3(position(rng), position(rng), position(rng)), glm::normalize(d)};
}

} // namespace

TEST(Bvh, ClosestHitAgreesWithTestingEveryPrimitive) {
    const Scene scene(random_scene(1, 3000));
    std::mt19937 rng(7);
    int hits = 0;
    for (int i = 0; i < 4000; ++i) {
        const Ray ray = random_ray(rng);
        const auto expected = closest_hit(ray, scene.primitives(), Interval{});
        const auto found = scene.closest_hit(ray);
        ASSERT_EQ(expected.has_value(), found.has_value()) << "ray " << i;
        if (expected) {
            ++hits;
            EXPECT_EQ(expected->t, found->t) << "ray " << i;
            EXPECT_EQ(expected->primitive, found->primitive) << "ray " << i;
        }
    }
    EXPECT_GT(hits, 1000); // the test means something only if many rays hit
}

TEST(Bvh, OcclusionAgreesWithTestingEveryPrimitive) {
    const Scene scene(random_scene(2, 3000));
    std::mt19937 rng(11);
    int blocked = 0;
    for (int i = 0; i < 4000; ++i) {
        const Ray ray = random_ray(rng);
        const Interval range{0.0, 5.0};
        const bool expected = closest_hit(ray, scene.primitives(), range).has_value();
        ASSERT_EQ(expected, scene.occluded(ray, range)) << "ray " << i;
        blocked += expected;
    }
    EXPECT_GT(blocked, 200);
    EXPECT_LT(blocked, 3800);
}

TEST(Bvh, ManyIdenticalPrimitivesStillBuildAndAnswer) {
    // Coincident centroids defeat every spatial split; the build must still terminate.
    SceneData data;
    data.materials.push_back(Material{});
    for (int i = 0; i < 100000; ++i) data.primitives.push_back({Sphere{Point3(0.0), 1.0}});
    const Scene scene(std::move(data));
    const auto hit = scene.closest_hit(Ray{Point3(0.0, 0.0, 5.0), Vec3(0.0, 0.0, -1.0)});
    ASSERT_TRUE(hit.has_value());
    EXPECT_DOUBLE_EQ(hit->t, 4.0);
}

TEST(Bvh, EmptySceneHitsNothing) {
    SceneData data;
    const Scene scene(std::move(data));
    EXPECT_FALSE(scene.closest_hit(Ray{Point3(0.0), Vec3(0.0, 0.0, -1.0)}).has_value());
    EXPECT_FALSE(scene.occluded(Ray{Point3(0.0), Vec3(0.0, 0.0, -1.0)}, Interval{0.0, 10.0}));
}

// Big trees build their two halves on other threads, into nodes of their own
// that are then appended: the tree must be the one a single thread builds,
// node for node, or a picture could depend on the machine.
TEST(Bvh, SeveralThreadsBuildTheTreeOneThreadBuilds) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> position(-100.0, 100.0), size(0.01, 2.0);
    std::vector<Aabb> boxes(300'000); // above the size that builds on several threads, two levels down
    for (Aabb& box : boxes) {
        box.min = Point3(position(rng), position(rng), position(rng));
        box.max = box.min + Vec3(size(rng), size(rng), size(rng));
    }
    // Without test costs (lab 10's yardstick tree) and with the renderer's (a third of them triangles).
    std::vector<float> mixed(boxes.size(), 1.0f);
    for (std::size_t i = 0; i < mixed.size(); i += 3) mixed[i] = 1.5f;
    for (const std::vector<float>& costs : {std::vector<float>{}, mixed}) {
        const Bvh one(boxes, costs, Bvh::Threads::one), several(boxes, costs, Bvh::Threads::several);
        ASSERT_EQ(one.order().size(), several.order().size());
        EXPECT_TRUE(std::equal(one.order().begin(), one.order().end(), several.order().begin()));
        ASSERT_EQ(one.nodes().size(), several.nodes().size());
        for (std::size_t i = 0; i < one.nodes().size(); ++i) {
            const Bvh::Node &a = one.nodes()[i], &b = several.nodes()[i];
            ASSERT_TRUE(a.first == b.first && a.count == b.count && a.bounds.min == b.bounds.min &&
                        a.bounds.max == b.bounds.max)
                << "node " << i << (costs.empty() ? "" : " (with test costs)");
        }
        EXPECT_GT(one.nodes().size(), boxes.size() / 4); // a real tree, not one leaf
    }
}

namespace {

// A unit box at (x, 0, 0).
Aabb box_at(double x) { return Aabb{Point3(x, 0.0, 0.0), Point3(x + 1.0, 1.0, 1.0)}; }

std::uint32_t largest_leaf(const Bvh& bvh) {
    std::uint32_t largest = 0;
    for (const Bvh::Node& node : bvh.nodes()) largest = std::max<std::uint32_t>(largest, node.count);
    return largest;
}

} // namespace

// Three unit boxes 10 apart, triangles (1.5 tests each: 4.5, more than the four a
// small node may cost before the SAH weighs it). Root box: 21 x 1 x 1, half area
// 21 + 1 + 21 = 43. A leaf costs 43 x 4.5 = 193.5 tests. The best split (one box |
// two: half areas 3 and 11 + 1 + 11 = 23) costs the node test plus each side's area
// times its tests: 43 + 3 x 1.5 + 23 x 3 = 116.5 < 193.5, so without the rays' set-up
// (4 node tests, 4 x 43 = 172 more) the SAH would split; with it the split costs
// 288.5 and the root stays one leaf, so rays walk no tree.
TEST(Bvh, WithTestCostsAFewShapesAreOneLeaf) {
    const Bvh bvh({box_at(0.0), box_at(10.0), box_at(20.0)}, {1.5f, 1.5f, 1.5f});
    ASSERT_EQ(bvh.nodes().size(), 1u);
    EXPECT_EQ(bvh.nodes()[0].count, 3u);
}

// Five unit boxes 2 apart (x in [2k, 2k + 1]). Root: 9 x 1 x 1, half area 19. With
// every test costing c, a leaf costs 19 x 5c = 95c; the split {0, 1} | {2, 3, 4}
// (half areas 7 and 11) costs the node test and the rays' set-up, 5 x 19 = 95, plus
// 7 x 2c + 11 x 3c = 47c. Spheres (c = 1): every split costs over 95, the leaf 95, so
// one leaf. Cones (c = 3): 236 < 285, so split: the costs, not the counts, decide.
TEST(Bvh, TestCostsDecideBetweenLeafAndSplit) {
    std::vector<Aabb> boxes;
    for (int k = 0; k < 5; ++k) boxes.push_back(box_at(2.0 * k));
    EXPECT_EQ(Bvh(boxes, std::vector<float>(5, 1.0f)).nodes().size(), 1u);
    EXPECT_GT(Bvh(boxes, std::vector<float>(5, 3.0f)).nodes().size(), 1u);
}

// Two clusters, 1000 apart, of four unit boxes 10 apart. Within a cluster (31 x 1 x 1,
// half area 63) a leaf of four triangles costs 63 x 6 = 378 tests; splitting it two and
// two costs 63 + 2 x (23 x 3) = 201: with test costs a cluster of triangles is split. Four
// spheres (4 tests, the small-leaf limit) stay one leaf, as every node of four does without costs.
TEST(Bvh, WithTestCostsTrianglesFarApartGetSmallerLeaves) {
    std::vector<Aabb> boxes;
    for (const double cluster : {0.0, 1000.0})
        for (int i = 0; i < 4; ++i) boxes.push_back(box_at(cluster + 10.0 * i));
    EXPECT_EQ(largest_leaf(Bvh(boxes)), 4u);
    EXPECT_EQ(largest_leaf(Bvh(boxes, std::vector<float>(8, 1.0f))), 4u);
    EXPECT_LT(largest_leaf(Bvh(boxes, std::vector<float>(8, 1.5f))), 4u);
}

TEST(Bvh, TestCostsAreOnePerBoxAndHalves) {
    EXPECT_THROW(Bvh({box_at(0.0), box_at(2.0)}, {1.0f}), std::invalid_argument);
    EXPECT_THROW(Bvh({box_at(0.0), box_at(2.0)}, {1.0f, 1.25f}), std::invalid_argument);
    EXPECT_THROW(Bvh({box_at(0.0), box_at(2.0)}, {1.0f, -1.0f}), std::invalid_argument);
    EXPECT_THROW(Bvh({box_at(0.0), box_at(2.0)}, {1.0f, std::numeric_limits<float>::quiet_NaN()}), std::invalid_argument);
}

// 5,000 points spread over less than 2^-1040 along x: the SAH's bins cannot tell
// them apart (16 over a subnormal spread overflows), so every node splits at the
// median centre, which moves the primitives around. Each leaf's box must be the
// box of the very points its primitives are: the boxes move with `order` (with
// test costs, the costs too).
TEST(Bvh, MedianSplitsKeepEachBoxWithItsPrimitive) {
    std::vector<Aabb> boxes;
    for (int i = 0; i < 5'000; ++i) {
        const Point3 p(std::ldexp(static_cast<double>((i * 7919) % 5'000), -1060), 0.0, 0.0); // shuffled
        boxes.push_back(Aabb{p, p});
    }
    for (const std::vector<float>& costs : {std::vector<float>{}, std::vector<float>(boxes.size(), 1.5f)}) {
        const Bvh bvh(boxes, costs);
        ASSERT_GT(bvh.nodes().size(), 1000u);
        for (const Bvh::Node& node : bvh.nodes()) {
            if (node.count == 0) continue;
            Aabb held;
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i) held.expand(boxes[bvh.order()[i]]);
            ASSERT_TRUE(held.min == node.bounds.min && held.max == node.bounds.max)
                << "leaf at " << node.first << (costs.empty() ? "" : " with test costs");
        }
    }
}
