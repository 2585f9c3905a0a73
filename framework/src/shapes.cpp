// Bounds of every shape, and the intersection routines for the shapes the
// framework provides itself (boxes and cones; lab 1 writes the others).
#include "whitted/primitive.hpp"

#include <cmath>

namespace whitted {

std::optional<Aabb> bounds(const Shape& shape) {
    struct Visitor {
        std::optional<Aabb> operator()(const Sphere& s) const {
            return Aabb{s.center - Vec3(s.radius), s.center + Vec3(s.radius)};
        }
        std::optional<Aabb> operator()(const Plane&) const { return std::nullopt; }
        std::optional<Aabb> operator()(const Triangle& t) const {
            Aabb box;
            box.expand(t.p0);
            box.expand(t.p1);
            box.expand(t.p2);
            return box;
        }
        std::optional<Aabb> operator()(const Box& b) const { return Aabb{b.min, b.max}; }
        std::optional<Aabb> operator()(const Cone& c) const {
            // A disc of radius r around axis a spans r * sqrt(1 - a_k^2) along world axis k.
            const Vec3 a = glm::normalize(c.apex - c.base);
            const Vec3 spread = glm::sqrt(glm::max(Vec3(0.0), Vec3(1.0) - a * a));
            Aabb box;
            box.expand(c.base - c.base_radius * spread);
            box.expand(c.base + c.base_radius * spread);
            box.expand(c.apex - c.apex_radius * spread);
            box.expand(c.apex + c.apex_radius * spread);
            return box;
        }
    };
    return std::visit(Visitor{}, shape);
}

std::optional<Hit> intersect_box(const Ray& ray, const Box& box, Interval t_range) {
    // Slab method: the ray is inside the box between the largest entry and the smallest exit.
    double t_enter = -kInfinity, t_exit = kInfinity;
    int enter_axis = 0, exit_axis = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const double inv = 1.0 / ray.direction[axis];
        double t0 = (box.min[axis] - ray.origin[axis]) * inv;
        double t1 = (box.max[axis] - ray.origin[axis]) * inv;
        if (std::isnan(t0) || std::isnan(t1)) return std::nullopt; // parallel and exactly on a face
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > t_enter) { t_enter = t0; enter_axis = axis; }
        if (t1 < t_exit) { t_exit = t1; exit_axis = axis; }
    }
    if (t_enter > t_exit) return std::nullopt;
    // Outward normal of the face crossed: it points against the ray on entry, along it on exit.
    auto face_normal = [&](int axis, double sign) {
        Vec3 n(0.0);
        n[axis] = sign;
        return n;
    };
    if (t_range.surrounds(t_enter)) {
        return make_hit(ray, t_enter, face_normal(enter_axis, ray.direction[enter_axis] > 0.0 ? -1.0 : 1.0));
    }
    if (t_range.surrounds(t_exit)) {
        return make_hit(ray, t_exit, face_normal(exit_axis, ray.direction[exit_axis] > 0.0 ? 1.0 : -1.0));
    }
    return std::nullopt;
}

std::optional<Hit> intersect_cone(const Ray& ray, const Cone& cone, Interval t_range) {
    // Work along the unit axis a: a point's height s = (p - base) . a runs from 0 to length,
    // and the surface radius there is r(s) = base_radius + slope s.
    const Vec3 axis = cone.apex - cone.base;
    const double length = glm::length(axis);
    if (!(length > 0.0)) return std::nullopt; // degenerate cone: no surface
    const Vec3 a = axis / length;
    const double slope = (cone.apex_radius - cone.base_radius) / length;
    // Start the ray at its point nearest the cone's middle, so far-away origins keep their digits.
    const double t_shift = glm::dot(0.5 * (cone.base + cone.apex) - ray.origin, ray.direction) /
                           glm::dot(ray.direction, ray.direction);
    const Vec3 w = ray.origin + t_shift * ray.direction - cone.base;
    // Split the start point and the direction into heights along a and parts across it.
    const double w_a = glm::dot(w, a), d_a = glm::dot(ray.direction, a);
    const Vec3 w_perp = w - w_a * a, d_perp = ray.direction - d_a * a;
    // |w_perp + t d_perp|^2 = (r0 + slope d_a t)^2 with r0 = r(w_a):  A t^2 + 2 B t + C = 0.
    const double r0 = cone.base_radius + slope * w_a;
    const double qa = glm::dot(d_perp, d_perp) - slope * slope * d_a * d_a;
    const double qb = glm::dot(w_perp, d_perp) - slope * d_a * r0;
    const double qc = glm::dot(w_perp, w_perp) - r0 * r0;
    double roots[2];
    if (qa == 0.0) {
        // Parallel to the axis of a cylinder (no hit) or to a line of the cone (one root).
        if (qb == 0.0) return std::nullopt;
        roots[0] = roots[1] = -qc / (2.0 * qb);
    } else {
        const double discriminant = qb * qb - qa * qc;
        if (discriminant < 0.0) return std::nullopt;
        // Stable roots: q = -(B + sign(B) sqrt(disc)), t = q / A and C / q.
        const double q = -(qb + std::copysign(std::sqrt(discriminant), qb));
        roots[0] = q / qa;
        roots[1] = q != 0.0 ? qc / q : roots[0];
        if (roots[0] > roots[1]) std::swap(roots[0], roots[1]);
    }
    for (const double root : roots) {
        const double t = root + t_shift;
        const double s = w_a + root * d_a;
        // Only the part of the surface between base and apex exists (this also drops the mirrored nappe).
        if (!t_range.surrounds(t) || s < 0.0 || s > length) continue;
        // Outward normal: the gradient of |p_perp|^2 - r(s)^2, i.e. p_perp - r(s) slope a.
        const Vec3 p_perp = w_perp + root * d_perp;
        Vec3 outward = p_perp - (cone.base_radius + slope * s) * slope * a;
        const double norm = glm::length(outward);
        // At the tip of a pointed cone the gradient vanishes: use the axis, pointing out of the tip.
        outward = norm > 0.0 ? outward / norm : (slope < 0.0 ? a : -a);
        return make_hit(ray, t, cone.inward ? -outward : outward);
    }
    return std::nullopt;
}

} // namespace whitted
