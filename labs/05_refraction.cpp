// Lab 5 — refraction: Snell's law, total internal reflection, and rays that
// enter or leave a transparent object.
// Handout: docs/labs/05_refraction.md. Tests: make test LAB=5
#include "whitted/labs.hpp"

namespace whitted {

// The direction of the ray refracted through a surface with unit normal n (on
// the side of wo), going from index eta_i into index eta_t (Snell's law), or
// no direction (std::nullopt) on total internal reflection.
std::optional<Vec3> refracted_direction(const Vec3& wo, const Vec3& n, double eta_i, double eta_t) {
    not_implemented();
}

// The light refracted through a transparent surface: trace the refracted ray
// one level deeper with weight material.transmittance (RayKind::refracted).
// hit.front_face tells whether the ray enters the material (air -> material.ior)
// or leaves it (material.ior -> air). Total internal reflection gives black.
Color refraction(const Tracer& tracer, const Hit& hit, const Vec3& wo, int depth) {
    not_implemented();
}

} // namespace whitted
