// Distance-only intersection tests for one primitive, with the same
// arithmetic, operation for operation, as the reference labs (solution/01 for
// spheres, planes and triangles; the framework's boxes and cones), so that the
// nearest primitive and its distance come out bit for bit the same.
//
// Why a header of internal functions: each kernel translation unit (the plain
// one and the AVX one, compiled with other instruction sets) needs its own copy;
// an anonymous namespace keeps the copies apart, so the linker can never hand
// the plain build an AVX copy.
#pragma once

#include "whitted/primitive.hpp"

#include <cmath>
#include <limits>
#include <utility>

namespace whitted {
namespace {

// What the distance functions return for "no hit in the range" (no valid t equals it:
// ranges are open, so even an infinite maximum excludes it).
constexpr double kMiss = std::numeric_limits<double>::infinity();

inline double sphere_distance(const Ray& ray, const Sphere& sphere, Interval t_range) {
    const Vec3 oc = ray.origin - sphere.center;
    const double b = glm::dot(oc, ray.direction);
    const double c = glm::dot(oc, oc) - sphere.radius * sphere.radius;
    const Vec3 to_line = oc - b * ray.direction;
    const double discriminant = sphere.radius * sphere.radius - glm::dot(to_line, to_line);
    if (discriminant < 0.0) return kMiss;
    const double q = -b - std::copysign(std::sqrt(discriminant), b);
    double t0 = q, t1 = (q != 0.0) ? c / q : 0.0;
    if (t0 > t1) std::swap(t0, t1);
    if (t_range.surrounds(t0)) return t0;
    if (t_range.surrounds(t1)) return t1;
    return kMiss;
}

inline double plane_distance(const Ray& ray, const Plane& plane, Interval t_range) {
    const double denominator = glm::dot(plane.normal, ray.direction);
    if (denominator == 0.0) return kMiss;
    const double t = glm::dot(plane.normal, plane.point - ray.origin) / denominator;
    if (!t_range.surrounds(t)) return kMiss;
    return t;
}

inline double triangle_distance(const Ray& ray, const Triangle& triangle, Interval t_range) {
    const Vec3 e1 = triangle.p1 - triangle.p0;
    const Vec3 e2 = triangle.p2 - triangle.p0;
    const Vec3 p = glm::cross(ray.direction, e2);
    const double determinant = glm::dot(e1, p);
    if (determinant == 0.0) return kMiss;
    const double inverse = 1.0 / determinant;
    const Vec3 s = ray.origin - triangle.p0;
    const double b1 = glm::dot(s, p) * inverse;
    if (b1 < 0.0 || b1 > 1.0) return kMiss;
    const Vec3 q = glm::cross(s, e1);
    const double b2 = glm::dot(ray.direction, q) * inverse;
    if (b2 < 0.0 || b1 + b2 > 1.0) return kMiss;
    const double t = glm::dot(e2, q) * inverse;
    if (!t_range.surrounds(t)) return kMiss;
    return t;
}

inline double distance(const Ray& ray, const Primitive& primitive, Interval t_range) {
    const Shape& shape = primitive.shape;
    if (const auto* sphere = std::get_if<Sphere>(&shape)) return sphere_distance(ray, *sphere, t_range);
    if (const auto* triangle = std::get_if<Triangle>(&shape)) return triangle_distance(ray, *triangle, t_range);
    if (const auto* plane = std::get_if<Plane>(&shape)) return plane_distance(ray, *plane, t_range);
    // get_if, not get: no throwing path (whose code each instruction set's copy would carry).
    const auto* box = std::get_if<Box>(&shape);
    const std::optional<Hit> hit = box ? intersect_box(ray, *box, t_range) : intersect_cone(ray, *std::get_if<Cone>(&shape), t_range);
    return hit ? hit->t : kMiss;
}

} // namespace
} // namespace whitted
