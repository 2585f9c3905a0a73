// Mistake: Always uses air -> material (eta_i = 1, eta_t = ior), ignoring hit.front_face, so the inside of glass never reflects totally.
// Symptom: Glass spheres lose the bright total-internal-reflection ring and their inside looks wrong.
#include "whitted/labs.hpp"

#include <cmath>

namespace whitted {

double fresnel_reflectance(double cos_theta_i, double eta_i, double eta_t) {
    const double sin_theta_t = eta_i / eta_t * std::sqrt(glm::max(0.0, 1.0 - cos_theta_i * cos_theta_i));
    if (sin_theta_t >= 1.0) return 1.0; // total internal reflection
    const double cos_theta_t = std::sqrt(1.0 - sin_theta_t * sin_theta_t);
    // Rs and Rp: reflectance of light polarised perpendicular and parallel to the plane of incidence.
    const double rs = (eta_i * cos_theta_i - eta_t * cos_theta_t) / (eta_i * cos_theta_i + eta_t * cos_theta_t);
    const double rp = (eta_i * cos_theta_t - eta_t * cos_theta_i) / (eta_i * cos_theta_t + eta_t * cos_theta_i);
    return 0.5 * (rs * rs + rp * rp);
}

Color fresnel_blend(const Tracer& tracer, const Hit& hit, const Vec3& wo, int depth) {
    const Material& material = tracer.scene().material(hit);
    const double eta_i = 1.0;
    const double eta_t = material.ior;
    const double kr = fresnel_reflectance(glm::dot(wo, hit.normal), eta_i, eta_t);
    // kr I(r) + (1 - kr) T I(t)
    const Ray reflected = spawn_ray(hit, mirror_direction(wo, hit.normal));
    Color color = tracer.trace(reflected, depth + 1, RayKind::reflected, Color(kr));
    if (kr < 1.0) {
        if (const std::optional<Vec3> wt = refracted_direction(wo, hit.normal, eta_i, eta_t)) {
            const Color weight((1.0 - kr) * material.transmittance);
            color += tracer.trace(spawn_ray(hit, *wt), depth + 1, RayKind::refracted, weight);
        }
    }
    return color;
}

} // namespace whitted
