// Lab 10 as a student may well write it without the surface area heuristic: each node split at the median
// centre along its longest axis, and walks that test the nearer child first (closest hit) or stop at the
// first hit (shadow feelers). The handout allows it ("the surface area heuristic, or at least the median"), so
// lab 10's tests must give it full marks: split.alternative.median_split runs them all on it through the link.
#include "whitted/labs.hpp"

#include <algorithm>
#include <utility>

namespace whitted {

std::optional<double> box_entry(const Ray& ray, const Vec3& inv_direction, const Aabb& box, Interval t_range) {
    for (int axis = 0; axis < 3; ++axis) {
        double enter = (box.min[axis] - ray.origin[axis]) * inv_direction[axis];
        double leave = (box.max[axis] - ray.origin[axis]) * inv_direction[axis];
        if (enter > leave) std::swap(enter, leave);
        // Comparisons with a NaN are false: a slab the ray runs along from its plane leaves the range as it was.
        // (std::min and std::max would not do: std::max(-inf, NaN) is -inf, a miss.)
        if (enter > t_range.min) t_range.min = enter;
        if (leave < t_range.max) t_range.max = leave;
    }
    if (t_range.min > t_range.max) return std::nullopt;
    return t_range.min;
}

namespace {

void split_node(BvhTree& tree, std::span<const Aabb> boxes, std::uint32_t index) {
    const std::uint32_t first = tree.nodes[index].first, count = tree.nodes[index].count;
    if (count <= 4) return;
    Aabb centres;
    for (std::uint32_t i = first; i < first + count; ++i) centres.expand(boxes[tree.order[i]].center());
    const Vec3 extent = centres.max - centres.min;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    if (!(extent[axis] > 0.0)) return; // every centre in one place: a leaf
    const std::uint32_t half = count / 2;
    const auto begin = tree.order.begin() + first;
    std::nth_element(begin, begin + half, begin + count, [&](std::uint32_t a, std::uint32_t b) {
        return boxes[a].center()[axis] < boxes[b].center()[axis];
    });
    const auto child = static_cast<std::uint32_t>(tree.nodes.size());
    for (const auto& [from, size] : {std::pair{first, half}, std::pair{first + half, count - half}}) {
        BvhNode node{Aabb(), from, size};
        for (std::uint32_t i = from; i < from + size; ++i) node.bounds.expand(boxes[tree.order[i]]);
        tree.nodes.push_back(node);
    }
    tree.nodes[index].first = child;
    tree.nodes[index].count = 0;
    split_node(tree, boxes, child);
    split_node(tree, boxes, child + 1);
}

} // namespace

BvhTree build_bvh(std::span<const Aabb> boxes) {
    BvhTree tree;
    for (std::uint32_t i = 0; i < boxes.size(); ++i) tree.order.push_back(i);
    if (boxes.empty()) return tree;
    BvhNode root{Aabb(), 0, static_cast<std::uint32_t>(boxes.size())};
    for (const Aabb& box : boxes) root.bounds.expand(box);
    tree.nodes.push_back(root);
    split_node(tree, boxes, 0);
    return tree;
}

std::optional<Hit> bvh_closest_hit(const Scene& scene, const Ray& ray, Interval t_range) {
    const BvhTree& tree = scene.lab_bvh();
    if (tree.nodes.empty()) return std::nullopt;
    const Vec3 inv(1.0 / ray.direction.x, 1.0 / ray.direction.y, 1.0 / ray.direction.z);
    std::optional<Hit> best;
    std::vector<std::pair<std::uint32_t, double>> todo; // node, where the ray enters it
    if (const auto t = box_entry(ray, inv, tree.nodes[0].bounds, t_range)) todo.emplace_back(0, *t);
    while (!todo.empty()) {
        const auto [index, entry] = todo.back();
        todo.pop_back();
        if (entry > t_range.max) continue; // a nearer hit was found since
        const BvhNode& node = tree.nodes[index];
        if (node.count > 0) {
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
                if (auto hit = intersect(ray, scene.bounded_primitives()[tree.order[i]], t_range)) {
                    t_range.max = hit->t;
                    best = hit;
                }
            continue;
        }
        auto left = box_entry(ray, inv, tree.nodes[node.first].bounds, t_range);
        auto right = box_entry(ray, inv, tree.nodes[node.first + 1].bounds, t_range);
        std::uint32_t near = node.first, far = node.first + 1;
        if (left && right && *right < *left) {
            std::swap(near, far);
            std::swap(left, right);
        }
        if (right) todo.emplace_back(far, *right); // the farther one waits below the nearer
        if (left) todo.emplace_back(near, *left);
    }
    return best;
}

bool bvh_occluded(const Scene& scene, const Ray& ray, Interval t_range) {
    const BvhTree& tree = scene.lab_bvh();
    if (tree.nodes.empty()) return false;
    const Vec3 inv(1.0 / ray.direction.x, 1.0 / ray.direction.y, 1.0 / ray.direction.z);
    std::vector<std::uint32_t> todo{0};
    while (!todo.empty()) {
        const BvhNode& node = tree.nodes[todo.back()];
        todo.pop_back();
        if (!box_entry(ray, inv, node.bounds, t_range)) continue;
        if (node.count == 0) {
            todo.push_back(node.first);
            todo.push_back(node.first + 1);
            continue;
        }
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
            if (intersect(ray, scene.bounded_primitives()[tree.order[i]], t_range)) return true;
    }
    return false;
}

} // namespace whitted
