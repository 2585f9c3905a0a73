// Vector types and small numeric helpers shared by the whole framework.
//
// Why: every lab speaks about points, directions and colours. They are all GLM
// double-precision 3-vectors; the aliases only say which one a value means.
// Double precision keeps student and reference results equal to the last bit
// far more often than float would, which matters for image grading.
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <limits>

namespace whitted {

using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;   // a direction or offset
using Point3 = glm::dvec3; // a position in world space
using Color = glm::dvec3;  // linear RGB, 1 = full intensity

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Converts degrees to radians.
constexpr double radians(double degrees) { return degrees * (kPi / 180.0); }

/// True when every component of v is a finite number (no NaN, no infinity).
inline bool is_finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// The largest absolute component of v; NaN when any component is NaN (a plain max would drop it).
inline double max_abs_component(const Vec3& v) {
    if (std::isnan(v.x) || std::isnan(v.y) || std::isnan(v.z)) return std::numeric_limits<double>::quiet_NaN();
    return glm::max(glm::abs(v.x), glm::max(glm::abs(v.y), glm::abs(v.z)));
}

} // namespace whitted
