// Axis-aligned bounding boxes: the building block of the BVH.
#pragma once

#include "whitted/interval.hpp"
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

} // namespace whitted
