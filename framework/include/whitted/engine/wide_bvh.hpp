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
//
// The build targets plain x86-64 (SSE2), which tests a node's eight boxes in two
// halves. Where the CPU has AVX2 (checked once, when the tree is built), the walks
// run a copy compiled for AVX2 that tests all eight at once: the same operations
// on the same numbers, so the same leaves in the same order (issue 17: 2-4 % on
// most scenes, tetra6 level). `whitted --version` says which one this CPU runs.
#pragma once

#include "whitted/engine/bvh.hpp"
#include "whitted/engine/ray_packet.hpp"
#include "whitted/engine/wide_ray.hpp"

#include <bit>
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

    /// How the walks test a node's boxes: `best` is AVX2 where the CPU has it,
    /// else SSE2 (the same answers, bit for bit; tests compare the two).
    enum class BoxTest { best, sse2 };

    WideBvh() = default;

    /// Collapses the binary tree into eight-wide nodes (same primitive order).
    explicit WideBvh(const Bvh& binary, BoxTest box_test = BoxTest::best);

    /// True when the walks test boxes with AVX2.
    bool walks_with_avx2() const { return avx2_; }
    /// True when this CPU has AVX2, so that trees built with BoxTest::best walk with it.
    static bool cpu_has_avx2();

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
#if WHITTED_AVX2_WALK
        if (avx2_) return traverse_avx2<kNearestFirst>(ray, t_min, t_max, leaf);
#endif
        traverse_impl<kNearestFirst, false, false>(ray, t_min, t_max, leaf, nullptr);
    }

    /// traverse(), also adding to `nodes_tested` each node whose boxes it tests (the `cost` pass).
    template <bool kNearestFirst = true, class LeafFn>
    void traverse_counting(const Ray& ray, double t_min, double t_max, LeafFn&& leaf, std::uint64_t& nodes_tested) const {
        traverse_impl<kNearestFirst, true, false>(ray, t_min, t_max, leaf, &nodes_tested);
    }

    /// Walks the tree with a coherent packet: visits each leaf some of its active
    /// rays may meet (nearer boxes first), calling `leaf(first, count, rays)` with
    /// those rays' bits; the callback shrinks or retires rays through `packet`.
    template <bool kNearestFirst = true, class LeafFn>
    void traverse_packet(RayPacket& packet, LeafFn&& leaf) const {
#if WHITTED_AVX2_WALK
        if (avx2_) return traverse_packet_avx2<kNearestFirst>(packet, leaf);
#endif
        traverse_packet_impl<kNearestFirst, false>(packet, leaf);
    }

  private:
    // The walk; kAvx2: the node test is WideRay::hit_eight_boxes_avx2, and the
    // caller must be compiled for AVX2 (traverse_avx2), into which it is inlined.
    template <bool kNearestFirst, bool kCount, bool kAvx2, class LeafFn>
    [[gnu::always_inline]] inline void traverse_impl(const Ray& ray, double t_min, double t_max, LeafFn& leaf,
                                              std::uint64_t* nodes_tested) const;

    // A node's box test by `tester`, a WideRay or a RayPacket: in AVX2 when kAvx2.
    template <bool kAvx2, class Tester>
    [[gnu::always_inline]] static unsigned test_node(const Tester& tester, const Node& node, float (&t_entry)[kWidth]) {
#if WHITTED_AVX2_WALK
        if constexpr (kAvx2) return tester.hit_eight_boxes_avx2(node.bounds, t_entry);
#endif
        return tester.hit_boxes(node.bounds, t_entry);
    }

    // The packet's walk; kAvx2 as for traverse_impl.
    template <bool kNearestFirst, bool kAvx2, class LeafFn>
    [[gnu::always_inline]] inline void traverse_packet_impl(RayPacket& packet, LeafFn& leaf) const;

#if WHITTED_AVX2_WALK
    // The walks compiled for AVX2, the leaf callback with them (only where the CPU has AVX2).
    template <bool kNearestFirst, class LeafFn>
    [[gnu::target("avx2"), gnu::noinline]] void traverse_avx2(const Ray& ray, double t_min, double t_max, LeafFn& leaf) const {
        traverse_impl<kNearestFirst, false, true>(ray, t_min, t_max, leaf, nullptr);
    }
    template <bool kNearestFirst, class LeafFn>
    [[gnu::target("avx2"), gnu::noinline]] void traverse_packet_avx2(RayPacket& packet, LeafFn& leaf) const {
        traverse_packet_impl<kNearestFirst, true>(packet, leaf);
    }
#endif

    std::vector<Node> nodes_;
    std::uint32_t root_count_ = 0; // primitives when the root is a leaf (nodes_ empty)
    double extent_ = 0.0;
    bool avx2_ = false;
};

template <bool kNearestFirst, bool kCount, bool kAvx2, class LeafFn>
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
            unsigned mask = test_node<kAvx2>(wide, node, t_entry);
            if (mask == 0) goto pop;
            int first = std::countr_zero(mask);
            mask &= mask - 1;
            if (mask == 0) {
                current = node.child[first];
                continue;
            }
            // Push every hit child, then bubble the nearer ones towards the top.
            const int base = top;
            stack[top++] = {node.child[first], t_entry[first]};
            for (; mask != 0; mask &= mask - 1) {
                const int i = std::countr_zero(mask);
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

template <bool kNearestFirst, bool kAvx2, class LeafFn>
void WideBvh::traverse_packet_impl(RayPacket& packet, LeafFn& leaf) const {
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
        unsigned mask = test_node<kAvx2>(packet, node, t_entry);
        const int base = top;
        for (; mask != 0; mask &= mask - 1) {
            const int i = std::countr_zero(mask);
            unsigned rays;
#if WHITTED_AVX2_WALK
            if constexpr (kAvx2) rays = packet.rays_meeting_avx2(node.bounds, i, current_rays);
            else
#endif
                rays = packet.rays_meeting(node.bounds, i, current_rays);
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
