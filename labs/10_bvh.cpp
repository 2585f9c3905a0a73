// Lab 10 — a bounding volume hierarchy (BVH): boxes around groups of
// primitives, boxes around groups of boxes, so that a ray skips every group
// whose box it misses. Testing every primitive costs a ray O(n); a good BVH
// makes it about O(log n), the difference between minutes and a second.
// Handout: docs/labs/10_bvh.md. Tests: make test LAB=10
#include "whitted/labs.hpp"

namespace whitted {

// The slab test. Along each axis the box is the slab min[axis] <= p <= max[axis];
// the ray is inside it for t between (min[axis] - origin[axis]) * inv_direction[axis]
// and (max[axis] - origin[axis]) * inv_direction[axis] (swap the two when the
// ray runs towards -axis). It is inside the box where it is inside all three
// slabs and inside t_range: from the largest entry to the smallest exit.
// Return that entry t when it is not after the exit, nothing otherwise.
// inv_direction = 1 / ray.direction: a division once per ray, not per box.
std::optional<double> box_entry(const Ray& ray, const Vec3& inv_direction, const Aabb& box, Interval t_range) {
    not_implemented();
}

// A BvhTree (whitted/bvh_tree.hpp) over the boxes, box i being primitive i's:
// nodes[0] is the root; a leaf (count > 0) holds order[first .. first+count-1];
// an inner node (count == 0) has the children nodes[first] and nodes[first+1].
// Start with one leaf holding everything and split nodes in two, along an axis,
// by the boxes' centres: at the median (simple) or where the surface area
// heuristic says a ray pays least (the handout explains both).
// No boxes at all (a scene of planes only): return a tree with no nodes.
BvhTree build_bvh(std::span<const Aabb> boxes) {
    not_implemented();
}

// The nearest hit among scene.bounded_primitives() with t inside t_range, by
// walking scene.lab_bvh() from the root: skip a node whose box the ray misses
// (box_entry), test a leaf's primitives with intersect(ray, primitive, t_range)
// and shrink t_range.max to each hit; visit the nearer child first.
// The tests count your intersect() calls: at most 1.5 times those of the
// framework's own walk of the same tree (docs/labs/10_bvh.md).
std::optional<Hit> bvh_closest_hit(const Scene& scene, const Ray& ray, Interval t_range) {
    not_implemented();
}

// True when any of scene.bounded_primitives() is hit with t inside t_range:
// the same walk, returning at the first hit (a shadow feeler needs no more).
bool bvh_occluded(const Scene& scene, const Ray& ray, Interval t_range) {
    not_implemented();
}

} // namespace whitted
