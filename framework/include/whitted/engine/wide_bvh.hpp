// The BVH the renderer queries: eight children per node, boxes in float.
//
// Why: box tests are most of a ray's cost (the binary double BVH spent over half
// of all instructions there). A node holding its eight children's boxes side by
// side lets two 4-wide float tests decide them all, and float boxes make a node
// 256 bytes, four cache lines. A ray's walk waits on each node it fetches, so
// fewer, wider nodes beat four-wide ones (issue 17: the sphereflakes 6-7 % and a
// triangle soup 13 % faster, teapot6 2 %, mount6 and tetra6 level). Float must
// never lose a hit the double primitive tests would find, so every box test is
// conservative: boxes are rounded outward, and each ray widens its slabs by a
// margin larger than every rounding error of the test (see WideRay). The hits
// themselves are still found by the primitives' double-precision tests, so
// images do not change.
//
// The tree is collapsed from the binary SAH tree of `Bvh` (whose primitive
// order it keeps): each node adopts the children of its largest inner children
// until it has eight.
#pragma once

#include "whitted/engine/bvh.hpp"
#include "whitted/engine/ray_packet.hpp"
#include "whitted/engine/wide_ray.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace whitted {

class WideBvh {
  public:
    static constexpr int kWidth = 8;

    struct alignas(64) Node {
        float bounds[6][kWidth];         // min x, max x, min y, max y, min z, max z of each child
        std::uint64_t child[kWidth];     // inner child: node index; leaf: leaf_ref(first, count)
    };

    /// A leaf child's reference: a flag bit, its primitive count and its first primitive.
    static constexpr std::uint64_t kLeafFlag = std::uint64_t{1} << 63;
    static constexpr std::uint64_t leaf_ref(std::uint32_t first, std::uint32_t count) {
        return kLeafFlag | std::uint64_t{count} << 32 | first;
    }

    static_assert(sizeof(Node) == 256, "a node is four cache lines");

    WideBvh() = default;

    /// Collapses the binary tree into eight-wide nodes (same primitive order).
    explicit WideBvh(const Bvh& binary);

    std::span<const Node> nodes() const { return nodes_; }
    /// Bytes of the nodes.
    std::size_t bytes() const { return nodes_.size() * sizeof(Node); }
    /// The largest absolute coordinate of any box (WideRay's margin needs the scene's size).
    double extent() const { return extent_; }

    /// Visits the leaves whose boxes the ray meets within (t_min, t_max), nearer
    /// boxes first, calling `leaf(first, count, t_max)`; the callback returns the
    /// new t_max (smaller after a hit) or a negative number to stop.
    template <bool kNearestFirst = true, class LeafFn>
    void traverse(const Ray& ray, double t_min, double t_max, LeafFn&& leaf) const {
        traverse_impl<kNearestFirst, false>(ray, t_min, t_max, leaf, nullptr);
    }

    /// traverse(), also adding to `nodes_tested` each node whose boxes it tests (the `cost` pass).
    template <bool kNearestFirst = true, class LeafFn>
    void traverse_counting(const Ray& ray, double t_min, double t_max, LeafFn&& leaf, std::uint64_t& nodes_tested) const {
        traverse_impl<kNearestFirst, true>(ray, t_min, t_max, leaf, &nodes_tested);
    }

    /// Walks the tree with a coherent packet: visits each leaf some of its active
    /// rays may meet (nearer boxes first), calling `leaf(first, count, rays)` with
    /// those rays' bits; the callback shrinks or retires rays through `packet`.
    template <bool kNearestFirst = true, class LeafFn>
    void traverse_packet(RayPacket& packet, LeafFn&& leaf) const;

  private:
    template <bool kNearestFirst, bool kCount, class LeafFn>
    void traverse_impl(const Ray& ray, double t_min, double t_max, LeafFn& leaf, std::uint64_t* nodes_tested) const;

    std::vector<Node> nodes_;
    std::uint32_t root_count_ = 0; // primitives when the root is a leaf (nodes_ empty)
    double extent_ = 0.0;
};

template <bool kNearestFirst, bool kCount, class LeafFn>
void WideBvh::traverse_impl(const Ray& ray, double t_min, double t_max, LeafFn& leaf, std::uint64_t* nodes_tested) const {
    if (nodes_.empty()) {
        if (root_count_ > 0) leaf(0u, root_count_, t_max);
        return;
    }
    const WideRay wide(ray, extent_, t_min, t_max);
    struct Entry {
        std::uint64_t ref;
        float t_entry;
    };
    Entry stack[1024]; // <= 7 pending siblings per level; the builder's trees have < 100 levels
    int top = 0;
    std::uint64_t current = 0;
    for (;;) {
        // Descend through inner nodes, nearest child first, pushing the others.
        while (!(current & kLeafFlag)) {
            const Node& node = nodes_[current];
            if constexpr (kCount) ++*nodes_tested;
            float t_entry[kWidth];
            unsigned mask = wide.hit_boxes(node.bounds, t_entry);
            if (mask == 0) goto pop;
            int first = __builtin_ctz(mask);
            mask &= mask - 1;
            if (mask == 0) {
                current = node.child[first];
                continue;
            }
            // Push every hit child, then bubble the nearer ones towards the top.
            const int base = top;
            stack[top++] = {node.child[first], t_entry[first]};
            for (; mask != 0; mask &= mask - 1) {
                const int i = __builtin_ctz(mask);
                stack[top] = {node.child[i], t_entry[i]};
                if constexpr (kNearestFirst)
                    for (int k = top; k > base && stack[k].t_entry > stack[k - 1].t_entry; --k) std::swap(stack[k], stack[k - 1]);
                ++top;
            }
            current = stack[--top].ref;
        }
        {
            const double new_t_max = leaf(static_cast<std::uint32_t>(current), static_cast<std::uint32_t>(current >> 32) & 0x7fffffffu, t_max);
            if (new_t_max < 0.0) return;
            if (new_t_max < t_max) {
                t_max = new_t_max;
                wide.shrink(t_max);
            }
        }
    pop:
        for (;;) {
            if (top == 0) return;
            const Entry& entry = stack[--top];
            if (entry.t_entry <= wide.t_max()) {
                current = entry.ref;
                break;
            }
        }
    }
}

template <bool kNearestFirst, class LeafFn>
void WideBvh::traverse_packet(RayPacket& packet, LeafFn&& leaf) const {
    if (nodes_.empty()) {
        if (root_count_ > 0 && packet.active() != 0) leaf(0u, root_count_, packet.active());
        return;
    }
    // A child goes on the stack with the rays that may meet it: the packet's
    // test rules out boxes for all its rays at once, each ray's own test then
    // keeps only its rays, so a packet whose rays part ways costs no more box
    // tests than its rays alone.
    struct Entry {
        std::uint64_t ref;
        float t_entry;
        unsigned rays;
    };
    Entry stack[1024]; // <= 8 children per level; the builder's trees have < 100 levels
    int top = 0;
    std::uint32_t current = 0;
    unsigned current_rays = packet.active();
    for (;;) {
        const Node& node = nodes_[current];
        float t_entry[kWidth];
        unsigned mask = packet.hit_boxes(node.bounds, t_entry);
        const int base = top;
        for (; mask != 0; mask &= mask - 1) {
            const int i = __builtin_ctz(mask);
            const unsigned rays = packet.rays_meeting(node.bounds, i, current_rays);
            if (rays == 0) continue;
            stack[top] = {node.child[i], t_entry[i], rays};
            if constexpr (kNearestFirst)
                for (int k = top; k > base && stack[k].t_entry > stack[k - 1].t_entry; --k) std::swap(stack[k], stack[k - 1]);
            ++top;
        }
        // The nearest child next: an inner node is tested, a leaf searched by its rays.
        for (;;) {
            if (top == 0) return;
            const Entry entry = stack[--top];
            const unsigned rays = entry.rays & packet.active();
            if (rays == 0 || entry.t_entry > packet.t_max()) continue;
            if (!(entry.ref & kLeafFlag)) {
                current = static_cast<std::uint32_t>(entry.ref);
                current_rays = rays;
                break;
            }
            leaf(static_cast<std::uint32_t>(entry.ref), static_cast<std::uint32_t>(entry.ref >> 32) & 0x7fffffffu, rays);
            if (packet.active() == 0) return;
        }
    }
}

} // namespace whitted
