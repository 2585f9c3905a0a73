#include "whitted/tracer.hpp"

#include "lab_call.hpp"
#include "tracer_engine.hpp"
#include "whitted/labs.hpp"

#include <cmath>
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

Tracer::Tracer(const Scene& scene, const RenderSettings& settings, RayStats& stats, RayTree* tree)
    : engine_(std::make_unique<Engine>(Engine{scene, settings, stats, tree})) {}
// A copy traces on its own: no answers or notes that point into the original.
Tracer::Tracer(const Tracer& other) : engine_(std::make_unique<Engine>(*other.engine_)) {
    engine_->ahead = nullptr;
    engine_->collecting_feelers = nullptr;
}
Tracer& Tracer::operator=(const Tracer& other) {
    if (this != &other) {
        Tracer copy(other);
        engine_ = std::move(copy.engine_);
    }
    return *this;
}
Tracer::~Tracer() = default;

const Scene& Tracer::scene() const { return engine_->scene; }
const RenderSettings& Tracer::settings() const { return engine_->settings; }
bool Tracer::records_tree() const { return engine_->tree != nullptr; }

TracerState Tracer::state() const {
    const Engine& e = *engine_;
    return {e.stats, e.path_weight, e.pixel_rays, e.pixel_cut_short, e.sample};
}

void Tracer::restore(const TracerState& state) const {
    Engine& e = *engine_;
    e.stats = state.stats;
    e.path_weight = state.path_weight;
    e.pixel_rays = state.pixel_rays;
    e.pixel_cut_short = state.pixel_cut_short;
    e.sample = state.sample;
}

const PixelSample& Tracer::pixel_sample() const { return engine_->sample; }

std::span<const PointLight> Tracer::lights() const {
    Engine& e = *engine_;
    if (e.scene.area_lights().empty()) return e.scene.point_lights(); // nothing to add: no copy
    // Sampled once a pixel sample: every hit of its ray tree sees the same points.
    const bool sampled = e.settings.stage >= stage_number(Stage::soft_shadows);
    if (e.lights_for && (!sampled || *e.lights_for == e.sample)) return e.lights;
    std::vector<PointLight> lights(e.scene.point_lights().begin(), e.scene.point_lights().end());
    for (const AreaLight& light : e.scene.area_lights()) {
        if (!sampled) {
            lights.push_back(PointLight{light.center, light.color});
            continue;
        }
        const std::vector<PointLight> points = detail::call_lab("light_samples", light_samples, *this, light);
        lights.insert(lights.end(), points.begin(), points.end());
    }
    e.lights = std::move(lights);
    e.lights_for = e.sample;
    return e.lights;
}

Color Tracer::trace(const Ray& ray, int depth, RayKind kind, const Color& weight) const {
    Engine& e = *engine_;
    if (e.forwarding) [[unlikely]]
        return e.forwarding->trace(*this, ray, depth, kind, weight);
    if (e.tree) [[unlikely]]
        return e.trace_recorded(*this, ray, depth, kind, weight);
    const Color parent_weight = e.path_weight;
    const Color path_weight = parent_weight * weight;
    if (e.too_weak(kind, path_weight) || !e.within_budget()) return Color(0.0);
    e.stats.count(kind);
    e.path_weight = path_weight;
    // (Engine::escaped_eye_ray() repeats these steps for an eye ray known to meet nothing.)
    const Color color = e.shade(*this, ray, depth);
    e.path_weight = parent_weight;
    return weight * color;
}

// trace() writing the ray into the tree: the same steps, in the same order.
Color Tracer::Engine::trace_recorded(const Tracer& tracer, const Ray& ray, int depth, RayKind kind, const Color& weight) {
    const Color parent_weight = path_weight;
    const Color weight_here = parent_weight * weight;
    const int node = record_ray(ray, Interval{}, depth, kind, weight);
    if (too_weak(kind, weight_here)) {
        tree->nodes[node].fate = RayFate::below_min_weight;
        return Color(0.0);
    }
    if (!within_budget()) {
        tree->nodes[node].fate = RayFate::over_budget;
        return Color(0.0);
    }
    stats.count(kind);
    path_weight = weight_here;
    const int parent_node = std::exchange(current_node, node);
    const Color color = shade(tracer, ray, depth);
    current_node = parent_node;
    path_weight = parent_weight;
    return tree->nodes[node].color = weight * color;
}

// The recursion of the slides: closest hit, local colour, then secondary rays.
Color Tracer::Engine::shade(const Tracer& tracer, const Ray& ray, int depth) {
    const std::optional<Hit> hit = closest_hit(ray, depth);
    if (tree) [[unlikely]]
        tree->nodes[current_node].hit = hit;
    if (!hit) return scene.background(ray.direction); // as escaped_eye_ray() for a pixel's escaping eye ray
    const Material& material = scene.material(*hit);
    const Vec3 wo = -ray.direction;
    const auto reached = [stage = settings.stage](Stage feature) { return stage >= stage_number(feature); };

    // Local colour: flat (ray casting), Lambert with shadows, then Blinn-Phong.
    if (!reached(Stage::shadows)) return noted(&RayNode::local, material.color_at(hit->point));
    feelers_sent = 0;
    std::optional<Color> local = local_ahead(ray, depth);
    if (!local) local = local_colour(tracer, *hit, wo);
    Color color = noted(&RayNode::local, *local);
    if (!reached(Stage::reflection) || depth >= settings.max_depth) return color;

    // Secondary rays, one level deeper.
    const bool transparent = material.transmittance > 0.0;
    if (reached(Stage::fresnel) && transparent)
        return color + noted(&RayNode::fresnel, detail::call_lab("fresnel_blend", fresnel_blend, tracer, *hit, wo, depth));
    if (material.specular > 0.0)
        color += noted(&RayNode::reflection, detail::call_lab("reflection", reflection, tracer, *hit, wo, depth));
    if (reached(Stage::refraction) && transparent)
        color += noted(&RayNode::refraction, detail::call_lab("refraction", refraction, tracer, *hit, wo, depth));
    return color;
}

Color Tracer::Engine::local_colour(const Tracer& tracer, const Hit& hit, const Vec3& wo) const {
    return settings.stage >= stage_number(Stage::blinn_phong) ? detail::call_lab("blinn_phong", blinn_phong, tracer, hit, wo)
                                                              : detail::call_lab("lambert", lambert, tracer, hit);
}

void Tracer::begin_pixel(const PixelSample& sample) const { engine_->begin_pixel(sample.x, sample.y, sample.index); }

Color Tracer::trace_pixel(double x, double y) const { return engine_->trace_sample(*this, pixel_at(x), pixel_at(y), 0, x, y); }

Color Tracer::trace_sample(const PixelSample& sample, double x, double y) const {
    if (engine_->forwarding) [[unlikely]]
        return engine_->forwarding->trace_sample(*this, sample, x, y);
    return engine_->trace_sample(*this, sample.x, sample.y, sample.index, x, y);
}

void Tracer::forward_to(const TraceForwarding* forwarding) { engine_->forwarding = forwarding; }

Color Tracer::Engine::trace_sample(const Tracer& tracer, int px, int py, int index, double x, double y) {
    begin_pixel(px, py, index);
    if (tree) tree->clear();
    current_node = -1;
    // The eye ray: through the pinhole, or from the sample's point of the thin lens
    // (lab 9) when the camera has an aperture; a pinhole camera's picture never changes.
    const Camera& camera = scene.camera();
    const bool lens = camera.aperture > 0.0 && settings.stage >= stage_number(Stage::depth_of_field);
    // (trace_pixels() made this very pinhole ray already, from the same x and y.)
    const Ray eye_ray = lens    ? detail::call_lab("thin_lens_ray", thin_lens_ray, camera, x, y, sample_numbers(sample, SampleUse::lens))
                        : ahead ? ahead->eye
                                : detail::call_lab("primary_ray", primary_ray, camera, x, y);
    const Color color = tracer.trace(eye_ray, 1, RayKind::eye, Color(1.0));
    if (pixel_cut_short) ++stats.pixels_cut_short;
    return color;
}

// What trace_sample() returns for a pixel whose pinhole eye ray trace_pixels()
// found to meet nothing, after begin_pixel(): the steps trace() and shade() take
// for that ray, without the calls (where most eye rays escape, the calls were a
// tenth of the render). One ray of the budget, counted, and 1 x the colour escaping rays see.
Color Tracer::Engine::escaped_eye_ray(const Ray& eye) {
    if (!within_budget()) {
        ++stats.pixels_cut_short;
        return Color(0.0);
    }
    stats.count(RayKind::eye);
    return Color(1.0) * scene.background(eye.direction);
}

bool Tracer::occluded(const Ray& ray, double distance) const {
    Engine& e = *engine_;
    if (e.collecting_feelers) { // trace_pixels() looking ahead: which feelers will this hit send?
        // Filled in place: a Feeler built aside and copied is read back in 16-byte
        // pieces from the narrower stores that wrote it, and the read waits. The
        // ray, just made by the lab, goes a vector at a time for the same reason
        // (a vector is written as 16 + 8 bytes, and a whole Ray read as 3 x 16).
        Engine::Feeler& feeler = e.collecting_feelers->emplace_back();
        static_assert(sizeof(Ray) == 2 * sizeof(Vec3), "a field added to Ray must be copied here too");
        feeler.ray.origin = ray.origin;
        feeler.ray.direction = ray.direction;
        feeler.distance = distance;
        return false;
    }
    if (e.tree) [[unlikely]]
        return e.occluded_recorded(ray, distance);
    if (!e.within_budget()) return true; // over budget: no more light is gathered for this pixel
    e.stats.count(RayKind::shadow);
    if (const std::optional<bool> blocked = e.blocked_ahead(ray, distance)) return *blocked;
    return e.scene.occluded(ray, feeler_range(distance), e.blockers[e.feelers_sent++ % Engine::kBlockerSlots]);
}

// occluded() writing the feeler into the tree.
bool Tracer::Engine::occluded_recorded(const Ray& ray, double distance) {
    const Interval t_range = feeler_range(distance);
    if (!within_budget()) {
        record_feeler(ray, t_range, distance, RayFate::over_budget, true);
        return true;
    }
    stats.count(RayKind::shadow);
    const bool blocked = scene.occluded(ray, t_range);
    record_feeler(ray, t_range, distance, RayFate::traced, blocked);
    return blocked;
}

int Tracer::Engine::record_ray(const Ray& ray, Interval t_range, int depth, RayKind kind, const Color& weight) {
    RayNode node;
    node.kind = kind;
    node.depth = depth;
    node.parent = current_node;
    node.ray = ray;
    node.t_range = t_range;
    node.weight = weight;
    node.path_weight = path_weight * weight;
    const int index = static_cast<int>(tree->nodes.size());
    if (current_node >= 0) tree->nodes[current_node].children.push_back(index);
    tree->nodes.push_back(std::move(node));
    return index;
}

void Tracer::Engine::record_feeler(const Ray& ray, Interval t_range, double distance, RayFate fate, bool blocked) {
    const int depth = current_node >= 0 ? tree->nodes[current_node].depth : 1;
    RayNode& node = tree->nodes[record_ray(ray, t_range, depth, RayKind::shadow, Color(1.0))];
    node.fate = fate;
    node.light_distance = distance;
    node.blocked = blocked;
    // Which surface is in the way, and where: the answer to "why is this point dark?".
    if (blocked && fate == RayFate::traced) node.hit = scene.closest_hit(ray, t_range);
}

} // namespace whitted
