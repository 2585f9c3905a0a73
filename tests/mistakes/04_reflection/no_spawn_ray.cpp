// Mistake: Starts the reflected ray exactly at hit.point instead of using spawn_ray(), so rounding errors let it hit the mirror it starts on.
// Symptom: Speckles (acne) in mirrors, worst far from the origin; the self-intersection test counts extra reflected rays.
#include "whitted/labs.hpp"

namespace whitted {

Vec3 mirror_direction(const Vec3& wo, const Vec3& n) {
    // r = 2 (V . n) n - V
    return 2.0 * glm::dot(wo, n) * n - wo;
}

Color reflection(const Tracer& tracer, const Hit& hit, const Vec3& wo, int depth) {
    const Material& material = tracer.scene().material(hit);
    const Ray reflected{hit.point, mirror_direction(wo, hit.normal)};
    // I(r) weighted by the specular reflection coefficient.
    return tracer.trace(reflected, depth + 1, RayKind::reflected, material.specular * material.specular_color);
}

} // namespace whitted
