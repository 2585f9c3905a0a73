#include "whitted/labs.hpp"
#include "whitted/primitive.hpp"

#include "lab_call.hpp"

#include <type_traits>

namespace whitted {

std::optional<Hit> intersect(const Ray& ray, const Primitive& primitive, Interval t_range) {
    // The one place that dispatches on the kind of shape.
    std::optional<Hit> hit = std::visit(
        [&](const auto& shape) -> std::optional<Hit> {
            using T = std::decay_t<decltype(shape)>;
            using detail::call_lab;
            if constexpr (std::is_same_v<T, Sphere>) return call_lab("intersect_sphere", intersect_sphere, ray, shape, t_range);
            else if constexpr (std::is_same_v<T, Plane>) return call_lab("intersect_plane", intersect_plane, ray, shape, t_range);
            else if constexpr (std::is_same_v<T, Triangle>) return call_lab("intersect_triangle", intersect_triangle, ray, shape, t_range);
            else if constexpr (std::is_same_v<T, Box>) return intersect_box(ray, shape, t_range);
            else return intersect_cone(ray, shape, t_range);
        },
        primitive.shape);
    if (hit) {
        hit->primitive = primitive.index;
        hit->material = primitive.material;
    }
    return hit;
}

} // namespace whitted
