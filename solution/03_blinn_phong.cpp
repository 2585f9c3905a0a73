// Lab 3 — the Blinn-Phong reflection model with ambient light and shadows.
#include "whitted/labs.hpp"

#include <cmath>

namespace whitted {

Color blinn_phong(const Tracer& tracer, const Hit& hit, const Vec3& wo) {
    const Scene& scene = tracer.scene();
    const Material& material = scene.material(hit);
    const Color kd = material.diffuse * material.color_at(hit.point);
    const Color ks = material.specular * material.specular_color;
    // I = I_a kd + sum over lights of f_s (I_l kd (n . L) + I_l ks (h . n)^shininess)
    Color color = scene.ambient() * kd;
    for (const PointLight& light : tracer.lights()) {
        const Vec3 to_light = light.position - hit.point;
        if (to_light == Vec3(0.0)) continue; // a light on the surface itself lights nothing
        const Vec3 wi = glm::normalize(to_light);
        const double cos_theta = glm::dot(hit.normal, wi);
        if (cos_theta <= 0.0 || !is_lit(tracer, hit, light)) continue;
        // A material without highlights (ks = 0) skips pow(): ks times any finite power is 0 anyway,
        // and pow() is slow when the power underflows (shininess 100000 on SPD scenes' matte floors).
        const Vec3 halfway = glm::normalize(wi + wo);
        const double highlight = ks == Color(0.0) ? 0.0 : std::pow(glm::max(glm::dot(halfway, hit.normal), 0.0), material.shininess);
        color += light.color * (kd * cos_theta + ks * highlight);
    }
    return color;
}

} // namespace whitted
