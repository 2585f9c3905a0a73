// The reference renderer's leaf kernels: the BVH walk with hit distances only
// inlined into it, with the same
// arithmetic, operation for operation, as the reference labs (solution/01 for
// spheres, planes and triangles; the framework's boxes and cones), so that the
// nearest primitive and its distance come out bit for bit the same.
//
// Why here and not in framework/: these are the answers to lab 1, and the
// student handout ships framework/ but not solution/.
#include "whitted/engine/leaf_kernels.hpp"

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
    const std::optional<Hit> hit = std::holds_alternative<Box>(shape) ? intersect_box(ray, std::get<Box>(shape), t_range)
                                                                      : intersect_cone(ray, std::get<Cone>(shape), t_range);
    return hit ? hit->t : kMiss;
}

// The scene's closest-hit query: planes first (a hit there shortens the range
// the BVH must search), then the BVH, leaves tested in order.
std::optional<std::uint32_t> closest(const SceneView& scene, const Ray& ray, Interval t_range) {
    std::optional<std::uint32_t> nearest;
    for (std::size_t i = scene.bounded_count; i < scene.primitives.size(); ++i) {
        if (const double t = distance(ray, scene.primitives[i], t_range); t != kMiss) {
            t_range.max = t;
            nearest = static_cast<std::uint32_t>(i);
        }
    }
    scene.bvh.traverse(ray, t_range.min, t_range.max, [&](std::uint32_t first, std::uint32_t count, double t_max) {
        const Interval leaf_range{t_range.min, t_max};
        double nearest_t = t_max;
        for (std::uint32_t i = first; i < first + count; ++i) {
            if (const double t = distance(ray, scene.primitives[i], Interval{leaf_range.min, nearest_t}); t != kMiss) {
                nearest_t = t;
                nearest = i;
            }
        }
        return nearest_t;
    });
    return nearest;
}

// The scene's occlusion query: any hit will do, so the first one ends it.
bool occluded(const SceneView& scene, const Ray& ray, Interval t_range) {
    for (std::size_t i = scene.bounded_count; i < scene.primitives.size(); ++i)
        if (distance(ray, scene.primitives[i], t_range) != kMiss) return true;
    bool blocked = false;
    scene.bvh.traverse<false>(ray, t_range.min, t_range.max, [&](std::uint32_t first, std::uint32_t count, double t_max) {
        for (std::uint32_t i = first; i < first + count; ++i) {
            if (distance(ray, scene.primitives[i], Interval{t_range.min, t_max}) != kMiss) {
                blocked = true;
                return -1.0;
            }
        }
        return t_max;
    });
    return blocked;
}

constexpr LeafKernels kReferenceKernels{closest, occluded};

} // namespace

const LeafKernels* linked_leaf_kernels() { return &kReferenceKernels; }

} // namespace whitted
