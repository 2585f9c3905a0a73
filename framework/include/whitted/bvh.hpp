// A bounding volume hierarchy over bounded primitives.
//
// Why: testing every primitive for every ray costs O(n); the BVH skips whole
// groups whose box the ray misses, so a ray costs about O(log n). It is built
// once with the surface area heuristic over binned centroids, and stores each
// leaf's primitives as one contiguous range, which the scene passes to the
// labs' `closest_hit()`.
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
        std::uint16_t axis = 0;  // inner: split axis, to visit the nearer child first
    };

    Bvh() = default;

    /// Builds the hierarchy over the boxes. Afterwards `order()[i]` is the index
    /// (into `boxes`) of the primitive that belongs at position i.
    explicit Bvh(std::span<const Aabb> boxes);

    std::span<const std::uint32_t> order() const { return order_; }
    std::span<const Node> nodes() const { return nodes_; }
    std::size_t bytes() const { return nodes_.size() * sizeof(Node) + order_.size() * sizeof(std::uint32_t); }

    /// Visits the leaves the ray may hit, nearest first, calling
    /// `leaf(first, count, t_max)`; the callback returns the new t_max (smaller
    /// after a hit) or a negative number to stop the traversal.
    template <class LeafFn>
    void traverse(const Ray& ray, double t_min, double t_max, LeafFn&& leaf) const;

  private:
    std::vector<Node> nodes_;
    std::vector<std::uint32_t> order_;
};

template <class LeafFn>
void Bvh::traverse(const Ray& ray, double t_min, double t_max, LeafFn&& leaf) const {
    if (nodes_.empty()) return;
    const RayBoxQuery query(ray);
    const bool negative[3] = {ray.direction.x < 0.0, ray.direction.y < 0.0, ray.direction.z < 0.0};
    std::uint32_t stack[128]; // the builder keeps the tree shallower than this
    int top = 0;
    std::uint32_t index = 0;
    if (query.entry(nodes_[0].bounds, t_min, t_max) == kInfinity) return;
    for (;;) {
        const Node& node = nodes_[index];
        if (node.count > 0) {
            t_max = leaf(node.first, node.count, t_max);
            if (t_max < 0.0) return;
        } else {
            // Children: index + 1 and node.first. Visit the one on the ray's near side first.
            std::uint32_t near = index + 1, far = node.first;
            if (negative[node.axis]) std::swap(near, far);
            const double t_near = query.entry(nodes_[near].bounds, t_min, t_max);
            const double t_far = query.entry(nodes_[far].bounds, t_min, t_max);
            if (t_near != kInfinity) {
                if (t_far != kInfinity) stack[top++] = far;
                index = near;
                continue;
            }
            if (t_far != kInfinity) {
                index = far;
                continue;
            }
        }
        // Pop the next subtree; skip it if it now lies beyond the nearest hit.
        for (;;) {
            if (top == 0) return;
            index = stack[--top];
            if (query.entry(nodes_[index].bounds, t_min, t_max) != kInfinity) break;
        }
    }
}

} // namespace whitted
