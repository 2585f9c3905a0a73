#include "whitted/tracer.hpp"

#include "whitted/labs.hpp"

#include <utility>

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
    if (tree_) [[unlikely]]
        return trace_recorded(ray, depth, kind, weight);
    const Color parent_weight = path_weight_;
    const Color path_weight = parent_weight * weight;
    if (too_weak(kind, path_weight) || !within_budget()) return Color(0.0);
    stats_.count(kind);
    path_weight_ = path_weight;
    const Color color = shade(ray, depth);
    path_weight_ = parent_weight;
    return weight * color;
}

// trace() writing the ray into the tree: the same steps, in the same order.
Color Tracer::trace_recorded(const Ray& ray, int depth, RayKind kind, const Color& weight) const {
    const Color parent_weight = path_weight_;
    const Color path_weight = parent_weight * weight;
    const int node = record_ray(ray, Interval{}, depth, kind, weight);
    if (too_weak(kind, path_weight)) {
        tree_->nodes[node].fate = RayFate::below_min_weight;
        return Color(0.0);
    }
    if (!within_budget()) {
        tree_->nodes[node].fate = RayFate::over_budget;
        return Color(0.0);
    }
    stats_.count(kind);
    path_weight_ = path_weight;
    const int parent_node = std::exchange(current_node_, node);
    const Color color = shade(ray, depth);
    current_node_ = parent_node;
    path_weight_ = parent_weight;
    return tree_->nodes[node].color = weight * color;
}

// The recursion of the slides: closest hit, local colour, then secondary rays.
Color Tracer::shade(const Ray& ray, int depth) const {
    const std::optional<Hit> hit = scene_.closest_hit(ray);
    if (tree_) [[unlikely]]
        tree_->nodes[current_node_].hit = hit;
    if (!hit) return scene_.background();
    const Material& material = scene_.material(*hit);
    const Vec3 wo = -ray.direction;
    const auto reached = [stage = settings_.stage](Stage feature) { return stage >= stage_number(feature); };

    // Local colour: flat (ray casting), Lambert with shadows, then Blinn-Phong.
    if (!reached(Stage::shadows)) return noted(&RayNode::local, material.color_at(hit->point));
    Color color = noted(&RayNode::local, reached(Stage::blinn_phong) ? blinn_phong(*this, *hit, wo) : lambert(*this, *hit));
    if (!reached(Stage::reflection) || depth >= settings_.max_depth) return color;

    // Secondary rays, one level deeper.
    const bool transparent = material.transmittance > 0.0;
    if (reached(Stage::fresnel) && transparent) return color + noted(&RayNode::fresnel, fresnel_blend(*this, *hit, wo, depth));
    if (material.specular > 0.0) color += noted(&RayNode::reflection, reflection(*this, *hit, wo, depth));
    if (reached(Stage::refraction) && transparent) color += noted(&RayNode::refraction, refraction(*this, *hit, wo, depth));
    return color;
}

void Tracer::begin_pixel() const {
    path_weight_ = Color(1.0);
    pixel_rays_ = 0;
    pixel_cut_short_ = false;
}

Color Tracer::trace_pixel(double x, double y) const {
    begin_pixel();
    if (tree_) tree_->clear();
    current_node_ = -1;
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
    if (tree_) [[unlikely]]
        return occluded_recorded(ray, distance);
    if (!within_budget()) return true; // over budget: no more light is gathered for this pixel
    stats_.count(RayKind::shadow);
    return scene_.occluded(ray, Interval{0.0, distance * (1.0 - 1e-6)});
}

// occluded() writing the feeler into the tree.
bool Tracer::occluded_recorded(const Ray& ray, double distance) const {
    const Interval t_range{0.0, distance * (1.0 - 1e-6)};
    if (!within_budget()) {
        record_feeler(ray, t_range, distance, RayFate::over_budget, true);
        return true;
    }
    stats_.count(RayKind::shadow);
    const bool blocked = scene_.occluded(ray, t_range);
    record_feeler(ray, t_range, distance, RayFate::traced, blocked);
    return blocked;
}

int Tracer::record_ray(const Ray& ray, Interval t_range, int depth, RayKind kind, const Color& weight) const {
    RayNode node;
    node.kind = kind;
    node.depth = depth;
    node.parent = current_node_;
    node.ray = ray;
    node.t_range = t_range;
    node.weight = weight;
    node.path_weight = path_weight_ * weight;
    const int index = static_cast<int>(tree_->nodes.size());
    if (current_node_ >= 0) tree_->nodes[current_node_].children.push_back(index);
    tree_->nodes.push_back(std::move(node));
    return index;
}

void Tracer::record_feeler(const Ray& ray, Interval t_range, double distance, RayFate fate, bool blocked) const {
    const int depth = current_node_ >= 0 ? tree_->nodes[current_node_].depth : 1;
    RayNode& node = tree_->nodes[record_ray(ray, t_range, depth, RayKind::shadow, Color(1.0))];
    node.fate = fate;
    node.light_distance = distance;
    node.blocked = blocked;
    // Which surface is in the way, and where: the answer to "why is this point dark?".
    if (blocked && fate == RayFate::traced) node.hit = scene_.closest_hit(ray, t_range);
}

void Tracer::note(std::optional<Color> RayNode::*part, const Color& color) const {
    if (current_node_ >= 0) tree_->nodes[current_node_].*part = color;
}

} // namespace whitted
