// A ray p(t) = origin + t * direction, as in the slides.
#pragma once

#include "whitted/math.hpp"

namespace whitted {

struct Ray {
    Point3 origin;
    Vec3 direction; // unit length for every ray the framework or the labs create

    /// The point at parameter t along the ray.
    Point3 at(double t) const { return origin + t * direction; }
};

/// What a ray is for: counted in `--stats`, named in the ray tree (`whitted trace`).
enum class RayKind { eye, shadow, reflected, refracted };

} // namespace whitted
