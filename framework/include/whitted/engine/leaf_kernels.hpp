// An optional fast path for the scene's two ray queries.
//
// Why: the labs' `closest_hit()` builds a complete `Hit` (point, normals, side)
// for every candidate a ray meets, and a shadow feeler builds one just to learn
// "something is there". The reference renderer plugs in queries that walk the
// BVH with distance-only tests, the reference lab 1's own (hit_distances.hpp),
// and build one `Hit` for the nearest primitive alone, from the distance they
// found: the same image, bit for bit (instructor/tests/solution checks it), for less work.
// A student build has none, so every ray goes through the student's own code.
#pragma once

#include "whitted/hit.hpp"
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
    /// The hit of the ray on the nearest primitive with t inside t_range, if any,
    /// as `intersect()` returns it (primitive and material set, vertex normals not yet applied).
    std::optional<Hit> (*closest)(const SceneView& scene, const Ray& ray, Interval t_range);
    /// True when any primitive is hit with t inside t_range. `blocker`, a
    /// position in `primitives` or kNoBlocker, is tested first (it blocked the
    /// feeler before); it is set to the primitive found blocking, or kNoBlocker.
    bool (*occluded)(const SceneView& scene, const Ray& ray, Interval t_range, std::uint32_t& blocker);
    /// closest() for rays[i] within t_ranges[i] into hits[i], up to
    /// RayPacket::kMaxRays rays walking the BVH together: the very same answers.
    void (*closest_packet)(const SceneView& scene, std::span<const Ray> rays, std::span<const Interval> t_ranges,
                           std::span<std::optional<Hit>> hits);
    /// occluded() for rays[i] within t_ranges[i] into blocked[i], up to RayPacket::kMaxRays rays
    /// together; `blocker` is tested first by each and set to one of their blockers, or kNoBlocker.
    void (*occluded_packet)(const SceneView& scene, std::span<const Ray> rays, std::span<const Interval> t_ranges,
                            std::span<bool> blocked, std::uint32_t& blocker);
};

/// The kernels this program was linked with: the reference renderer's, or
/// nullptr in a build that renders with the student's labs.
const LeafKernels* linked_leaf_kernels();

} // namespace whitted
