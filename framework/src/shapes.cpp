// Bounds of every shape, and the intersection routines for the shapes the
// framework provides itself (boxes and cones; lab 1 writes the others).
#include "whitted/primitive.hpp"

#include <cmath>
#include <stdexcept>

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

std::optional<Hit> intersect_cone(const Ray&, const Cone&, Interval) {
    throw std::logic_error("intersect_cone() is not implemented yet");
}

} // namespace whitted
