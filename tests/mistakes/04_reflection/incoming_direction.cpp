// Mistake: Passes the incoming direction -wo to mirror_direction() (as if it were ray.direction), so the reflected ray goes into the mirror.
// Symptom: Mirrors show what lies behind them (the background) instead of the reflected scene.
#include "whitted/labs.hpp"

namespace whitted {

Vec3 mirror_direction(const Vec3& wo, const Vec3& n) {
    // r = 2 (V . n) n - V
    return 2.0 * glm::dot(wo, n) * n - wo;
}

Color reflection(const Tracer& tracer, const Hit& hit, const Vec3& wo, int depth) {
    const Material& material = tracer.scene().material(hit);
    const Ray reflected = spawn_ray(hit, mirror_direction(-wo, hit.normal));
    // I(r) weighted by the specular reflection coefficient.
    return tracer.trace(reflected, depth + 1, RayKind::reflected, material.specular * material.specular_color);
}

} // namespace whitted
