// Mistake: Traces the reflected ray with weight 1 instead of Ks x specular colour.
// Symptom: Every reflective surface is a perfect, colourless mirror and pictures get too bright; weights in the Reflection tests are wrong.
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
    return tracer.trace(reflected, depth + 1, RayKind::reflected, Color(1.0));
}

} // namespace whitted
