// The scene's two fast queries, closest hit and occlusion, written once over a
// leaf tester: planes first, then the BVH walk, each leaf handed to `Leaf`.
//
// Why a template: the plain kernels and the AVX kernels differ only in how a
// leaf's primitives are tested. `Leaf` provides
//   double nearest(ray, primitives, first, count, t_min, t_max, nearest_index):
//       tests primitives [first, first + count) in order, as one loop with the
//       range's max shrinking at each hit would, and returns the new t_max
//       (setting nearest_index) or t_max unchanged;
//   bool any(ray, primitives, first, count, t_min, t_max).
// Internal linkage, like distances.hpp: one copy per instruction set.
#pragma once

#include "distances.hpp"

#include "whitted/leaf_kernels.hpp"

namespace whitted {
namespace {

template <class Leaf>
std::optional<std::uint32_t> closest_query(const SceneView& scene, const Ray& ray, Interval t_range) {
    std::optional<std::uint32_t> nearest;
    for (std::size_t i = scene.bounded_count; i < scene.primitives.size(); ++i) {
        if (const double t = distance(ray, scene.primitives[i], t_range); t != kMiss) {
            t_range.max = t;
            nearest = static_cast<std::uint32_t>(i);
        }
    }
    const Leaf leaf(ray);
    const Primitive* primitives = scene.primitives.data();
    scene.bvh.traverse(ray, t_range.min, t_range.max, [&](std::uint32_t first, std::uint32_t count, double t_max) {
        return leaf.nearest(ray, primitives, first, count, t_range.min, t_max, nearest);
    });
    return nearest;
}

template <class Leaf>
bool occluded_query(const SceneView& scene, const Ray& ray, Interval t_range) {
    for (std::size_t i = scene.bounded_count; i < scene.primitives.size(); ++i)
        if (distance(ray, scene.primitives[i], t_range) != kMiss) return true;
    bool blocked = false;
    const Leaf leaf(ray);
    const Primitive* primitives = scene.primitives.data();
    scene.bvh.traverse<false>(ray, t_range.min, t_range.max, [&](std::uint32_t first, std::uint32_t count, double t_max) {
        if (!leaf.any(ray, primitives, first, count, t_range.min, t_max)) return t_max;
        blocked = true;
        return -1.0;
    });
    return blocked;
}

} // namespace
} // namespace whitted
