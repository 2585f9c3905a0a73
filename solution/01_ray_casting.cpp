// Lab 1 — ray casting: primary rays and the intersections of the first shapes.
#include "whitted/labs.hpp"
#include "whitted/engine/hit_distances.hpp"
#include "01_ray_casting_distances.hpp"

#include <cmath>
#include <utility>

namespace whitted {

Ray primary_ray(const Camera& camera, double x, double y) {
    // d = normalize(w (x / ResX - 1/2) xe + h (y / ResY - 1/2) ye - df ze)
    const Vec3 d = camera.w * (x / camera.res_x - 0.5) * camera.xe +
                   camera.h * (y / camera.res_y - 0.5) * camera.ye - camera.df * camera.ze;
    return Ray{camera.eye, glm::normalize(d)};
}

// The distances alone (declared in whitted/engine/hit_distances.hpp), with the
// arithmetic of 01_ray_casting_distances.hpp, which the reference renderer's
// fast queries inline: one copy of it, so they agree bit for bit.

std::optional<double> sphere_distance(const Ray& ray, const Sphere& sphere, Interval t_range) {
    return lab1::sphere_distance(ray, sphere, t_range);
}

std::optional<double> plane_distance(const Ray& ray, const Plane& plane, Interval t_range) {
    return lab1::plane_distance(ray, plane, t_range);
}

std::optional<TriangleDistance> triangle_distance(const Ray& ray, const Triangle& triangle, Interval t_range) {
    return lab1::triangle_distance(ray, triangle, t_range);
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
    const std::optional<double> t = sphere_distance(ray, sphere, t_range);
    if (!t) return std::nullopt;
    return sphere_hit(ray, sphere, *t);
}

std::optional<Hit> intersect_plane(const Ray& ray, const Plane& plane, Interval t_range) {
    const std::optional<double> t = plane_distance(ray, plane, t_range);
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
