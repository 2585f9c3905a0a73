// An optional fast path for the tests inside BVH leaves.
//
// Why: the labs' `closest_hit()` builds a complete `Hit` (point, normals, side)
// for every candidate a ray meets, and a shadow feeler builds one just to learn
// "something is there". The reference renderer plugs in kernels that find only
// the distance, with the very same arithmetic as the reference labs, and the
// scene then builds one `Hit` for the nearest primitive alone: the same image,
// bit for bit (tests/solution checks it), for less work. A student build has
// none, so every ray goes through the student's own code.
#pragma once

#include "whitted/interval.hpp"
#include "whitted/primitive.hpp"

#include <cstdint>
#include <optional>
#include <span>

namespace whitted {

/// The nearest hit found in a leaf: which primitive (index within the span) and where.
struct LeafHit {
    std::uint32_t index = 0;
    double t = 0.0;
};

struct LeafKernels {
    /// The nearest hit among the primitives with t inside t_range, if any.
    std::optional<LeafHit> (*closest)(const Ray& ray, std::span<const Primitive> primitives, Interval t_range);
    /// True when any of the primitives is hit with t inside t_range.
    bool (*any)(const Ray& ray, std::span<const Primitive> primitives, Interval t_range);
};

/// The kernels this program was linked with: the reference renderer's, or
/// nullptr in a build that renders with the student's labs.
const LeafKernels* linked_leaf_kernels();

} // namespace whitted
