// Mistake: spawn_ray moves the origin a fixed 1e-4 along the new direction instead of a tiny, scaled offset off the surface.
// Symptom: small gaps in contact shadows and, for rays into a surface, rays that start inside it; the SpawnRay tests report the offset and the distance to the far wall.
#include "whitted/labs.hpp"

namespace whitted {

// How far a new ray starts off the surface, relative to the size of the hit
// point's coordinates (rounding errors grow with them).
constexpr double kRelativeOffset = 1e-7;

Ray spawn_ray(const Hit& hit, const Vec3& direction) {
    // Move the origin off the surface along the geometric normal, to the side the
    // ray leaves towards. Unlike a minimum distance along the ray, this also works
    // for rays that leave at grazing angles, and for rays that go into the surface.
    return Ray{hit.point + 1e-4 * direction, direction};
}

bool is_lit(const Tracer& tracer, const Hit& hit, const PointLight& light) {
    const Vec3 to_light = light.position - hit.point;
    const double distance = glm::length(to_light);
    return !tracer.occluded(spawn_ray(hit, to_light / distance), distance);
}

Color lambert(const Tracer& tracer, const Hit& hit) {
    const Scene& scene = tracer.scene();
    const Material& material = scene.material(hit);
    const Color kd = material.diffuse * material.color_at(hit.point);
    Color color(0.0);
    for (const PointLight& light : scene.lights()) {
        const Vec3 wi = glm::normalize(light.position - hit.point);
        const double cos_theta = glm::dot(hit.normal, wi);
        // No shadow feeler towards a light behind the surface.
        if (cos_theta <= 0.0 || !is_lit(tracer, hit, light)) continue;
        color += light.color * kd * cos_theta;
    }
    return color;
}

} // namespace whitted
