// Calibration variant (not a mistake): lab 1 computed in float, as many students write it.
#include "whitted/labs.hpp"

#include <cmath>

namespace whitted {

Ray primary_ray(const Camera& camera, double x, double y) {
    // The same formula, computed in float as a student might.
    const glm::vec3 xe(camera.xe), ye(camera.ye), ze(camera.ze);
    const float w = float(camera.w), h = float(camera.h), df = float(camera.df);
    const glm::vec3 d = w * (float(x) / float(camera.res_x) - 0.5f) * xe + h * (float(y) / float(camera.res_y) - 0.5f) * ye - df * ze;
    return Ray{camera.eye, Vec3(glm::normalize(d))};
}

std::optional<Hit> intersect_sphere(const Ray& ray, const Sphere& sphere, Interval t_range) {
    // Textbook quadratic in float.
    const glm::vec3 oc(ray.origin - sphere.center), d(ray.direction);
    const float b = glm::dot(oc, d);
    const float c = glm::dot(oc, oc) - float(sphere.radius * sphere.radius);
    const float disc = b * b - c;
    if (disc < 0.0f) return std::nullopt;
    const float root = std::sqrt(disc);
    double t = -b - root;
    if (!t_range.surrounds(t)) {
        t = -b + root;
        if (!t_range.surrounds(t)) return std::nullopt;
    }
    const Point3 p = ray.at(t);
    Vec3 outward = glm::normalize(p - sphere.center);
    if (sphere.inward) outward = -outward;
    return make_hit(ray, t, outward);
}

std::optional<Hit> intersect_plane(const Ray& ray, const Plane& plane, Interval t_range) {
    // n . (o + t d - p) = 0  =>  t = n . (p - o) / (n . d)
    const double denominator = glm::dot(plane.normal, ray.direction);
    if (denominator == 0.0) return std::nullopt; // parallel
    const double t = glm::dot(plane.normal, plane.point - ray.origin) / denominator;
    if (!t_range.surrounds(t)) return std::nullopt;
    return make_hit(ray, t, plane.normal);
}

std::optional<Hit> intersect_triangle(const Ray& ray, const Triangle& triangle, Interval t_range) {
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
    Hit hit = make_hit(ray, t, glm::normalize(glm::cross(e1, e2)));
    hit.uv = Vec2(b1, b2);
    return hit;
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
