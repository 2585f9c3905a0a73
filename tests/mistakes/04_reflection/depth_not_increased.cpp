// Mistake: Traces the reflected ray at the same depth instead of depth + 1, so max_depth never stops the recursion.
// Symptom: Facing mirrors reflect until the weights fade (min_weight) or the stack overflows; ray counts per max_depth are wrong.
#include "whitted/labs.hpp"

namespace whitted {

Vec3 mirror_direction(const Vec3& wo, const Vec3& n) {
    // r = 2 (V . n) n - V
    return 2.0 * glm::dot(wo, n) * n - wo;
}

Color reflection(const Tracer& tracer, const Hit& hit, const Vec3& wo, int depth) {
    const Material& material = tracer.scene().material(hit);
    const Ray reflected = spawn_ray(hit, mirror_direction(wo, hit.normal));
    // I(r) weighted by the specular reflection coefficient.
    return tracer.trace(reflected, depth, RayKind::reflected, material.specular * material.specular_color);
}

} // namespace whitted
