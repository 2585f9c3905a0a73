// Collapsing the binary SAH tree into eight-wide nodes with float boxes.
#include "whitted/engine/wide_bvh.hpp"

#include "prefetch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace whitted {
namespace {

constexpr float kInfinityF = std::numeric_limits<float>::infinity();

// A box's minimum and maximum in float, moved outwards by 2^-20 of their size
// (WideRay's margin takes care of the ray's share of the rounding) and then
// rounded outwards: never upwards for the minimum, never downwards for the maximum.
float float_below(double x) {
    x -= 0x1p-20 * std::abs(x);
    const float f = static_cast<float>(x);
    return static_cast<double>(f) > x ? std::nextafter(f, -kInfinityF) : f;
}
float float_above(double x) {
    x += 0x1p-20 * std::abs(x);
    const float f = static_cast<float>(x);
    return static_cast<double>(f) < x ? std::nextafter(f, kInfinityF) : f;
}

struct Collapser {
    std::span<const Bvh::Node> binary;
    std::vector<WideBvh::Node>& nodes;

    std::uint32_t left(std::uint32_t b) const { return b + 1; }
    std::uint32_t right(std::uint32_t b) const { return binary[b].first; }
    bool is_leaf(std::uint32_t b) const { return binary[b].count > 0; }
    // The half surface area of inner node b, as the choice of which node to open weighs it; -1 for a leaf.
    // An inner node's second child, which may be opened next, is asked for from memory now (in a big
    // tree it lies far from its parent, and each wait for it stalls the collapse).
    double surface(std::uint32_t b) const {
        if (is_leaf(b)) return -1.0;
        detail::prefetch(&binary[right(b)]);
        return binary[b].bounds.half_area();
    }

    // Makes the wide node for binary inner node b and returns its index.
    std::uint32_t collapse(std::uint32_t b) {
        std::uint32_t children[WideBvh::kWidth] = {left(b), right(b)};
        // Each child's surface, or -1 for a leaf (never opened): found once per child.
        double areas[WideBvh::kWidth] = {surface(children[0]), surface(children[1])};
        int count = 2;
        // Open the inner child with the largest surface until there are eight.
        while (count < WideBvh::kWidth) {
            int largest = -1;
            for (int i = 0; i < count; ++i)
                if (areas[i] >= 0.0 && (largest < 0 || areas[i] > areas[largest])) largest = i;
            if (largest < 0) break;
            const std::uint32_t opened = children[largest];
            children[largest] = left(opened);
            areas[largest] = surface(children[largest]);
            children[count] = right(opened);
            areas[count++] = surface(right(opened));
        }
        const auto index = static_cast<std::uint32_t>(nodes.size());
        nodes.emplace_back();
        for (int i = 0; i < WideBvh::kWidth; ++i) {
            WideBvh::Node& node = nodes[index];
            if (i >= count) {
                // An empty slot: an inverted infinite box, which no ray meets in either direction.
                for (int axis = 0; axis < 3; ++axis) {
                    node.bounds[2 * axis][i] = kInfinityF;
                    node.bounds[2 * axis + 1][i] = -kInfinityF;
                }
                node.child[i] = WideBvh::leaf_ref(0, 0);
                continue;
            }
            const Bvh::Node& child = binary[children[i]];
            for (int axis = 0; axis < 3; ++axis) {
                node.bounds[2 * axis][i] = float_below(child.bounds.min[axis]);
                node.bounds[2 * axis + 1][i] = float_above(child.bounds.max[axis]);
            }
            if (child.count > 0) {
                node.child[i] = WideBvh::leaf_ref(child.first, child.count);
            } else {
                const std::uint32_t grandchild = collapse(children[i]); // may reallocate `nodes`
                nodes[index].child[i] = grandchild;
            }
        }
        return index;
    }
};

} // namespace

bool WideBvh::cpu_has_avx2() {
#if WHITTED_AVX2_WALK
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}

WideBvh::WideBvh(const Bvh& binary, BoxTest box_test) : avx2_(box_test == BoxTest::best && cpu_has_avx2()) {
    const std::span<const Bvh::Node> tree = binary.nodes();
    if (tree.empty()) return;
    const Aabb& root = tree[0].bounds;
    for (int axis = 0; axis < 3; ++axis)
        extent_ = std::max({extent_, std::abs(root.min[axis]), std::abs(root.max[axis])});
    if (tree[0].count > 0) {
        root_count_ = tree[0].count;
        return;
    }
    // Each wide node takes at least one inner node of the binary tree, which has (size - 1) / 2.
    nodes_.reserve(tree.size() / 2); // never grown, so never copied; the room left unused is never touched
    Collapser{tree, nodes_}.collapse(0);
}

} // namespace whitted
