// A binary bounding volume hierarchy over bounded primitives: the builder.
//
// Why: testing every primitive for every ray costs O(n); a BVH skips whole
// groups whose box the ray misses, so a ray costs about O(log n). This tree is
// built once with the surface area heuristic over binned centroids, and keeps
// each leaf's primitives as one contiguous range of `order()`. The renderer
// queries it after WideBvh has collapsed it into eight-wide nodes.
#pragma once

#include "whitted/aabb.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace whitted {

class Bvh {
  public:
    struct Node {
        Aabb bounds;
        std::uint32_t first = 0; // leaf: first primitive; inner: index of the second child (the first follows the node)
        std::uint16_t count = 0; // number of primitives; 0 for an inner node
    };

    /// Whether a big tree may build its subtrees on other threads (the tree is the same either way).
    enum class Threads { one, several };

    Bvh() = default;

    /// Builds the hierarchy over the boxes, after which `order()[i]` is the index
    /// (into `boxes`) of the primitive at position i; `test_costs` (each primitive's
    /// test in node tests, multiples of 1/2) let the SAH split nodes of up to four
    /// primitives that cost more than four, which are leaves without them.
    explicit Bvh(std::vector<Aabb> boxes, std::vector<float> test_costs = {}, Threads threads = Threads::several);

    std::span<const std::uint32_t> order() const { return order_; }
    std::span<const Node> nodes() const { return nodes_; }

  private:
    std::vector<Node> nodes_;
    std::vector<std::uint32_t> order_;
};

} // namespace whitted
