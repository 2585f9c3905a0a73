// Mistake: Forgets the factor 2 in r = 2 (wo . n) n - wo, so the result is only the tangent part flipped: not unit length and at the wrong angle.
// Symptom: Reflections are squeezed towards the surface; the spot values and the unit-length check of MirrorDirection fail.
#include "whitted/labs.hpp"

namespace whitted {

Vec3 mirror_direction(const Vec3& wo, const Vec3& n) {
    // r = 2 (V . n) n - V
    return glm::dot(wo, n) * n - wo;
}

Color reflection(const Tracer& tracer, const Hit& hit, const Vec3& wo, int depth) {
    const Material& material = tracer.scene().material(hit);
    const Ray reflected = spawn_ray(hit, mirror_direction(wo, hit.normal));
    // I(r) weighted by the specular reflection coefficient.
    return tracer.trace(reflected, depth + 1, RayKind::reflected, material.specular * material.specular_color);
}

} // namespace whitted
