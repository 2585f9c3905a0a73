// Lab 1 — ray casting: primary rays and the intersections of the first shapes.
#include "whitted/labs.hpp"
#include "whitted/engine/hit_distances.hpp"

#include <cmath>
#include <utility>

namespace whitted {

Ray primary_ray(const Camera& camera, double x, double y) {
    // d = normalize(w (x / ResX - 1/2) xe + h (y / ResY - 1/2) ye - df ze)
    const Vec3 d = camera.w * (x / camera.res_x - 0.5) * camera.xe +
                   camera.h * (y / camera.res_y - 0.5) * camera.ye - camera.df * camera.ze;
    return Ray{camera.eye, glm::normalize(d)};
}

// The distances alone (declared in whitted/engine/hit_distances.hpp): the reference
// renderer's fast queries call these same functions, so they agree bit for bit.

Distance sphere_distance(const Ray& ray, const Sphere& sphere, Interval t_range) {
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

Distance plane_distance(const Ray& ray, const Plane& plane, Interval t_range) {
    // n . (o + t d - p) = 0  =>  t = n . (p - o) / (n . d)
    const double denominator = glm::dot(plane.normal, ray.direction);
    if (denominator == 0.0) return std::nullopt; // parallel
    const double t = glm::dot(plane.normal, plane.point - ray.origin) / denominator;
    if (!t_range.surrounds(t)) return std::nullopt;
    return t;
}

std::optional<TriangleDistance> triangle_distance(const Ray& ray, const Triangle& triangle, Interval t_range) {
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

// The hits, built from the distances.

Hit sphere_hit(const Ray& ray, const Sphere& sphere, double t) {
    Vec3 outward = (ray.at(t) - sphere.center) / sphere.radius;
    if (sphere.inward) outward = -outward;
    return make_hit(ray, t, outward);
}

Hit plane_hit(const Ray& ray, const Plane& plane, double t) { return make_hit(ray, t, plane.normal); }

Hit triangle_hit(const Ray& ray, const Triangle& triangle, const TriangleDistance& found) {
    const Vec3 e1 = triangle.p1 - triangle.p0;
    const Vec3 e2 = triangle.p2 - triangle.p0;
    Hit hit = make_hit(ray, found.t, glm::normalize(glm::cross(e1, e2)));
    hit.uv = Vec2(found.b1, found.b2);
    return hit;
}

std::optional<Hit> intersect_sphere(const Ray& ray, const Sphere& sphere, Interval t_range) {
    const Distance t = sphere_distance(ray, sphere, t_range);
    if (!t) return std::nullopt;
    return sphere_hit(ray, sphere, *t);
}

std::optional<Hit> intersect_plane(const Ray& ray, const Plane& plane, Interval t_range) {
    const Distance t = plane_distance(ray, plane, t_range);
    if (!t) return std::nullopt;
    return plane_hit(ray, plane, *t);
}

std::optional<Hit> intersect_triangle(const Ray& ray, const Triangle& triangle, Interval t_range) {
    const std::optional<TriangleDistance> found = triangle_distance(ray, triangle, t_range);
    if (!found) return std::nullopt;
    return triangle_hit(ray, triangle, *found);
}

std::optional<Hit> closest_hit(const Ray& ray, std::span<const Primitive> primitives, Interval t_range) {
    std::optional<Hit> closest;
    for (const Primitive& primitive : primitives) {
        if (auto hit = intersect(ray, primitive, t_range)) {
            t_range.max = hit->t; // from now on only nearer hits count
            closest = hit;
        }
    }
    return closest;
}

} // namespace whitted
