// The yardsticks lab 10's tests measure a tree and a walk with: the
// framework's own hierarchy over the same boxes, and the tests the framework's
// walk of a tree makes.
//
// Why not in the public headers: they are the framework's answers to lab 10
// (its builder and its walk), which the labs may not call (the grader refuses
// a lab file that does: instructor/grader/lab_fences.hpp); the tests include
// this header from the framework's sources.
#pragma once

#include "whitted/bvh_tree.hpp"

#include <cstdint>
#include <span>

namespace whitted {

/// The intersection tests of one ray query through a tree.
struct TreeQueryCost {
    std::uint64_t nodes_visited = 0;    // nodes whose box the ray was tested against
    std::uint64_t primitive_tests = 0;  // ray-primitive tests

    TreeQueryCost& operator+=(const TreeQueryCost& other) {
        nodes_visited += other.nodes_visited;
        primitive_tests += other.primitive_tests;
        return *this;
    }
};

/// The tests a closest-hit query makes through `tree` with the framework's
/// traversal (the nearer child first, boxes beyond the nearest hit skipped):
/// the measure of a tree's quality that does not depend on whose traversal runs.
/// `primitives[i]` is the primitive of `boxes[i]` the tree was built over.
TreeQueryCost closest_hit_cost(const BvhTree& tree, std::span<const Primitive> primitives, const Ray& ray,
                               Interval t_range);

/// The tests an occlusion query makes through `tree` with the framework's
/// traversal (the nearer child first, stopping at the first hit).
TreeQueryCost occluded_cost(const BvhTree& tree, std::span<const Primitive> primitives, const Ray& ray,
                            Interval t_range);

/// The framework's own hierarchy over the boxes (binned SAH, the reference
/// renderer's) in this layout: the yardstick lab 10's trees are measured against.
BvhTree framework_bvh_tree(std::span<const Aabb> boxes);

} // namespace whitted
