// Lab 10 — a bounding volume hierarchy: built with the surface area heuristic
// over binned centroids, walked nearest child first for the closest hit and
// until the first hit for shadow feelers.
#include "whitted/labs.hpp"

#include <algorithm>
#include <array>

namespace whitted {
namespace {

constexpr int kBins = 16;                // candidate split planes per axis: between the bins
constexpr std::uint32_t kSmallLeaf = 2;  // a node this small is a leaf without asking the SAH
constexpr std::uint32_t kLargestLeaf = 16; // a node larger than this is split even when the SAH says keep it
constexpr double kNodeCost = 1.0;        // testing a node's two children, in units of one primitive test

Aabb union_of(std::span<const Aabb> boxes, std::span<const std::uint32_t> indices) {
    Aabb box;
    for (std::uint32_t i : indices) box.expand(boxes[i]);
    return box;
}

/// The best split of a node: along `axis`, bins [0, bin) on the left.
struct Split {
    int axis = -1;
    int bin = 0;
    double cost = kInfinity;
};

/// Which of the kBins bins along `axis` the centre falls in, over the centres' extent [low, high].
int bin_of(double center, double low, double high) {
    const int bin = static_cast<int>(kBins * (center - low) / (high - low));
    return std::clamp(bin, 0, kBins - 1);
}

/// The cheapest split of the node's primitives by the SAH: cost = node cost +
/// (area_left n_left + area_right n_right) / area_node.
Split best_split(std::span<const Aabb> boxes, std::span<const std::uint32_t> indices, const Aabb& bounds) {
    Aabb centers;
    for (std::uint32_t i : indices) centers.expand(boxes[i].center());
    Split best;
    for (int axis = 0; axis < 3; ++axis) {
        const double low = centers.min[axis], high = centers.max[axis];
        if (!(high > low)) continue; // all centres in one plane: no split along this axis
        std::array<Aabb, kBins> bin_bounds;
        std::array<std::uint32_t, kBins> bin_counts{};
        for (std::uint32_t i : indices) {
            const int bin = bin_of(boxes[i].center()[axis], low, high);
            bin_bounds[bin].expand(boxes[i]);
            ++bin_counts[bin];
        }
        // Sweep from the right, then from the left: the areas and counts on each side of every plane.
        std::array<double, kBins> right_area{};
        std::array<std::uint32_t, kBins> right_count{};
        Aabb right;
        std::uint32_t count = 0;
        for (int bin = kBins - 1; bin > 0; --bin) {
            right.expand(bin_bounds[bin]);
            count += bin_counts[bin];
            right_area[bin] = right.half_area();
            right_count[bin] = count;
        }
        Aabb left;
        count = 0;
        for (int bin = 1; bin < kBins; ++bin) {
            left.expand(bin_bounds[bin - 1]);
            count += bin_counts[bin - 1];
            if (count == 0 || right_count[bin] == 0) continue;
            const double cost = kNodeCost + (left.half_area() * count + right_area[bin] * right_count[bin]) / bounds.half_area();
            if (cost < best.cost) best = Split{axis, bin, cost};
        }
    }
    return best;
}

} // namespace

std::optional<double> box_entry(const Ray& ray, const Vec3& inv_direction, const Aabb& box, Interval t_range) {
    double t_near = t_range.min, t_far = t_range.max;
    for (int axis = 0; axis < 3; ++axis) {
        double t0 = (box.min[axis] - ray.origin[axis]) * inv_direction[axis];
        double t1 = (box.max[axis] - ray.origin[axis]) * inv_direction[axis];
        if (t0 > t1) std::swap(t0, t1);
        // Written so that a NaN (0 x infinity: the origin on a slab of an axis the ray runs along) changes nothing.
        if (t0 > t_near) t_near = t0;
        if (t1 < t_far) t_far = t1;
    }
    if (t_near > t_far) return std::nullopt;
    return t_near;
}

BvhTree build_bvh(std::span<const Aabb> boxes) {
    BvhTree tree;
    tree.order.resize(boxes.size());
    for (std::uint32_t i = 0; i < boxes.size(); ++i) tree.order[i] = i;
    if (boxes.empty()) return tree;
    tree.nodes.push_back(BvhNode{union_of(boxes, tree.order), 0, static_cast<std::uint32_t>(boxes.size())});
    // Nodes still to split, as a list rather than recursion: a lopsided tree can be very deep.
    std::vector<std::uint32_t> pending{0};
    while (!pending.empty()) {
        const std::uint32_t index = pending.back();
        pending.pop_back();
        const BvhNode node = tree.nodes[index];
        if (node.count <= kSmallLeaf) continue;
        const std::span<std::uint32_t> indices(tree.order.data() + node.first, node.count);
        const Split split = best_split(boxes, indices, node.bounds);
        if (split.axis < 0 || (split.cost >= node.count && node.count <= kLargestLeaf)) continue; // stays a leaf
        // Bins left of the split first; the centres' extent is recomputed exactly as best_split did.
        Aabb centers;
        for (std::uint32_t i : indices) centers.expand(boxes[i].center());
        const double low = centers.min[split.axis], high = centers.max[split.axis];
        const auto middle = std::partition(indices.begin(), indices.end(), [&](std::uint32_t i) {
            return bin_of(boxes[i].center()[split.axis], low, high) < split.bin;
        });
        const auto left_count = static_cast<std::uint32_t>(middle - indices.begin());
        const auto first_child = static_cast<std::uint32_t>(tree.nodes.size());
        const std::span<const std::uint32_t> left(indices.data(), left_count);
        const std::span<const std::uint32_t> right(indices.data() + left_count, node.count - left_count);
        tree.nodes.push_back(BvhNode{union_of(boxes, left), node.first, left_count});
        tree.nodes.push_back(BvhNode{union_of(boxes, right), node.first + left_count, node.count - left_count});
        tree.nodes[index] = BvhNode{node.bounds, first_child, 0};
        pending.push_back(first_child);
        pending.push_back(first_child + 1);
    }
    return tree;
}

std::optional<Hit> bvh_closest_hit(const Scene& scene, const Ray& ray, Interval t_range) {
    const BvhTree& bvh = scene.lab_bvh();
    const std::span<const Primitive> primitives = scene.bounded_primitives();
    if (bvh.nodes.empty()) return std::nullopt;
    const Vec3 inv_direction = 1.0 / ray.direction;
    std::optional<Hit> nearest;
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
        const BvhNode& node = bvh.nodes[stack.back()];
        stack.pop_back();
        // Tested again now: a hit found since the node was put on the stack may have moved t_range.max before it.
        if (!box_entry(ray, inv_direction, node.bounds, t_range)) continue;
        if (node.count > 0) {
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                if (std::optional<Hit> hit = intersect(ray, primitives[bvh.order[i]], t_range)) {
                    t_range.max = hit->t;
                    nearest = hit;
                }
            }
            continue;
        }
        // The nearer child is walked first (pushed last): its hits let the farther one be skipped.
        const std::optional<double> a = box_entry(ray, inv_direction, bvh.nodes[node.first].bounds, t_range);
        const std::optional<double> b = box_entry(ray, inv_direction, bvh.nodes[node.first + 1].bounds, t_range);
        if (a && b) {
            stack.push_back(*a <= *b ? node.first + 1 : node.first);
            stack.push_back(*a <= *b ? node.first : node.first + 1);
        } else if (a || b) {
            stack.push_back(a ? node.first : node.first + 1);
        }
    }
    return nearest;
}

bool bvh_occluded(const Scene& scene, const Ray& ray, Interval t_range) {
    const BvhTree& bvh = scene.lab_bvh();
    const std::span<const Primitive> primitives = scene.bounded_primitives();
    if (bvh.nodes.empty()) return false;
    const Vec3 inv_direction = 1.0 / ray.direction;
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
        const BvhNode& node = bvh.nodes[stack.back()];
        stack.pop_back();
        if (!box_entry(ray, inv_direction, node.bounds, t_range)) continue;
        if (node.count == 0) { // any order will do: the first hit ends the search
            stack.push_back(node.first);
            stack.push_back(node.first + 1);
            continue;
        }
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
            if (intersect(ray, primitives[bvh.order[i]], t_range)) return true;
    }
    return false;
}

} // namespace whitted
