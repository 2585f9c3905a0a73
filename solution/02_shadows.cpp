// Lab 2 — shadows: robust secondary rays, shadow feelers and Lambert diffuse light.
#include "whitted/labs.hpp"

namespace whitted {

// How far a new ray starts off the surface, relative to the size of the hit
// point's coordinates (rounding errors grow with them).
constexpr double kRelativeOffset = 1e-7;

Ray spawn_ray(const Hit& hit, const Vec3& direction) {
    // Move the origin off the surface along the geometric normal, to the side the
    // ray leaves towards. Unlike a minimum distance along the ray, this also works
    // for rays that leave at grazing angles, and for rays that go into the surface.
    const double offset = kRelativeOffset * (1.0 + max_abs_component(hit.point));
    const Vec3 side = glm::dot(direction, hit.geometric_normal) >= 0.0 ? hit.geometric_normal : -hit.geometric_normal;
    return Ray{hit.point + offset * side, direction};
}

bool is_lit(const Tracer& tracer, const Hit& hit, const PointLight& light) {
    const Vec3 to_light = light.position - hit.point;
    const double distance = glm::length(to_light);
    if (distance == 0.0) return false; // a light on the surface itself lights nothing
    return !tracer.occluded(spawn_ray(hit, to_light / distance), distance);
}

Color lambert(const Tracer& tracer, const Hit& hit) {
    const Scene& scene = tracer.scene();
    const Material& material = scene.material(hit);
    const Color kd = material.diffuse * material.color_at(hit.point);
    Color color(0.0);
    for (const PointLight& light : tracer.lights()) {
        const Vec3 to_light = light.position - hit.point;
        if (to_light == Vec3(0.0)) continue; // a light on the surface itself lights nothing
        const Vec3 wi = glm::normalize(to_light);
        const double cos_theta = glm::dot(hit.normal, wi);
        // No shadow feeler towards a light behind the surface.
        if (cos_theta <= 0.0 || !is_lit(tracer, hit, light)) continue;
        color += light.color * kd * cos_theta;
    }
    return color;
}

} // namespace whitted
