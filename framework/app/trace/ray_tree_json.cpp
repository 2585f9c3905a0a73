// The ray tree as JSON: one object per ray, its children nested inside.
#include "trace/ray_tree_report.hpp"

namespace whitted {
namespace {

using nlohmann::json;

// Numbers that are not finite become null, as JSON has no NaN.
json json_number(double value) { return std::isfinite(value) ? json(value + 0.0) : json(nullptr); }
json json_vec(const Vec3& v) { return json::array({json_number(v.x), json_number(v.y), json_number(v.z)}); }

const char* json_kind(RayKind kind) {
    switch (kind) {
    case RayKind::eye: return "eye";
    case RayKind::shadow: return "shadow";
    case RayKind::reflected: return "reflected";
    case RayKind::refracted: return "refracted";
    }
    return "eye";
}

const char* fate_name(RayFate fate) {
    switch (fate) {
    case RayFate::traced: return "traced";
    case RayFate::below_min_weight: return "below_min_weight";
    case RayFate::over_budget: return "over_budget";
    }
    return "traced";
}

json hit_json(const Hit& hit, const TraceContext& context) {
    return {{"object", object_name(context, hit.primitive)},
            {"line", context.scene.primitives()[hit.primitive].line},
            {"t", json_number(hit.t)},
            {"point", json_vec(hit.point)},
            {"normal", json_vec(hit.normal)},
            {"front_face", hit.front_face}};
}

json node_json(const RayTree& tree, int index, const TraceContext& context) {
    const RayNode& node = tree.nodes[index];
    json j = {{"kind", json_kind(node.kind)},
              {"depth", node.depth},
              {"origin", json_vec(node.ray.origin)},
              {"direction", json_vec(node.ray.direction)},
              {"weight", json_vec(node.weight)},
              {"path_weight", json_vec(node.path_weight)},
              {"fate", fate_name(node.fate)}};
    if (node.hit) j[node.kind == RayKind::shadow ? "blocker" : "hit"] = hit_json(*node.hit, context);
    if (node.kind == RayKind::shadow) {
        j["light_distance"] = json_number(node.light_distance);
        j["blocked"] = node.blocked;
        j["blocked_by_own_surface"] = blocked_by_own_surface(tree, index, context);
    } else {
        if (node.local) j["local"] = json_vec(*node.local);
        if (node.reflection) j["reflection"] = json_vec(*node.reflection);
        if (node.refraction) j["refraction"] = json_vec(*node.refraction);
        if (node.fresnel) j["fresnel"] = json_vec(*node.fresnel);
        j["color"] = json_vec(node.color);
    }
    if (const std::optional<DirectionCheck> check = check_direction(tree, index, context)) {
        j["check"] = {{"law", check->law},
                      {"theta_i_degrees", json_number(check->theta_i)},
                      {"theta_out_degrees", json_number(check->theta_out)},
                      {"expected_direction", check->expected ? json_vec(*check->expected) : json(nullptr)},
                      {"off_degrees", json_number(check->off_degrees)},
                      {"agrees", check->agrees}};
        if (node.kind == RayKind::refracted) j["check"]["eta_i"] = check->eta_i, j["check"]["eta_t"] = check->eta_t;
    }
    json children = json::array();
    for (int child : node.children) children.push_back(node_json(tree, child, context));
    j["children"] = std::move(children);
    return j;
}

} // namespace

json ray_tree_json(const RayTree& tree, const TraceContext& context) {
    json j = {{"scene", context.scene_path},
              {"pixel", {context.x, context.y}},
              {"width", context.width},
              {"height", context.height},
              {"stage", context.settings.stage},
              {"max_depth", context.settings.max_depth},
              {"min_weight", context.settings.min_weight},
              {"color", json_vec(tree.nodes.front().color)},
              {"ray", node_json(tree, 0, context)}};
    // A pixel of several samples: "color" and "ray" are sample `index`'s; "pixel_color" is the pixel's value.
    if (const std::optional<ShownSample>& sample = context.sample)
        j["sample"] = {{"index", sample->index},
                       {"count", sample->count},
                       {"place", {json_number(sample->place.x), json_number(sample->place.y)}},
                       {"pixel_color", json_vec(sample->pixel)}};
    return j;
}

} // namespace whitted
