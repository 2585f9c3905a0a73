// Binned surface-area-heuristic BVH construction.
#include "whitted/engine/bvh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <memory>
#include <numeric>
#include <system_error>

namespace whitted {
namespace {

constexpr int kBins = 16;
constexpr std::uint32_t kMaxLeafSize = 4;
constexpr int kMaxSahDepth = 48; // deeper than this, split at the median so the tree stays shallow
constexpr double kTraversalCost = 1.0; // relative to one primitive test
constexpr std::uint32_t kMaxLeafCount = 65535; // Node::count is 16 bits
constexpr std::uint32_t kLeaf = 0;             // sah_split: make a leaf
constexpr std::uint32_t kMedian = ~0u;         // sah_split: split at the median instead
constexpr std::uint32_t kParallelCount = 1u << 16; // subtrees this big build their halves on two threads...
constexpr int kParallelDepth = 2;                  // ...down to this depth (at most four threads at once)

// The box around some primitives and the box around their centres.
struct RangeBounds {
    Aabb boxes, centers;

    void expand(const Aabb& box, const Point3& center) {
        boxes.expand(box);
        centers.expand(center);
    }
    void expand(const RangeBounds& other) {
        boxes.expand(other.boxes);
        centers.expand(other.centers);
    }
};

// Where a node's primitives split, and the bounds of each side.
struct Split {
    std::uint32_t mid = kMedian;
    RangeBounds left, right;
};

struct Builder {
    std::span<const Aabb> boxes;
    std::vector<std::uint32_t>& order;
    std::vector<Bvh::Node>& nodes;
    Bvh::Threads threads;
    // sah_split's scratch: the bin of each primitive of the node being split (as many as the builder's own).
    std::unique_ptr<std::uint8_t[]> bin_ids;

    // A box's centre along one axis, as Aabb::center() computes it (read from the box, not stored: less memory to fill).
    double center(std::uint32_t prim, int axis) const { return 0.5 * (boxes[prim].min[axis] + boxes[prim].max[axis]); }

    RangeBounds bounds_of(std::uint32_t first, std::uint32_t count) const {
        RangeBounds range;
        for (std::uint32_t i = first; i < first + count; ++i) range.expand(boxes[order[i]], boxes[order[i]].center());
        return range;
    }

    // Builds the subtree over order[first, first + count) at nodes[index]; `range` bounds them.
    // A child's bounds come from the parent's split (the boxes of its bins), not from another pass.
    void build(std::uint32_t index, std::uint32_t first, std::uint32_t count, int depth, const RangeBounds& range) {
        nodes[index].bounds = range.boxes;
        if (count <= kMaxLeafSize) return make_leaf(index, first, count);

        const Vec3 extent = range.centers.max - range.centers.min;
        int axis = 0;
        if (extent.y > extent[axis]) axis = 1;
        if (extent.z > extent[axis]) axis = 2;
        Split split;
        if (extent[axis] <= 0.0) {
            // All centroids coincide: no spatial split helps.
            if (count <= kMaxLeafCount) return make_leaf(index, first, count);
        } else if (depth < kMaxSahDepth) {
            split = sah_split(first, count, axis, range);
            if (split.mid == kLeaf) return make_leaf(index, first, count);
        }
        if (split.mid == kMedian) {
            auto begin = order.begin() + first;
            std::nth_element(begin, begin + count / 2, begin + count,
                             [&](std::uint32_t a, std::uint32_t b) { return center(a, axis) < center(b, axis); });
            split.mid = first + count / 2;
            split.left = bounds_of(first, split.mid - first);
            split.right = bounds_of(split.mid, first + count - split.mid);
        }
        // The left child directly follows its parent; `first` names the right one.
        const auto left = static_cast<std::uint32_t>(nodes.size());
        nodes.resize(nodes.size() + 1);
        if (threads == Bvh::Threads::several && count >= kParallelCount && depth < kParallelDepth)
            return build_both(index, left, first, count, depth, split);
        build(left, first, split.mid - first, depth + 1, split.left);
        const auto right = static_cast<std::uint32_t>(nodes.size());
        nodes.resize(nodes.size() + 1);
        nodes[index].first = right;
        build(right, split.mid, first + count - split.mid, depth + 1, split.right);
    }

    // The same as the two calls above, with the right subtree built on another
    // thread into nodes of its own, then appended after the left one: the tree
    // is the same, node for node, whatever the number of threads.
    void build_both(std::uint32_t index, std::uint32_t left, std::uint32_t first, std::uint32_t count, int depth,
                    const Split& split) {
        const std::uint32_t right_count = first + count - split.mid;
        std::vector<Bvh::Node> right_nodes(1);
        right_nodes.reserve(2 * right_count);
        auto build_right = [&, this] {
            Builder right{boxes, order, right_nodes, threads, std::make_unique<std::uint8_t[]>(right_count)};
            right.build(0, split.mid, right_count, depth + 1, split.right);
        };
        std::future<void> right_done;
        try {
            right_done = std::async(std::launch::async, build_right); // the two halves of `order` do not overlap
        } catch (const std::system_error&) {
            build_right(); // no thread to be had (a process limit): one after the other
        }
        build(left, first, split.mid - first, depth + 1, split.left);
        if (right_done.valid()) right_done.get();
        const auto right = static_cast<std::uint32_t>(nodes.size());
        nodes[index].first = right;
        for (Bvh::Node& node : right_nodes) {
            if (node.count == 0) node.first += right; // an inner node's second child, now counted from here
            nodes.push_back(node);
        }
    }

    // Moves the primitives of order[first, first + count) whose bin (bin_ids) is below
    // `best_bin` to the front and returns how many they are. The ends walk inwards and
    // swap what stands on the wrong side, as std::partition does, so the order is the same.
    std::uint32_t partition_by_bin(std::uint32_t first, std::uint32_t count, int best_bin) {
        std::uint32_t* prims = order.data() + first;
        std::uint8_t* ids = bin_ids.get();
        std::uint32_t low = 0, high = count;
        for (;;) {
            while (low != high && ids[low] < best_bin) ++low;
            if (low == high) return low;
            --high;
            while (low != high && ids[high] >= best_bin) --high;
            if (low == high) return low;
            std::swap(prims[low], prims[high]);
            std::swap(ids[low], ids[high]);
            ++low;
        }
    }

    void make_leaf(std::uint32_t index, std::uint32_t first, std::uint32_t count) {
        nodes[index].first = first;
        nodes[index].count = static_cast<std::uint16_t>(count);
    }

    // Partitions by the cheapest bin boundary and returns the split position with
    // the bounds of both sides; kLeaf when a leaf is cheaper than any split,
    // kMedian when no boundary separates.
    Split sah_split(std::uint32_t first, std::uint32_t count, int axis, const RangeBounds& range) {
        struct Bin {
            RangeBounds bounds;
            std::uint32_t count = 0;
        };
        std::array<Bin, kBins> bins{};
        const double lo = range.centers.min[axis];
        const double scale = kBins / (range.centers.max[axis] - lo);
        if (!std::isfinite(scale)) return {}; // a subnormal spread: bins cannot tell the centroids apart
        auto bin_of = [&](std::uint32_t prim) {
            // Clamped as a double: the product may overflow to infinity, which no int holds.
            return static_cast<int>(std::clamp((center(prim, axis) - lo) * scale, 0.0, kBins - 1.0));
        };
        std::uint8_t* ids = bin_ids.get(); // each primitive's bin, for the partition below
        for (std::uint32_t i = 0; i < count; ++i) {
            const std::uint32_t prim = order[first + i];
            const int b = bin_of(prim);
            ids[i] = static_cast<std::uint8_t>(b);
            Bin& bin = bins[b];
            bin.bounds.expand(boxes[prim], boxes[prim].center());
            ++bin.count;
        }
        // Sweep from the right to know the cost of every right-hand side.
        std::array<double, kBins> right_cost{};
        Aabb right_box;
        std::uint32_t right_count = 0;
        for (int b = kBins - 1; b > 0; --b) {
            right_box.expand(bins[b].bounds.boxes);
            right_count += bins[b].count;
            right_cost[b] = right_box.half_area() * right_count;
        }
        Aabb left_box;
        std::uint32_t left_count = 0;
        double best_cost = kInfinity;
        int best_bin = -1;
        for (int b = 1; b < kBins; ++b) {
            left_box.expand(bins[b - 1].bounds.boxes);
            left_count += bins[b - 1].count;
            if (left_count == 0 || left_count == count) continue;
            const double cost = left_box.half_area() * left_count + right_cost[b];
            if (cost < best_cost) {
                best_cost = cost;
                best_bin = b;
            }
        }
        if (best_bin < 0) return {};
        const double leaf_cost = range.boxes.half_area() * count;
        const double split_cost = kTraversalCost * range.boxes.half_area() + best_cost;
        if (count <= kMaxLeafCount && leaf_cost <= split_cost) return {kLeaf, {}, {}};
        Split split;
        for (int b = 0; b < kBins; ++b) (b < best_bin ? split.left : split.right).expand(bins[b].bounds);
        split.mid = first + partition_by_bin(first, count, best_bin);
        return split;
    }
};

} // namespace

Bvh::Bvh(std::span<const Aabb> boxes, Threads threads) {
    order_.resize(boxes.size());
    std::iota(order_.begin(), order_.end(), 0u);
    if (boxes.empty()) return;
    nodes_.reserve(2 * boxes.size()); // never grown, so never copied; the room left unused is never touched
    nodes_.resize(1);
    Builder builder{boxes, order_, nodes_, threads, std::make_unique<std::uint8_t[]>(boxes.size())};
    const auto count = static_cast<std::uint32_t>(boxes.size());
    builder.build(0, 0, count, 0, builder.bounds_of(0, count));
}

} // namespace whitted
