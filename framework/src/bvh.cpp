// Binned surface-area-heuristic BVH construction.
#include "whitted/engine/bvh.hpp"

#include "permute.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>
#include <system_error>

namespace whitted {
namespace {

constexpr int kBins = 16;
constexpr std::uint32_t kMaxLeafSize = 4; // without test costs, nodes this small are leaves
constexpr int kMaxSahDepth = 48; // deeper than this, split at the median so the tree stays shallow
constexpr double kTraversalCost = 1.0; // relative to one primitive test
// With test costs: what a ray pays before its first node test (WideRay's set-up), in
// node tests. Only the root weighs it: a scene of a few shapes is one leaf, no walk.
constexpr double kRaySetupCost = 4.0;
// With test costs: a node of at most four primitives whose tests cost at most this is a leaf
// (four spheres): a wide node costs about one test, so splitting it saves little and
// costs memory and build time.
constexpr double kSmallLeafCost = 4.0;
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

// The primitives of one of sah_split's bins.
struct Bin {
    RangeBounds bounds;
    std::uint32_t count = 0;
    double cost = 0.0; // the sum of its primitives' test costs (exact: they are multiples of 1/2)

    void add(const Bin& other) {
        bounds.expand(other.bounds);
        count += other.count;
        cost += other.cost;
    }
};
using Bins = std::array<Bin, kBins>;

// Where a node's primitives split, and the bounds of each side.
struct Split {
    std::uint32_t mid = kMedian;
    RangeBounds left, right;
};

// The builder keeps each primitive's box and test cost at its position in `order`,
// moving them when it moves the primitive, so that every pass over a node reads
// memory front to back (the boxes in the file's order, looked up through `order`,
// cost a cache miss each in a big scene).
struct Builder {
    std::span<Aabb> boxes;             // boxes[i] is the box of primitive order[i]
    std::span<float> test_costs;       // the same for the test costs; empty: every primitive costs 1 and small nodes are leaves
    std::vector<std::uint32_t>& order;
    std::vector<Bvh::Node>& nodes;
    Bvh::Threads threads;
    // sah_split's scratch: the bin of each primitive of the node being split (as many as the builder's own).
    std::unique_ptr<std::uint8_t[]> bin_ids;

    // The centre along one axis of the box at position i, as Aabb::center() computes it (read from the box, not stored: less memory to fill).
    double center(std::uint32_t i, int axis) const { return 0.5 * (boxes[i].min[axis] + boxes[i].max[axis]); }

    // The test costs of the primitives at positions [first, first + count).
    double tests_of(std::uint32_t first, std::uint32_t count) const {
        double sum = 0.0;
        for (std::uint32_t i = first; i < first + count; ++i) sum += test_costs[i];
        return sum;
    }

    RangeBounds bounds_of(std::uint32_t first, std::uint32_t count) const {
        RangeBounds range;
        for (std::uint32_t i = first; i < first + count; ++i) range.expand(boxes[i], boxes[i].center());
        return range;
    }

    // Builds the subtree over order[first, first + count) at nodes[index]; `range` bounds them.
    // A child's bounds come from the parent's split (the boxes of its bins), not from another pass.
    void build(std::uint32_t index, std::uint32_t first, std::uint32_t count, int depth, const RangeBounds& range) {
        nodes[index].bounds = range.boxes;
        if (count <= kMaxLeafSize && (test_costs.empty() || tests_of(first, count) <= kSmallLeafCost))
            return make_leaf(index, first, count);

        const Vec3 extent = range.centers.max - range.centers.min;
        int axis = 0;
        if (extent.y > extent[axis]) axis = 1;
        if (extent.z > extent[axis]) axis = 2;
        Split split;
        if (extent[axis] <= 0.0) {
            // All centroids coincide: no spatial split helps.
            if (count <= kMaxLeafCount) return make_leaf(index, first, count);
        } else if (depth < kMaxSahDepth) {
            split = sah_split(first, count, axis, range, depth);
            if (split.mid == kLeaf) return make_leaf(index, first, count);
        }
        if (split.mid == kMedian) {
            split_at_median(first, count, axis);
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
            Builder right{boxes, test_costs, order, right_nodes, threads, std::make_unique<std::uint8_t[]>(right_count)};
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
        Aabb* prim_boxes = boxes.data() + first;
        float* costs = test_costs.empty() ? nullptr : test_costs.data() + first;
        std::uint8_t* ids = bin_ids.get();
        std::uint32_t low = 0, high = count;
        for (;;) {
            while (low != high && ids[low] < best_bin) ++low;
            if (low == high) return low;
            --high;
            while (low != high && ids[high] >= best_bin) --high;
            if (low == high) return low;
            std::swap(prims[low], prims[high]);
            std::swap(prim_boxes[low], prim_boxes[high]);
            if (costs) std::swap(costs[low], costs[high]);
            std::swap(ids[low], ids[high]);
            ++low;
        }
    }

    // Puts the primitive with the median centre along `axis` at position first + count / 2,
    // those below it before and those above after (as std::nth_element would), with
    // their boxes and costs: the new order is chosen first, then each array follows it.
    void split_at_median(std::uint32_t first, std::uint32_t count, int axis) {
        std::vector<std::uint32_t> from(count); // counted from `first`
        std::iota(from.begin(), from.end(), 0u);
        std::nth_element(from.begin(), from.begin() + count / 2, from.end(), [&](std::uint32_t a, std::uint32_t b) {
            return center(first + a, axis) < center(first + b, axis);
        });
        detail::permute_in_place(std::span(order).subspan(first, count), from);
        detail::permute_in_place(boxes.subspan(first, count), from);
        if (!test_costs.empty()) detail::permute_in_place(test_costs.subspan(first, count), from);
    }

    void make_leaf(std::uint32_t index, std::uint32_t first, std::uint32_t count) {
        nodes[index].first = first;
        nodes[index].count = static_cast<std::uint16_t>(count);
    }

    // Adds the primitives at positions [begin, end) of the node starting at `first` to
    // the bins of their centres along `axis`, noting each one's bin in bin_ids.
    void fill_bins(std::uint32_t first, std::uint32_t begin, std::uint32_t end, int axis, double lo, double scale,
                   Bins& bins) const {
        std::uint8_t* ids = bin_ids.get();
        for (std::uint32_t at = begin; at < end; ++at) {
            // Clamped as a double: the product may overflow to infinity, which no int holds.
            const int b = static_cast<int>(std::clamp((center(at, axis) - lo) * scale, 0.0, kBins - 1.0));
            ids[at - first] = static_cast<std::uint8_t>(b);
            Bin& bin = bins[b];
            bin.bounds.expand(boxes[at], boxes[at].center());
            ++bin.count;
            bin.cost += test_costs.empty() ? 1.0 : test_costs[at];
        }
    }

    // Partitions by the cheapest bin boundary and returns the split position with the
    // bounds of both sides; kLeaf when a leaf is cheaper than any split (with test costs,
    // splitting the root also costs each ray its set-up), kMedian when no boundary separates.
    Split sah_split(std::uint32_t first, std::uint32_t count, int axis, const RangeBounds& range, int depth) {
        const double setup_cost = depth == 0 && !test_costs.empty() ? kRaySetupCost : 0.0;
        Bins bins{};
        const double lo = range.centers.min[axis];
        const double scale = kBins / (range.centers.max[axis] - lo);
        if (!std::isfinite(scale)) return {}; // a subnormal spread: bins cannot tell the centroids apart
        if (threads == Bvh::Threads::several && depth == 0 && count >= kParallelCount) {
            // The root is split before any subtree keeps another thread busy: bin its halves
            // on two. The bins come out the same (minima, maxima and exact sums), so the tree does.
            const std::uint32_t half = first + count / 2;
            Bins upper{};
            std::future<void> upper_done;
            try {
                upper_done = std::async(std::launch::async, [&] { fill_bins(first, half, first + count, axis, lo, scale, upper); });
            } catch (const std::system_error&) {
                fill_bins(first, half, first + count, axis, lo, scale, upper);
            }
            fill_bins(first, first, half, axis, lo, scale, bins);
            if (upper_done.valid()) upper_done.get();
            for (int b = 0; b < kBins; ++b) bins[b].add(upper[b]);
        } else {
            fill_bins(first, first, first + count, axis, lo, scale, bins);
        }
        // Sweep from the right to know the cost of every right-hand side.
        std::array<double, kBins> right_cost{};
        Aabb right_box;
        double right_tests = 0.0;
        for (int b = kBins - 1; b > 0; --b) {
            right_box.expand(bins[b].bounds.boxes);
            right_tests += bins[b].cost;
            right_cost[b] = right_box.half_area() * right_tests;
        }
        Aabb left_box;
        std::uint32_t left_count = 0;
        double left_tests = 0.0;
        double best_cost = kInfinity;
        int best_bin = -1;
        for (int b = 1; b < kBins; ++b) {
            left_box.expand(bins[b - 1].bounds.boxes);
            left_count += bins[b - 1].count;
            left_tests += bins[b - 1].cost;
            if (left_count == 0 || left_count == count) continue;
            const double cost = left_box.half_area() * left_tests + right_cost[b];
            if (cost < best_cost) {
                best_cost = cost;
                best_bin = b;
            }
        }
        if (best_bin < 0) return {};
        const double leaf_cost = range.boxes.half_area() * (left_tests + bins[kBins - 1].cost);
        const double split_cost = (kTraversalCost + setup_cost) * range.boxes.half_area() + best_cost;
        if (count <= kMaxLeafCount && leaf_cost <= split_cost) return {kLeaf, {}, {}};
        Split split;
        for (int b = 0; b < kBins; ++b) (b < best_bin ? split.left : split.right).expand(bins[b].bounds);
        split.mid = first + partition_by_bin(first, count, best_bin);
        return split;
    }
};

} // namespace

Bvh::Bvh(std::vector<Aabb> boxes, std::vector<float> test_costs, Threads threads) {
    if (!test_costs.empty() && test_costs.size() != boxes.size())
        throw std::invalid_argument("Bvh: " + std::to_string(test_costs.size()) + " test costs for " + std::to_string(boxes.size()) + " boxes");
    // Sums of halves are exact in any order, so bins filled by two threads match one thread's.
    for (const float cost : test_costs)
        if (!(cost >= 0.0f && cost <= 1024.0f && std::floor(2.0f * cost) == 2.0f * cost))
            throw std::invalid_argument("Bvh: a test cost of " + std::to_string(cost) + " (expected a multiple of 1/2 in [0, 1024])");
    order_.resize(boxes.size());
    std::iota(order_.begin(), order_.end(), 0u);
    if (boxes.empty()) return;
    nodes_.reserve(2 * boxes.size()); // never grown, so never copied; the room left unused is never touched
    nodes_.resize(1);
    Builder builder{boxes, test_costs, order_, nodes_, threads, std::make_unique<std::uint8_t[]>(boxes.size())};
    const auto count = static_cast<std::uint32_t>(boxes.size());
    builder.build(0, 0, count, 0, builder.bounds_of(0, count));
}

} // namespace whitted
