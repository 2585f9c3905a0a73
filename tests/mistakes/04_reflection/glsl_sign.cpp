// Mistake: Uses GLSL's reflect() convention wo - 2 (wo . n) n, which expects the incoming direction, so the mirror direction points into the surface.
// Symptom: Mirrors show the background (or whatever lies behind them) instead of the scene; MirrorDirection tests see r . n < 0.
#include "whitted/labs.hpp"

namespace whitted {

Vec3 mirror_direction(const Vec3& wo, const Vec3& n) {
    // r = 2 (V . n) n - V
    return wo - 2.0 * glm::dot(wo, n) * n;
}

Color reflection(const Tracer& tracer, const Hit& hit, const Vec3& wo, int depth) {
    const Material& material = tracer.scene().material(hit);
    const Ray reflected = spawn_ray(hit, mirror_direction(wo, hit.normal));
    // I(r) weighted by the specular reflection coefficient.
    return tracer.trace(reflected, depth + 1, RayKind::reflected, material.specular * material.specular_color);
}

} // namespace whitted
