// Lab 1's intersections, distance only: you do not need this header for the labs.
//
// Why: the reference renderer's leaf kernels (see leaf_kernels.hpp) test many
// candidates per ray and want only the nearest one's distance, while lab 1's
// intersect_sphere/plane/triangle also build a Hit. The reference lab 1 defines
// these three functions and builds its hits from them, and the kernels call the
// very same functions, so both paths agree bit for bit because there is one copy
// of the arithmetic (as pbrt-v4's shapes feed both their intersection queries
// from one BasicIntersect). A student's lab 1 need not define them: only the
// reference renderer calls them.
#pragma once

#include "whitted/hit.hpp"
#include "whitted/interval.hpp"
#include "whitted/ray.hpp"
#include "whitted/shapes.hpp"

#include <limits>
#include <optional>

namespace whitted {

/// Where a ray meets a triangle: the distance t along the ray and the barycentric
/// coordinates (b1, b2) of the point, the weights of p1 and p2.
struct TriangleDistance {
    double t = 0.0;
    double b1 = 0.0;
    double b2 = 0.0;
};

/// A distance along a ray, or none: std::optional<double>'s meaning held in one
/// double, with none as +infinity (which no open range of t holds: made from
/// +infinity, a Distance is none).
///
/// Why not std::optional<double>: g++ 12, returning one from a function that is
/// not inlined, builds its flag word in a stack slot (a byte store, then an
/// eight-byte load of the slot into a register), and that load waits for the
/// store at every return (sphere_distance returns once for every candidate
/// sphere). A Distance comes back in one register with no store.
class Distance {
  public:
    /// None.
    constexpr Distance() = default;
    /// None.
    constexpr Distance(std::nullopt_t) {}
    /// The distance t (none when t is +infinity).
    constexpr Distance(double t) : t_(t) {}
    /// True when there is a distance.
    constexpr explicit operator bool() const { return t_ != kNone; }
    /// The distance (only when there is one).
    constexpr double operator*() const { return t_; }
    /// The distance, or `none` when there is none.
    constexpr double value_or(double none) const { return t_ != kNone ? t_ : none; }

  private:
    static constexpr double kNone = std::numeric_limits<double>::infinity();
    double t_ = kNone;
};

/// The distance t of the ray's hit with the sphere inside t_range (the nearer root first), if any.
Distance sphere_distance(const Ray& ray, const Sphere& sphere, Interval t_range);

/// The distance t of the ray's hit with the plane inside t_range, if any (none when the ray is parallel).
Distance plane_distance(const Ray& ray, const Plane& plane, Interval t_range);

/// The distance and barycentric coordinates of the ray's hit with the triangle inside t_range, if any.
std::optional<TriangleDistance> triangle_distance(const Ray& ray, const Triangle& triangle, Interval t_range);

// The hits at those distances: intersect_sphere/plane/triangle return exactly
// these, so a caller that already knows the distance need not test again.

/// The hit on the sphere at distance t along the ray (t from sphere_distance).
Hit sphere_hit(const Ray& ray, const Sphere& sphere, double t);

/// The hit on the plane at distance t along the ray (t from plane_distance).
Hit plane_hit(const Ray& ray, const Plane& plane, double t);

/// The hit on the triangle where triangle_distance found it.
Hit triangle_hit(const Ray& ray, const Triangle& triangle, const TriangleDistance& found);

} // namespace whitted
