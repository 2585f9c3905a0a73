// Axis-aligned bounding boxes: the building block of the BVH.
#pragma once

#include "whitted/interval.hpp"
#include "whitted/ray.hpp"

#include <algorithm>
#include <optional>
#include <utility>

namespace whitted {

struct Aabb {
    Point3 min{kInfinity};
    Point3 max{-kInfinity};

    /// Grows the box to contain p.
    void expand(const Point3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    /// Grows the box to contain other.
    void expand(const Aabb& other) {
        min = glm::min(min, other.min);
        max = glm::max(max, other.max);
    }
    Point3 center() const { return 0.5 * (min + max); }
    /// Half the surface area (all the SAH needs); 0 for an empty box.
    double half_area() const {
        if (!(min.x <= max.x)) return 0.0;
        const Vec3 e = max - min;
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }
    bool is_finite() const { return whitted::is_finite(min) && whitted::is_finite(max); }
};

/// The part of t_range where the ray is inside the box (the slab test), or
/// nothing; inv_direction = 1 / ray.direction. A NaN of 0 x infinity (the origin
/// on the face of a slab the ray runs along) is ignored. The framework's own
/// (its grid and its count of a tree's cost), apart from lab 10's box_entry.
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
