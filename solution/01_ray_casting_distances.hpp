// Lab 1's distance arithmetic, the reference answer, inline.
//
// Why: the reference lab 1 (01_ray_casting.cpp) defines the distance functions of
// whitted/engine/hit_distances.hpp with these, and the reference renderer's leaf
// kernels call these directly, so that the compiler can inline them into the
// BVH walk (a call per sphere tested cost the sphere scenes 1-2 %). One copy of
// the arithmetic, compiled with the same flags (-ffp-contract=off, SSE2 doubles),
// gives the same bits in both places.
#pragma once

#include "whitted/engine/hit_distances.hpp"

#include <cmath>
#include <optional>
#include <utility>

namespace whitted::lab1 {

inline std::optional<double> sphere_distance(const Ray& ray, const Sphere& sphere, Interval t_range) {
    // |o + t d - c|^2 = r^2 with |d| = 1:  t^2 + 2 b t + c = 0, b = (o - c) . d, c = |o - c|^2 - r^2.
    const Vec3 oc = ray.origin - sphere.center;
    const double b = glm::dot(oc, ray.direction);
    const double c = glm::dot(oc, oc) - sphere.radius * sphere.radius;
    // The discriminant b^2 - c, computed as r^2 - (distance from the centre to the ray)^2,
    // which does not lose its digits when the sphere is small and far away.
    const Vec3 to_line = oc - b * ray.direction;
    const double discriminant = sphere.radius * sphere.radius - glm::dot(to_line, to_line);
    if (discriminant < 0.0) return std::nullopt;
    // Stable roots: q = -b - sign(b) sqrt(disc); t0 = q, t1 = c / q.
    const double q = -b - std::copysign(std::sqrt(discriminant), b);
    double t0 = q, t1 = (q != 0.0) ? c / q : 0.0;
    if (t0 > t1) std::swap(t0, t1);
    if (t_range.surrounds(t0)) return t0;
    if (t_range.surrounds(t1)) return t1;
    return std::nullopt;
}

inline std::optional<double> plane_distance(const Ray& ray, const Plane& plane, Interval t_range) {
    // n . (o + t d - p) = 0  =>  t = n . (p - o) / (n . d)
    const double denominator = glm::dot(plane.normal, ray.direction);
    if (denominator == 0.0) return std::nullopt; // parallel
    const double t = glm::dot(plane.normal, plane.point - ray.origin) / denominator;
    if (!t_range.surrounds(t)) return std::nullopt;
    return t;
}

inline std::optional<TriangleDistance> triangle_distance(const Ray& ray, const Triangle& triangle, Interval t_range) {
    // Moller-Trumbore: solve o + t d = (1 - b1 - b2) p0 + b1 p1 + b2 p2 with Cramer's rule.
    const Vec3 e1 = triangle.p1 - triangle.p0;
    const Vec3 e2 = triangle.p2 - triangle.p0;
    const Vec3 p = glm::cross(ray.direction, e2);
    const double determinant = glm::dot(e1, p);
    if (determinant == 0.0) return std::nullopt; // ray parallel to the triangle's plane
    const double inverse = 1.0 / determinant;
    const Vec3 s = ray.origin - triangle.p0;
    const double b1 = glm::dot(s, p) * inverse;
    if (b1 < 0.0 || b1 > 1.0) return std::nullopt;
    const Vec3 q = glm::cross(s, e1);
    const double b2 = glm::dot(ray.direction, q) * inverse;
    if (b2 < 0.0 || b1 + b2 > 1.0) return std::nullopt;
    const double t = glm::dot(e2, q) * inverse;
    if (!t_range.surrounds(t)) return std::nullopt;
    return TriangleDistance{t, b1, b2};
}

} // namespace whitted::lab1
