// Lab 6 — Fresnel: how much a dielectric reflects and how much it transmits.
#include "whitted/labs.hpp"

#include <cmath>

namespace whitted {

double fresnel_reflectance(double cos_theta_i, double eta_i, double eta_t) {
    cos_theta_i = glm::clamp(cos_theta_i, 0.0, 1.0); // rounding may push a unit dot product past 1
    const double eta = eta_i / eta_t;
    const double sin2_theta_t = eta * eta * glm::max(0.0, 1.0 - cos_theta_i * cos_theta_i);
    if (sin2_theta_t >= 1.0) return 1.0; // total internal reflection, from the critical angle on (as in lab 5)
    const double cos_theta_t = std::sqrt(1.0 - sin2_theta_t);
    // Rs and Rp: reflectance of light polarised perpendicular and parallel to the plane of incidence.
    const double rs = (eta_i * cos_theta_i - eta_t * cos_theta_t) / (eta_i * cos_theta_i + eta_t * cos_theta_t);
    const double rp = (eta_i * cos_theta_t - eta_t * cos_theta_i) / (eta_i * cos_theta_t + eta_t * cos_theta_i);
    return 0.5 * (rs * rs + rp * rp);
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
