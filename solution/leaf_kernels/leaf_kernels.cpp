// The reference renderer's leaf kernels: the BVH walk with hit distances only.
// Spheres, planes and triangles go through the reference lab 1's own distance
// functions (whitted/engine/hit_distances.hpp, defined in solution/01), boxes and
// cones through the framework's intersections, so the nearest primitive and its
// distance are the labs' own, bit for bit, by construction.
//
// Why here and not in framework/: these are the answers to lab 1, and the
// student handout ships framework/ but not solution/.
#include "whitted/engine/leaf_kernels.hpp"
#include "whitted/engine/hit_distances.hpp"

#include <cmath>
#include <limits>

namespace whitted {
namespace {

// What distance() returns for "no hit in the range" (no valid t equals it:
// ranges are open, so even an infinite maximum excludes it).
constexpr double kMiss = std::numeric_limits<double>::infinity();

// The distance of the ray's hit with the primitive inside t_range, or kMiss.
inline double distance(const Ray& ray, const Primitive& primitive, Interval t_range) {
    const Shape& shape = primitive.shape;
    if (const auto* sphere = std::get_if<Sphere>(&shape)) return sphere_distance(ray, *sphere, t_range).value_or(kMiss);
    if (const auto* triangle = std::get_if<Triangle>(&shape)) {
        const std::optional<TriangleDistance> found = triangle_distance(ray, *triangle, t_range);
        return found ? found->t : kMiss;
    }
    if (const auto* plane = std::get_if<Plane>(&shape)) return plane_distance(ray, *plane, t_range).value_or(kMiss);
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
