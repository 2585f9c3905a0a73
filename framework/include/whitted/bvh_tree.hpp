// The bounding volume hierarchy of lab 10, as plain data, and the framework's
// checks of one.
//
// Why: a tree that lab 10 builds is handed to code that did not build it (the
// traversal, the grader's counters, the grading link), so it is a value with a
// simple layout: an array of nodes whose children sit side by side, and the
// primitives' order. The checks here tell a wrong tree from a slow one: a tree
// that loses a primitive or has a box too small gives wrong pictures; a tree
// that is merely poor gives the right picture slowly, and its cost says so.
// (The yardsticks the tests measure a tree and a walk with are the framework's
// own, in framework/src/tree_yardsticks.hpp: not for the labs to call.)
#pragma once

#include "whitted/aabb.hpp"
#include "whitted/interval.hpp"
#include "whitted/primitive.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace whitted {

/// One node of a BvhTree. A leaf (count > 0) holds the primitives
/// order[first], ..., order[first + count - 1]; an inner node (count == 0) has
/// two children, nodes[first] and nodes[first + 1].
struct BvhNode {
    Aabb bounds;              // contains everything below the node
    std::uint32_t first = 0;  // leaf: first position in `order`; inner node: index of the first child
    std::uint32_t count = 0;  // leaf: number of primitives (> 0); inner node: 0
};

/// A bounding volume hierarchy over n boxes: nodes[0] is the root, and `order`
/// lists the box indices 0..n-1, each once, leaf by leaf.
struct BvhTree {
    std::vector<BvhNode> nodes;
    std::vector<std::uint32_t> order;
};

/// Why `tree` is not a valid hierarchy over `boxes` ("" when it is): every box
/// in exactly one leaf, every child after its parent and inside the node array,
/// every node's bounds containing its children's and its primitives' boxes.
std::string bvh_tree_error(const BvhTree& tree, std::span<const Aabb> boxes);

/// The surface area heuristic's expected cost of a ray through the tree, in
/// units of one primitive test: sum over inner nodes of area / root area times
/// `node_cost`, plus sum over leaves of area / root area times their count.
double sah_cost(const BvhTree& tree, double node_cost = 1.0);

/// The boxes of bounded primitives, in order (an unbounded primitive throws std::invalid_argument).
std::vector<Aabb> primitive_boxes(std::span<const Primitive> primitives);

} // namespace whitted
