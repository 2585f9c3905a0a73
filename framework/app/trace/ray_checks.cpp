// The physics checks next to each ray of `whitted trace`, computed by the
// framework on its own (not by the labs' code), so that they can disagree.
#include "trace/ray_tree_report.hpp"

#include <cmath>
#include <filesystem>
#include <tuple>
#include <utility>
#include <type_traits>
#include <variant>

namespace whitted {
namespace {

double degrees_between(const Vec3& a, const Vec3& b) {
    const double length = glm::length(a) * glm::length(b);
    if (!(length > 0.0)) return 0.0;
    return std::acos(glm::clamp(glm::dot(a, b) / length, -1.0, 1.0)) * 180.0 / kPi;
}

// The indices of refraction on the incoming side and on the far side of a hit:
// air (1) outside, the material's inside.
std::pair<double, double> indices_at(const Hit& hit, const Material& material) {
    return hit.front_face ? std::pair{1.0, material.ior} : std::pair{material.ior, 1.0};
}

} // namespace

std::string object_name(const TraceContext& context, std::uint32_t primitive) {
    const Primitive& p = context.scene.primitives()[primitive];
    const char* shape = std::visit(
        [](const auto& s) -> const char* {
            using S = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<S, Sphere>) return "sphere";
            else if constexpr (std::is_same_v<S, Plane>) return "plane";
            else if constexpr (std::is_same_v<S, Triangle>) return "triangle";
            else if constexpr (std::is_same_v<S, Box>) return "box";
            else return "cone";
        },
        p.shape);
    if (p.line == 0) return std::string(shape) + " #" + std::to_string(p.index);
    return std::string(shape) + " (" + std::filesystem::path(context.scene_path).filename().string() + ":" +
           std::to_string(p.line) + ")";
}

std::optional<DirectionCheck> check_direction(const RayTree& tree, int index, const TraceContext& context) {
    const RayNode& node = tree.nodes[index];
    if ((node.kind != RayKind::reflected && node.kind != RayKind::refracted) || node.parent < 0) return std::nullopt;
    const RayNode& parent = tree.nodes[node.parent];
    if (!parent.hit) return std::nullopt;
    const Hit& hit = *parent.hit;
    const Vec3 wo = -glm::normalize(parent.ray.direction); // the report flags a direction that is not unit length
    const Vec3& n = hit.normal;
    const double cos_theta_i = glm::dot(wo, n);
    DirectionCheck check;
    check.theta_i = degrees_between(wo, n);
    if (node.kind == RayKind::reflected) {
        check.law = "mirror law";
        check.theta_out = degrees_between(node.ray.direction, n);
        check.expected = 2.0 * cos_theta_i * n - wo;
        check.theta_expected = degrees_between(*check.expected, n);
    } else {
        // Snell's law, sin(theta_t) = eta_i / eta_t sin(theta_i), in vector form.
        const Material& material = context.scene.material(hit);
        check.law = "Snell's law";
        std::tie(check.eta_i, check.eta_t) = indices_at(hit, material);
        check.theta_out = degrees_between(node.ray.direction, -n);
        const double eta = check.eta_i / check.eta_t;
        const double sin2_theta_t = eta * eta * std::max(0.0, 1.0 - cos_theta_i * cos_theta_i);
        if (sin2_theta_t <= 1.0)
            check.expected = glm::normalize(eta * (cos_theta_i * n - wo) - std::sqrt(1.0 - sin2_theta_t) * n);
        if (check.expected) check.theta_expected = degrees_between(*check.expected, -n);
    }
    if (check.expected) {
        check.off_degrees = degrees_between(node.ray.direction, *check.expected);
        check.agrees = check.off_degrees < 0.01;
    }
    return check;
}

std::optional<MissingRefraction> check_missing_refraction(const RayTree& tree, int index, const TraceContext& context) {
    const RayNode& node = tree.nodes[index];
    const RenderSettings& settings = context.settings;
    if (!node.hit || settings.stage < stage_number(Stage::refraction) || node.depth >= settings.max_depth) return std::nullopt;
    const Material& material = context.scene.material(*node.hit);
    if (material.transmittance <= 0.0) return std::nullopt;
    for (int child : node.children)
        if (tree.nodes[child].kind == RayKind::refracted) return std::nullopt;
    MissingRefraction missing;
    std::tie(missing.eta_i, missing.eta_t) = indices_at(*node.hit, material);
    const double cos_theta_i = glm::dot(-glm::normalize(node.ray.direction), node.hit->normal);
    missing.sin_theta_t =
        missing.eta_i / missing.eta_t * std::sqrt(std::max(0.0, 1.0 - cos_theta_i * cos_theta_i));
    return missing;
}

bool blocked_by_own_surface(const RayTree& tree, int index, const TraceContext& context) {
    const RayNode& node = tree.nodes[index];
    if (node.parent < 0 || !tree.nodes[node.parent].hit) return false;
    return hits_its_own_surface(context.scene, *tree.nodes[node.parent].hit, node);
}

} // namespace whitted
