// An optional fast path for the scene's two ray queries.
//
// Why: the labs' `closest_hit()` builds a complete `Hit` (point, normals, side)
// for every candidate a ray meets, and a shadow feeler builds one just to learn
// "something is there". The reference renderer plugs in queries that walk the
// BVH with distance-only tests, the reference lab 1's own (hit_distances.hpp);
// the scene then builds one `Hit` for the nearest primitive
// alone: the same image, bit for bit (instructor/tests/solution checks it), for less work.
// A student build has none, so every ray goes through the student's own code.
#pragma once

#include "whitted/interval.hpp"
#include "whitted/primitive.hpp"
#include "whitted/engine/wide_bvh.hpp"

#include <cstdint>
#include <optional>
#include <span>

namespace whitted {

/// What the leaf kernels see of a built scene: its primitives (the BVH's ones
/// first, in BVH order, then the infinite planes) and its BVH.
struct SceneView {
    std::span<const Primitive> primitives;
    std::size_t bounded_count = 0;
    const WideBvh& bvh;
};

struct LeafKernels {
    /// The nearest primitive (its index) hit by the ray with t inside t_range, if any.
    std::optional<std::uint32_t> (*closest)(const SceneView& scene, const Ray& ray, Interval t_range);
    /// True when any primitive is hit with t inside t_range.
    bool (*occluded)(const SceneView& scene, const Ray& ray, Interval t_range);
};

/// The kernels this program was linked with: the reference renderer's, or
/// nullptr in a build that renders with the student's labs.
const LeafKernels* linked_leaf_kernels();

} // namespace whitted
