#include "whitted/engine/remote_queries.hpp"
#include "whitted/labs.hpp"
#include "whitted/primitive.hpp"
#include "whitted/primitive_test_count.hpp"

#include "lab_call.hpp"

#include <type_traits>

namespace whitted {
namespace {

/// A box or cone: the framework's own shapes, tested by the other process of a grading worker.
template <class S>
std::optional<Hit> intersect_framework_shape(const Ray& ray, const S& shape, Interval t_range) {
    if (const RemoteSceneQueries* remote = remote_scene_queries(); remote && remote->intersect_shape) [[unlikely]]
        return remote->intersect_shape(ray, Shape{shape}, t_range);
    if constexpr (std::is_same_v<S, Box>) return intersect_box(ray, shape, t_range);
    else return intersect_cone(ray, shape, t_range);
}

} // namespace

std::optional<Hit> intersect(const Ray& ray, const Primitive& primitive, Interval t_range) {
    PrimitiveTestCount::note_test();
    // The one place that dispatches on the kind of shape.
    std::optional<Hit> hit = std::visit(
        [&](const auto& shape) -> std::optional<Hit> {
            using T = std::decay_t<decltype(shape)>;
            using detail::call_lab;
            if constexpr (std::is_same_v<T, Sphere>) return call_lab("intersect_sphere", intersect_sphere, ray, shape, t_range);
            else if constexpr (std::is_same_v<T, Plane>) return call_lab("intersect_plane", intersect_plane, ray, shape, t_range);
            else if constexpr (std::is_same_v<T, Triangle>) return call_lab("intersect_triangle", intersect_triangle, ray, shape, t_range);
            else return intersect_framework_shape(ray, shape, t_range);
        },
        primitive.shape);
    if (hit) {
        hit->primitive = primitive.index;
        hit->material = primitive.material;
    }
    return hit;
}

} // namespace whitted
