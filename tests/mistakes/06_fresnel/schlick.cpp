// Mistake: Uses Schlick's approximation R0 + (1 - R0) (1 - cos)^5 instead of the exact Fresnel equations the lab asks for.
// Symptom: Right at normal incidence (0.04) but too reflective at grazing angles: 0.409910 instead of 0.387704 at 80 degrees.
#include "whitted/labs.hpp"

#include <cmath>

namespace whitted {

double fresnel_reflectance(double cos_theta_i, double eta_i, double eta_t) {
    const double sin_theta_t = eta_i / eta_t * std::sqrt(glm::max(0.0, 1.0 - cos_theta_i * cos_theta_i));
    if (sin_theta_t >= 1.0) return 1.0; // total internal reflection
    // Schlick: R0 + (1 - R0) (1 - cos(theta))^5, with the angle on the denser side.
    const double r0 = (eta_i - eta_t) * (eta_i - eta_t) / ((eta_i + eta_t) * (eta_i + eta_t));
    const double cos_theta = eta_i > eta_t ? std::sqrt(1.0 - sin_theta_t * sin_theta_t) : cos_theta_i;
    return r0 + (1.0 - r0) * std::pow(1.0 - cos_theta, 5.0);
}

Color fresnel_blend(const Tracer& tracer, const Hit& hit, const Vec3& wo, int depth) {
    const Material& material = tracer.scene().material(hit);
    const double eta_i = hit.front_face ? 1.0 : material.ior;
    const double eta_t = hit.front_face ? material.ior : 1.0;
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
