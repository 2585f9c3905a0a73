#include "whitted/tracer.hpp"

#include "whitted/labs.hpp"

namespace whitted {

RayStats& RayStats::operator+=(const RayStats& other) {
    eye += other.eye;
    shadow += other.shadow;
    reflected += other.reflected;
    refracted += other.refracted;
    pixels_cut_short += other.pixels_cut_short;
    return *this;
}

void RayStats::count(RayKind kind) {
    switch (kind) {
    case RayKind::eye: ++eye; break;
    case RayKind::shadow: ++shadow; break;
    case RayKind::reflected: ++reflected; break;
    case RayKind::refracted: ++refracted; break;
    }
}

Color Tracer::trace(const Ray& ray, int depth, RayKind kind, const Color& weight) const {
    const Color parent_weight = path_weight_;
    const Color path_weight = parent_weight * weight;
    if (kind != RayKind::eye && glm::all(glm::lessThan(path_weight, Color(settings_.min_weight)))) return Color(0.0);
    if (!within_budget()) return Color(0.0);
    stats_.count(kind);
    path_weight_ = path_weight;
    const Color color = shade(ray, depth);
    path_weight_ = parent_weight;
    return weight * color;
}

// The recursion of the slides: closest hit, local colour, then secondary rays.
Color Tracer::shade(const Ray& ray, int depth) const {
    const std::optional<Hit> hit = scene_.closest_hit(ray);
    if (!hit) return scene_.background();
    const Material& material = scene_.material(*hit);
    const Vec3 wo = -ray.direction;
    const int stage = settings_.stage;

    // Local colour: flat (lab 1), Lambert with shadows (lab 2), Blinn-Phong (lab 3 on).
    if (stage == 1) return material.color_at(hit->point);
    Color color = stage == 2 ? lambert(*this, *hit) : blinn_phong(*this, *hit, wo);
    if (stage < 4 || depth >= settings_.max_depth) return color;

    // Secondary rays, one level deeper.
    const bool transparent = material.transmittance > 0.0;
    if (stage >= 6 && transparent) return color + fresnel_blend(*this, *hit, wo, depth);
    if (material.specular > 0.0) color += reflection(*this, *hit, wo, depth);
    if (stage >= 5 && transparent) color += refraction(*this, *hit, wo, depth);
    return color;
}

Color Tracer::trace_pixel(double x, double y) const {
    path_weight_ = Color(1.0);
    pixel_rays_ = 0;
    pixel_cut_short_ = false;
    const Color color = trace(primary_ray(scene_.camera(), x, y), 1, RayKind::eye, Color(1.0));
    if (pixel_cut_short_) ++stats_.pixels_cut_short;
    return color;
}

bool Tracer::within_budget() const {
    if (++pixel_rays_ <= settings_.max_rays_per_pixel) return true;
    pixel_cut_short_ = true;
    return false;
}

bool Tracer::occluded(const Ray& ray, double distance) const {
    if (!within_budget()) return true; // over budget: no more light is gathered for this pixel
    stats_.count(RayKind::shadow);
    return scene_.occluded(ray, Interval{0.0, distance * (1.0 - 1e-6)});
}

} // namespace whitted
