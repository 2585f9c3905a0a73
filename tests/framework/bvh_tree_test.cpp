// The framework's side of lab 10 (whitted/bvh_tree.hpp): the checks that tell a
// tree that is not a hierarchy from one that is, the SAH cost, the counting
// walk the quality tests use, the framework's own tree in lab 10's layout, and
// a scene that tests every primitive (accel none).
#include "whitted/bvh_tree.hpp"
#include "whitted/scene.hpp"
#include "tree_yardsticks.hpp"

#include <gtest/gtest.h>

using namespace whitted;

namespace {

// Two unit boxes side by side along x, [0, 1] and [2, 3] (y, z in [0, 1]).
const std::vector<Aabb> kTwo{Aabb{Point3(0.0), Point3(1.0)}, Aabb{Point3(2.0, 0.0, 0.0), Point3(3.0, 1.0, 1.0)}};
const Aabb kBoth{Point3(0.0), Point3(3.0, 1.0, 1.0)};

/// The right tree over kTwo: a root and two leaves of one box each.
BvhTree two_leaves() { return BvhTree{{BvhNode{kBoth, 1, 0}, BvhNode{kTwo[0], 0, 1}, BvhNode{kTwo[1], 1, 1}}, {0, 1}}; }

} // namespace

TEST(BvhTreeError, ARightTreeHasNoError) {
    EXPECT_EQ(bvh_tree_error(two_leaves(), kTwo), "");
    EXPECT_EQ(bvh_tree_error(BvhTree{{BvhNode{kBoth, 0, 2}}, {1, 0}}, kTwo), "") << "one leaf holding both";
    EXPECT_EQ(bvh_tree_error(BvhTree{}, {}), "") << "no boxes, no nodes";
}

TEST(BvhTreeError, EachWayOfBeingWrongIsNamed) {
    BvhTree tree = two_leaves();
    tree.order = {0, 0};
    EXPECT_EQ(bvh_tree_error(tree, kTwo), "primitive 0 is listed twice in order");
    tree = two_leaves();
    tree.order = {0};
    EXPECT_EQ(bvh_tree_error(tree, kTwo), "order holds 1 indices for 2 primitives");
    tree = two_leaves();
    tree.nodes[1].bounds = kTwo[1];
    EXPECT_EQ(bvh_tree_error(tree, kTwo), "node 1's bounds do not contain its primitive 0");
    tree = two_leaves();
    tree.nodes[0].bounds = kTwo[0];
    EXPECT_EQ(bvh_tree_error(tree, kTwo), "node 0's bounds do not contain its child 2's");
    tree = two_leaves();
    tree.nodes[2].first = 0; // both leaves hold order[0] (their bounds hold both boxes, as the root's do)
    tree.nodes[1].bounds = tree.nodes[2].bounds = kBoth;
    EXPECT_EQ(bvh_tree_error(tree, kTwo), "order[0] is in two leaves");
    tree = two_leaves();
    tree.nodes[0].first = 0; // its own child: a cycle
    EXPECT_NE(bvh_tree_error(tree, kTwo).find("children come after their parent"), std::string::npos);
    tree = two_leaves();
    tree.nodes[2].count = 5;
    EXPECT_EQ(bvh_tree_error(tree, kTwo), "node 2 is a leaf past the end of order");
    tree = two_leaves();
    tree.nodes.push_back(BvhNode{kBoth, 0, 1});
    EXPECT_EQ(bvh_tree_error(tree, kTwo), "node 3 is not below the root");
    tree = two_leaves();
    tree.nodes[0].bounds.max.x = std::nan("");
    EXPECT_NE(bvh_tree_error(tree, kTwo), "") << "a NaN bound contains nothing";
    // No boxes and a root anyway (a leaf of count 0 is an inner node): the message says what the answer is,
    // not that the root's children are missing.
    EXPECT_EQ(bvh_tree_error(BvhTree{{BvhNode{Aabb{}, 0, 0}}, {}}, {}),
              "1 node for no primitives: a tree over no boxes has no nodes (and an empty order)");
}

TEST(SahCost, IsTheAreaWeightedCountOfTests) {
    // Root half area: 3x1 + 1x1 + 1x3 = 7; each leaf: 3 (a unit cube). Cost = 1 (root, node cost 1)
    // + 2 x (3/7 x 1 primitive) = 1 + 6/7. One leaf of both: 7/7 x 2 = 2.
    EXPECT_NEAR(sah_cost(two_leaves()), 1.0 + 6.0 / 7.0, 1e-15);
    EXPECT_NEAR(sah_cost(BvhTree{{BvhNode{kBoth, 0, 2}}, {0, 1}}), 2.0, 1e-15);
    EXPECT_NEAR(sah_cost(two_leaves(), 0.5), 0.5 + 6.0 / 7.0, 1e-15);
}

TEST(ClosestHitCost, CountsTheNodesAndPrimitivesTheWalkTests) {
    // Spheres in the two boxes; a ray along x at y = z = 0.5 from x = -5: root, both leaves,
    // the nearer sphere first; its hit (t = 5) ends the walk before the farther leaf's sphere is tested.
    const std::vector<Primitive> spheres{{Sphere{Point3(0.5), 0.5}, 0}, {Sphere{Point3(2.5, 0.5, 0.5), 0.5}, 0}};
    const Ray ray{Point3(-5.0, 0.5, 0.5), Vec3(1.0, 0.0, 0.0)};
    const TreeQueryCost cost = closest_hit_cost(two_leaves(), spheres, ray, Interval{});
    EXPECT_EQ(cost.primitive_tests, 1u);
    EXPECT_EQ(cost.nodes_visited, 3u) << "the root, the near leaf, then the far leaf, whose box lies beyond the hit";
    // A ray that misses the root box: one node, no primitive.
    const TreeQueryCost miss = closest_hit_cost(two_leaves(), spheres, Ray{Point3(-5.0, 5.0, 0.5), Vec3(1.0, 0.0, 0.0)}, Interval{});
    EXPECT_EQ(miss.nodes_visited, 1u);
    EXPECT_EQ(miss.primitive_tests, 0u);
}

TEST(FrameworkBvhTree, IsAHierarchyInLab10sLayout) {
    std::vector<Aabb> boxes;
    for (int i = 0; i < 500; ++i) {
        const Point3 p(std::sin(i * 1.3) * 10.0, std::cos(i * 0.7) * 10.0, (i % 17) * 0.5);
        boxes.push_back(Aabb{p, p + Vec3(0.3)});
    }
    const BvhTree tree = framework_bvh_tree(boxes);
    EXPECT_EQ(bvh_tree_error(tree, boxes), "");
    EXPECT_GT(tree.nodes.size(), 100u) << "500 boxes in leaves of at most a few";
}

TEST(AccelerationNone, TestsEveryPrimitiveAndFindsTheSameHits) {
    SceneData data;
    data.materials = {Material{}};
    for (int i = 0; i < 50; ++i)
        data.primitives.push_back({Sphere{Point3(std::sin(i) * 5.0, std::cos(i * 2.0) * 5.0, i * 0.2 - 5.0), 0.4}, 0});
    data.primitives.push_back({Plane{Point3(0.0, -6.0, 0.0), Vec3(0.0, 1.0, 0.0)}, 0});
    SceneData brute = data;
    brute.acceleration = Acceleration::none;
    const Scene with_bvh(data), without(brute);
    EXPECT_EQ(without.acceleration(), Acceleration::none);
    for (int i = 0; i < 200; ++i) {
        const Ray ray{Point3(0.0, 0.0, 20.0), glm::normalize(Vec3(std::sin(i * 0.37) * 0.4, std::cos(i * 0.61) * 0.4, -1.0))};
        const std::optional<Hit> a = with_bvh.closest_hit(ray), b = without.closest_hit(ray);
        ASSERT_EQ(a.has_value(), b.has_value()) << "ray " << i;
        if (a) { EXPECT_EQ(a->t, b->t); }
        EXPECT_EQ(with_bvh.occluded(ray, Interval{0.0, 15.0}), without.occluded(ray, Interval{0.0, 15.0}));
    }
}
