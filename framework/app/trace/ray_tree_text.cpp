// The ray tree as indented text, one ray per branch, checks beside each ray.
#include "trace/ray_tree_report.hpp"

#include <cmath>
#include <cstdio>

namespace whitted {
namespace {

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value + 0.0);
    return text;
}

std::string vec(const Vec3& v) {
    char text[96];
    // + 0.0 turns -0 into 0: "-0" would only puzzle.
    std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g)", v.x + 0.0, v.y + 0.0, v.z + 0.0);
    return text;
}

const char* kind_phrase(RayKind kind) {
    switch (kind) {
    case RayKind::eye: return "eye ray";
    case RayKind::shadow: return "shadow feeler";
    case RayKind::reflected: return "reflected ray";
    case RayKind::refracted: return "refracted ray";
    }
    return "ray";
}

// The light a feeler goes to: the point light nearest the feeler's end, or the
// area light whose parallelogram holds it (a point lab 8 took on it).
std::string light_of(const Scene& scene, const RayNode& feeler) {
    const Point3 end = feeler.ray.at(feeler.light_distance);
    std::string name;
    double best_distance = kInfinity;
    for (std::size_t i = 0; i < scene.point_lights().size(); ++i) {
        const double d = glm::length(scene.point_lights()[i].position - end);
        if (d < best_distance) name = "light " + std::to_string(i + 1) + " at " + vec(scene.point_lights()[i].position), best_distance = d;
    }
    for (std::size_t i = 0; i < scene.area_lights().size(); ++i) {
        const AreaLight& light = scene.area_lights()[i];
        // The end's distance from the light's plane, and its place along the edges (in edge lengths from the centre).
        const Vec3 normal = glm::normalize(glm::cross(light.edge_u, light.edge_v));
        const Vec3 offset = end - light.center;
        const double along_u = glm::dot(offset, light.edge_u) / glm::dot(light.edge_u, light.edge_u);
        const double along_v = glm::dot(offset, light.edge_v) / glm::dot(light.edge_v, light.edge_v);
        const double d = std::abs(glm::dot(offset, normal));
        if (std::abs(along_u) <= 0.5 + 1e-6 && std::abs(along_v) <= 0.5 + 1e-6 && d < best_distance)
            name = "a point of area light " + std::to_string(i + 1) + " at " + vec(end), best_distance = d;
    }
    return name;
}

struct TextWriter {
    const RayTree& tree;
    const TraceContext& context;
    std::string out;

    void line(const std::string& prefix, const std::string& text) { out += prefix + text + "\n"; }

    std::string title(int index) const {
        const RayNode& node = tree.nodes[index];
        std::string text = kind_phrase(node.kind);
        if (node.kind == RayKind::shadow) {
            const std::string light = light_of(context.scene, node);
            if (light.empty()) return text + " (to no light of the scene)";
            text += " to " + light + ", " + number(node.light_distance) + " away: ";
            if (node.fate == RayFate::over_budget) return text + "not cast (the pixel's ray budget is used up)";
            if (!node.blocked) return text + "lit";
            text += "BLOCKED";
            if (node.hit) text += " by " + object_name(context, node.hit->primitive) + " at t " + number(node.hit->t);
            if (blocked_by_own_surface(tree, index, context))
                text += " -- its own surface: self-intersection (shadow acne, lab 2)";
            return text;
        }
        text += " (depth " + std::to_string(node.depth) + ")";
        if (node.kind != RayKind::eye) text += ", weight " + vec(node.weight);
        return text;
    }

    // Where a secondary ray starts: spawn_ray() should move it a tiny distance off the hit point.
    std::string origin(const RayNode& node) const {
        std::string text = "from " + vec(node.ray.origin);
        if (node.parent >= 0 && tree.nodes[node.parent].hit) {
            const Hit& hit = *tree.nodes[node.parent].hit;
            const double moved = glm::length(node.ray.origin - hit.point);
            text += moved == 0.0 ? " (exactly the hit point: not moved off the surface)"
                                 : " (" + number(moved) + " off the hit point, " +
                                       (glm::dot(node.ray.origin - hit.point, hit.geometric_normal) >= 0.0
                                            ? "on the incoming ray's side)"
                                            : "on the other side of the surface)");
        }
        return text;
    }

    void details(int index, const std::string& prefix) {
        const RayNode& node = tree.nodes[index];
        if (node.kind == RayKind::shadow) {
            line(prefix, origin(node) + " along " + vec(node.ray.direction));
            return;
        }
        std::string ray = origin(node) + " along " + vec(node.ray.direction);
        const double length = glm::length(node.ray.direction);
        if (!(std::abs(length - 1.0) < 1e-6)) ray += "  <- the direction's length is " + number(length) + ", not 1";
        line(prefix, ray);
        if (node.fate == RayFate::below_min_weight) {
            line(prefix, "not traced: its weight from the eye " + vec(node.path_weight) + " is below --min-weight " +
                             number(context.settings.min_weight));
            return;
        }
        if (node.fate == RayFate::over_budget) {
            line(prefix, "not traced: the pixel's budget of rays is used up");
            return;
        }
        if (const std::optional<DirectionCheck> check = check_direction(tree, index, context)) {
            // "Snell's law with eta_i 1 and eta_t 1.5: in at 32.74 deg from the normal, so out at 21.13 deg: ok"
            std::string text = check->law;
            if (node.kind == RayKind::refracted)
                text += " with eta_i " + number(check->eta_i) + " and eta_t " + number(check->eta_t);
            text += ": in at " + number(check->theta_i) + " deg from the normal, so ";
            if (!check->expected) {
                text += "total internal reflection: no refracted ray should exist; this one goes out at " +
                        number(check->theta_out) + " deg  <- DIFFERS";
            } else {
                text += "out at " + number(check->theta_expected) + " deg";
                if (check->agrees)
                    text += ": ok";
                else if (std::abs(check->theta_out - check->theta_expected) >= 0.01)
                    text += "; this ray goes out at " + number(check->theta_out) + " deg  <- DIFFERS";
                else // the right angle in the wrong plane
                    text += ", along " + vec(*check->expected) + "; this ray is " + number(check->off_degrees) +
                            " deg away from that  <- DIFFERS";
            }
            line(prefix, text);
        }
        if (!node.hit) {
            line(prefix, std::string("hits nothing: the ") + (context.scene.has_skybox() ? "skybox " : "background ") +
                             vec(context.scene.background(node.ray.direction)));
        } else {
            const Hit& hit = *node.hit;
            std::string text = "hit " + object_name(context, hit.primitive) + " at t " + number(hit.t) + ": point " +
                               vec(hit.point) + ", normal " + vec(hit.normal) +
                               (hit.front_face ? ", front face (from outside)" : ", back face (from inside)");
            // What every lab relies on (hit.hpp): a unit normal on the incoming ray's side.
            if (glm::dot(hit.normal, node.ray.direction) > 0.0)
                text += "  <- DIFFERS: the normal should face the incoming ray";
            else if (!(std::abs(glm::length(hit.normal) - 1.0) < 1e-6))
                text += "  <- DIFFERS: the normal's length is " + number(glm::length(hit.normal)) + ", not 1";
            line(prefix, text);
        }
        std::string colour;
        if (node.local) colour += "local " + vec(*node.local);
        if (node.reflection) colour += " + reflection() " + vec(*node.reflection);
        if (node.refraction) colour += " + refraction() " + vec(*node.refraction);
        if (node.fresnel) colour += " + fresnel_blend() " + vec(*node.fresnel);
        if (node.kind != RayKind::eye) colour += (colour.empty() ? "" : ", ") + std::string("times the weight");
        line(prefix, colour + (colour.empty() ? "" : ": ") + "returns " + vec(node.color));
        note_missing_refraction(index, prefix);
    }

    // A transparent surface with no refracted ray: total internal reflection, or a bug.
    void note_missing_refraction(int index, const std::string& prefix) {
        const std::optional<MissingRefraction> missing = check_missing_refraction(tree, index, context);
        if (!missing) return;
        const std::string indices = " with eta_i " + number(missing->eta_i) + " and eta_t " + number(missing->eta_t);
        if (missing->sin_theta_t > 1.0)
            line(prefix, "no refracted ray: Snell's law" + indices + " gives total internal reflection here: ok");
        else
            line(prefix, "no refracted ray, but Snell's law" + indices + " gives sin(theta_t) = " +
                             number(missing->sin_theta_t) + " < 1 (out at " +
                             number(std::asin(missing->sin_theta_t) * 180.0 / kPi) +
                             " deg): a refracted ray was expected  <- DIFFERS");
    }

    void node(int index, const std::string& head, const std::string& rest) {
        const RayNode& n = tree.nodes[index];
        line(head, title(index));
        details(index, rest + (n.children.empty() ? "    " : "|   "));
        for (std::size_t k = 0; k < n.children.size(); ++k) {
            const bool last = k + 1 == n.children.size();
            node(n.children[k], rest + (last ? "`-- " : "|-- "), rest + (last ? "    " : "|   "));
        }
    }
};

} // namespace

std::string ray_tree_text(const RayTree& tree, const TraceContext& context) {
    TextWriter writer{tree, context, {}};
    const Color& colour = tree.nodes.front().color;
    // "(0.2, 0.4, 0.6), in the image 51 102 153": a colour, and the bytes of the image file.
    const auto colour_in_image = [](const Color& c) {
        return vec(c) + ", in the image " +
               (is_finite(c) ? std::to_string(to_byte(c.r, Encoding::linear)) + " " +
                                   std::to_string(to_byte(c.g, Encoding::linear)) + " " +
                                   std::to_string(to_byte(c.b, Encoding::linear))
                             : "magenta: NaN or infinite, a bug");
    };
    const std::string pixel = "pixel (" + std::to_string(context.x) + ", " + std::to_string(context.y) + ") of " +
                              std::to_string(context.width) + "x" + std::to_string(context.height) + ", stage " +
                              std::to_string(context.settings.stage) + ", max depth " +
                              std::to_string(context.settings.max_depth);
    if (const std::optional<ShownSample>& sample = context.sample) {
        const std::string count = std::to_string(sample->count);
        writer.line("", pixel + ", " + count + " samples a pixel: the pixel's value, the average of its " + count +
                            " samples (pixel_color()), " + colour_in_image(sample->pixel));
        writer.line("", "the rays below are sample " + std::to_string(sample->index) + " of " + count + " (--sample 0 to " +
                            std::to_string(sample->count - 1) + " shows another), traced at (" + number(sample->place.x) +
                            ", " + number(sample->place.y) + ") in the pixel (from its lower left corner): colour " +
                            vec(colour));
    } else {
        writer.line("", pixel + ": one ray through its centre, colour " + colour_in_image(colour));
    }
    writer.line("", "");
    writer.node(0, "", "");
    return writer.out;
}

} // namespace whitted
