// Lab 5 — refraction: Snell's law, total internal reflection, entering and leaving.
#include "whitted/labs.hpp"

#include <cmath>

namespace whitted {

std::optional<Vec3> refracted_direction(const Vec3& wo, const Vec3& n, double eta_i, double eta_t) {
    // vt = (V . n) n - V is the tangential part of -V, of length sin(theta_i).
    const double cos_theta_i = glm::dot(wo, n);
    const Vec3 vt = cos_theta_i * n - wo;
    // Snell: sin(theta_t) = eta_i / eta_t sin(theta_i).
    const double eta = eta_i / eta_t;
    const double sin2_theta_t = eta * eta * glm::max(0.0, 1.0 - cos_theta_i * cos_theta_i);
    if (sin2_theta_t >= 1.0) return std::nullopt; // total internal reflection, from the critical angle on
    const double cos_theta_t = std::sqrt(1.0 - sin2_theta_t);
    // rt = sin(theta_t) t + cos(theta_t) (-n), and sin(theta_t) t = eta vt.
    return glm::normalize(eta * vt - cos_theta_t * n);
}

Color refraction(const Tracer& tracer, const Hit& hit, const Vec3& wo, int depth) {
    const Material& material = tracer.scene().material(hit);
    // Entering through the outward side: from air into the material; else leaving it.
    const double eta_i = hit.front_face ? 1.0 : material.ior;
    const double eta_t = hit.front_face ? material.ior : 1.0;
    const std::optional<Vec3> wt = refracted_direction(wo, hit.normal, eta_i, eta_t);
    if (!wt) return Color(0.0); // total internal reflection: nothing is transmitted
    // I(t) weighted by the transmittance.
    return tracer.trace(spawn_ray(hit, *wt), depth + 1, RayKind::refracted, Color(material.transmittance));
}

} // namespace whitted
