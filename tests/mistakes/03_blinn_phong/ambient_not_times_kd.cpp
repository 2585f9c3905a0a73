// Mistake: blinn_phong adds the ambient light itself, without multiplying it by kd.
// Symptom: shadows are grey whatever the surface colour; the test without lights finds Ia instead of Ia kd.
#include "whitted/labs.hpp"

#include <cmath>

namespace whitted {

Color blinn_phong(const Tracer& tracer, const Hit& hit, const Vec3& wo) {
    const Scene& scene = tracer.scene();
    const Material& material = scene.material(hit);
    const Color kd = material.diffuse * material.color_at(hit.point);
    const Color ks = material.specular * material.specular_color;
    // I = I_a kd + sum over lights of f_s (I_l kd (n . L) + I_l ks (h . n)^shininess)
    Color color = scene.ambient();
    for (const PointLight& light : scene.lights()) {
        const Vec3 wi = glm::normalize(light.position - hit.point);
        const double cos_theta = glm::dot(hit.normal, wi);
        if (cos_theta <= 0.0 || !is_lit(tracer, hit, light)) continue;
        const Vec3 halfway = glm::normalize(wi + wo);
        const double highlight = std::pow(glm::max(glm::dot(halfway, hit.normal), 0.0), material.shininess);
        color += light.color * (kd * cos_theta + ks * highlight);
    }
    return color;
}

} // namespace whitted
