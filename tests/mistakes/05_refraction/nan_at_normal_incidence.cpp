// Mistake: Normalises vt to get the tangent t, which divides by zero when the ray hits the surface head-on.
// Symptom: A NaN direction for rays at exactly normal incidence: a magenta pixel or line where a glass object faces the camera.
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
    if (sin2_theta_t > 1.0) return std::nullopt; // total internal reflection
    const double sin_theta_t = std::sqrt(sin2_theta_t);
    const double cos_theta_t = std::sqrt(1.0 - sin2_theta_t);
    // rt = sin(theta_t) t + cos(theta_t) (-n), and sin(theta_t) t = eta vt.
    const Vec3 t = vt / glm::length(vt);
    return sin_theta_t * t - cos_theta_t * n;
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
