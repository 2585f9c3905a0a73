// Binned surface-area-heuristic BVH construction.
#include "whitted/engine/bvh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace whitted {
namespace {

constexpr int kBins = 16;
constexpr std::uint32_t kMaxLeafSize = 4;
constexpr int kMaxSahDepth = 48; // deeper than this, split at the median so the tree stays shallow
constexpr double kTraversalCost = 1.0; // relative to one primitive test
constexpr std::uint32_t kMaxLeafCount = 65535; // Node::count is 16 bits
constexpr std::uint32_t kLeaf = 0;             // sah_split: make a leaf
constexpr std::uint32_t kMedian = ~0u;         // sah_split: split at the median instead

struct Builder {
    std::span<const Aabb> boxes;
    std::vector<Point3> centers;
    std::vector<std::uint32_t>& order;
    std::vector<Bvh::Node>& nodes;

    // Builds the subtree over order[first, first + count) at nodes[index].
    void build(std::uint32_t index, std::uint32_t first, std::uint32_t count, int depth) {
        Aabb bounds, centroid_bounds;
        for (std::uint32_t i = first; i < first + count; ++i) {
            bounds.expand(boxes[order[i]]);
            centroid_bounds.expand(centers[order[i]]);
        }
        nodes[index].bounds = bounds;
        if (count <= kMaxLeafSize) return make_leaf(index, first, count);

        const Vec3 extent = centroid_bounds.max - centroid_bounds.min;
        int axis = 0;
        if (extent.y > extent[axis]) axis = 1;
        if (extent.z > extent[axis]) axis = 2;
        std::uint32_t mid = kMedian;
        if (extent[axis] <= 0.0) {
            // All centroids coincide: no spatial split helps.
            if (count <= kMaxLeafCount) return make_leaf(index, first, count);
        } else if (depth < kMaxSahDepth) {
            mid = sah_split(first, count, axis, centroid_bounds, bounds);
            if (mid == kLeaf) return make_leaf(index, first, count);
        }
        if (mid == kMedian) {
            auto begin = order.begin() + first;
            std::nth_element(begin, begin + count / 2, begin + count,
                             [&](std::uint32_t a, std::uint32_t b) { return centers[a][axis] < centers[b][axis]; });
            mid = first + count / 2;
        }
        // The left child directly follows its parent; `first` names the right one.
        const auto left = static_cast<std::uint32_t>(nodes.size());
        nodes.resize(nodes.size() + 1);
        build(left, first, mid - first, depth + 1);
        const auto right = static_cast<std::uint32_t>(nodes.size());
        nodes.resize(nodes.size() + 1);
        nodes[index].first = right;
        build(right, mid, first + count - mid, depth + 1);
    }

    void make_leaf(std::uint32_t index, std::uint32_t first, std::uint32_t count) {
        nodes[index].first = first;
        nodes[index].count = static_cast<std::uint16_t>(count);
    }

    // Partitions by the cheapest bin boundary and returns the split position;
    // kLeaf when a leaf is cheaper than any split, kMedian when no boundary separates.
    std::uint32_t sah_split(std::uint32_t first, std::uint32_t count, int axis, const Aabb& centroid_bounds,
                            const Aabb& bounds) {
        struct Bin {
            Aabb box;
            std::uint32_t count = 0;
        };
        std::array<Bin, kBins> bins{};
        const double lo = centroid_bounds.min[axis];
        const double scale = kBins / (centroid_bounds.max[axis] - lo);
        if (!std::isfinite(scale)) return kMedian; // a subnormal spread: bins cannot tell the centroids apart
        auto bin_of = [&](std::uint32_t prim) {
            // Clamped as a double: the product may overflow to infinity, which no int holds.
            return static_cast<int>(std::clamp((centers[prim][axis] - lo) * scale, 0.0, kBins - 1.0));
        };
        for (std::uint32_t i = first; i < first + count; ++i) {
            Bin& bin = bins[bin_of(order[i])];
            bin.box.expand(boxes[order[i]]);
            ++bin.count;
        }
        // Sweep from the right to know the cost of every right-hand side.
        std::array<double, kBins> right_cost{};
        Aabb right_box;
        std::uint32_t right_count = 0;
        for (int b = kBins - 1; b > 0; --b) {
            right_box.expand(bins[b].box);
            right_count += bins[b].count;
            right_cost[b] = right_box.half_area() * right_count;
        }
        Aabb left_box;
        std::uint32_t left_count = 0;
        double best_cost = kInfinity;
        int best_bin = -1;
        for (int b = 1; b < kBins; ++b) {
            left_box.expand(bins[b - 1].box);
            left_count += bins[b - 1].count;
            if (left_count == 0 || left_count == count) continue;
            const double cost = left_box.half_area() * left_count + right_cost[b];
            if (cost < best_cost) {
                best_cost = cost;
                best_bin = b;
            }
        }
        if (best_bin < 0) return kMedian;
        const double leaf_cost = bounds.half_area() * count;
        const double split_cost = kTraversalCost * bounds.half_area() + best_cost;
        if (count <= kMaxLeafCount && leaf_cost <= split_cost) return kLeaf;
        auto middle = std::partition(order.begin() + first, order.begin() + first + count,
                                     [&](std::uint32_t prim) { return bin_of(prim) < best_bin; });
        return static_cast<std::uint32_t>(middle - order.begin());
    }
};

} // namespace

Bvh::Bvh(std::span<const Aabb> boxes) {
    order_.resize(boxes.size());
    std::iota(order_.begin(), order_.end(), 0u);
    if (boxes.empty()) return;
    std::vector<Point3> centers(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) centers[i] = boxes[i].center();
    nodes_.reserve(2 * boxes.size());
    nodes_.resize(1);
    Builder builder{boxes, std::move(centers), order_, nodes_};
    builder.build(0, 0, static_cast<std::uint32_t>(boxes.size()), 0);
    nodes_.shrink_to_fit();
}

} // namespace whitted
