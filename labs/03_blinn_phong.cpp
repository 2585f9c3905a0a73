// Lab 3 — the Blinn-Phong reflection model with ambient light and several
// coloured lights.
// Handout: docs/labs/03_blinn_phong.md. Tests: make test LAB=3
#include "whitted/labs.hpp"

namespace whitted {

// Ambient + sum over the lights that reach the hit point of diffuse + specular:
//   I = I_ambient x kd + sum f_s (I_light x kd (n . L) + I_light x ks (h . n)^shininess)
// with kd = material.diffuse * material.color_at(point),
//      ks = material.specular * material.specular_color,
//      h  = the halfway vector between L and wo, f_s = 0 in shadow, 1 otherwise,
// and the lights tracer.lights().
Color blinn_phong(const Tracer& tracer, const Hit& hit, const Vec3& wo) {
    not_implemented();
}

} // namespace whitted
