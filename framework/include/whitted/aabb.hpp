// Axis-aligned bounding boxes: the building block of the BVH.
#pragma once

#include "whitted/ray.hpp"

#include <algorithm>

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

/// A ray prepared for box tests: origin and reciprocal direction.
struct RayBoxQuery {
    Point3 origin;
    Vec3 inv_direction;
    explicit RayBoxQuery(const Ray& ray) : origin(ray.origin), inv_direction(1.0 / ray.direction) {}

    /// The entry distance into the box if the ray meets it within [t_min, t_max], else +infinity.
    /// Uses the slab method; the min/max ordering also handles direction components of 0
    /// (their reciprocals are infinite) without producing NaN for origins off the slab.
    double entry(const Aabb& box, double t_min, double t_max) const {
        for (int axis = 0; axis < 3; ++axis) {
            double t0 = (box.min[axis] - origin[axis]) * inv_direction[axis];
            double t1 = (box.max[axis] - origin[axis]) * inv_direction[axis];
            if (t0 > t1) std::swap(t0, t1);
            // NaN (0 * inf, origin exactly on a slab of a flat box) must not reject: treat as unbounded.
            if (t0 > t_min) t_min = t0;
            if (t1 < t_max) t_max = t1;
            if (t_min > t_max) return kInfinity;
        }
        return t_min;
    }
};

} // namespace whitted
