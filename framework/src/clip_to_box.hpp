// The framework's own slab test (its grid, and the count of a tree's cost).
//
// Why here, in the framework's sources and not its public headers: lab 10's
// box_entry() is the student's slab test, and the grader never hands its answer
// over (instructor/grader/lab_fences.hpp); a header the labs can include would.
#pragma once

#include "whitted/aabb.hpp"

#include <optional>
#include <utility>

namespace whitted {

/// The part of t_range where the ray is inside the box (the slab test), or
/// nothing; inv_direction = 1 / ray.direction. A NaN of 0 x infinity (the origin
/// on the face of a slab the ray runs along) is ignored.
inline std::optional<Interval> clip_to_box(const Ray& ray, const Vec3& inv_direction, const Aabb& box, Interval t_range) {
    for (int axis = 0; axis < 3; ++axis) {
        double t0 = (box.min[axis] - ray.origin[axis]) * inv_direction[axis];
        double t1 = (box.max[axis] - ray.origin[axis]) * inv_direction[axis];
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > t_range.min) t_range.min = t0;
        if (t1 < t_range.max) t_range.max = t1;
    }
    if (!(t_range.min <= t_range.max)) return std::nullopt;
    return t_range;
}

} // namespace whitted
