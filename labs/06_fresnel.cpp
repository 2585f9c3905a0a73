// Lab 6 — Fresnel: how much light a glass surface reflects and how much it lets
// through, depending on the angle.
// Handout: docs/labs/06_fresnel.md. Tests: make test LAB=6
#include "whitted/labs.hpp"

namespace whitted {

// The reflectance Kr = (Rs + Rp) / 2 of unpolarised light arriving at an angle
// with cosine cos_theta_i (> 0) from index eta_i onto index eta_t; 1 on total
// internal reflection.
double fresnel_reflectance(double cos_theta_i, double eta_i, double eta_t) {
    not_implemented();
}

// The light a transparent surface sends towards wo: Kr x (reflected light) +
// (1 - Kr) x T x (refracted light), with one ray traced in each direction
// (weights Kr and (1 - Kr) T). Here T is material.transmittance; the slides'
// "T = 1 - Kr" is the (1 - Kr) factor. On total internal reflection everything
// is reflected.
Color fresnel_blend(const Tracer& tracer, const Hit& hit, const Vec3& wo, int depth) {
    not_implemented();
}

} // namespace whitted
