// The POV-Ray 3.7 scene writer: our scene, term by term, in POV-Ray's words.
//
// Why each choice (POV-Ray 3.7 behaviour checked against its source, trace.cpp):
//  - Camera: POV's perspective camera shoots direction + x0 right + y0 up with
//    x0 = col/W - 1/2 and y0 = 1/2 - row/H at pixel centres. Giving it our
//    frame explicitly (direction -df ze, right w xe, up h ye) reproduces our eye
//    rays exactly; no `look_at`/`angle`, so POV's handedness fix-ups never run
//    and the picture cannot come out mirrored.
//  - Highlights: POV's `specular` is Specular * (h . n)^(1/roughness) with the
//    halfway vector h, i.e. exactly Blinn-Phong; `phong` uses the mirror vector
//    instead (Phong), so `specular Ks roughness 1/Shine` is the closest match.
//  - Transparency: `transmit T` (uncoloured, like our weight T) with `interior
//    { ior }`; Fresnel reflection via `reflection { 0, 1 fresnel on }` and
//    `conserve_energy`, which scales the transmitted light by 1 - Kr, as our
//    stage 6 does. POV 3.7 also scales ambient and diffuse light by the opacity
//    1 - T, which we do not: ambient and diffuse are divided by 1 - T here.
//  - Shadows: POV lets light through transparent objects; ours stop at them.
//    With PovOptions::opaque_shadows, transparent objects get `no_shadow` and an
//    invisible (`no_image no_reflection`) black copy casts their shadow.
//  - Hollow shells: POV decides entering and leaving from the objects a ray is
//    in, not from normals, so an inward sphere inside an outer sphere of the same
//    centre and material becomes one `difference`; a lone inward sphere or cone
//    becomes `inverse` (the same surfaces, seen from the other side).
//  - Triangles go into one `mesh` per material: POV-Ray bounds a mesh's
//    triangles with its own hierarchy, far faster than thousands of objects.
//  - Numbers are written as the shortest text that reads back as the same double.
#include "pov_scene.hpp"

#include <charconv>
#include <cmath>
#include <map>
#include <ostream>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

namespace whitted::bench {
namespace {

std::string num(double value) {
    if (value == 0.0) value = 0.0; // "-0" reads back the same, but is noise in the file
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

// Built by appending (GCC 12 warns falsely about "literal" + std::string temporaries).
std::string vec(const Vec3& v) {
    std::string text = "<";
    text += num(v.x);
    text += ", ";
    text += num(v.y);
    text += ", ";
    text += num(v.z);
    text += ">";
    return text;
}

// A pigment colour: `rgb` when opaque, `rgbt` (transmit) when the material lets light through.
std::string pigment_colour(const Color& c, double transmittance) {
    std::string text;
    if (transmittance > 0.0) {
        text = "rgbt ";
        text += vec(c);
        text.pop_back();
        text += ", ";
        text += num(transmittance);
        text += ">";
    } else {
        text = "rgb ";
        text += vec(c);
    }
    return text;
}

std::string texture_name(std::uint32_t material) { return std::string("M") += std::to_string(material); }
std::string interior_name(std::uint32_t material) { return std::string("I") += std::to_string(material); }

void write_material(std::ostream& out, std::uint32_t index, const Material& m) {
    const double t = m.transmittance;
    // POV 3.7 weights a surface's own ambient and diffuse light by its opacity 1 - T.
    const double opacity_compensation = (t > 0.0 && t < 1.0) ? 1.0 / (1.0 - t) : 1.0;
    out << "#declare " << texture_name(index) << " = texture {\n  pigment { ";
    if (m.checker) {
        // POV's checker alternates unit cubes by the parity of floor(x) + floor(y) + floor(z), as ours does.
        out << "checker color " << pigment_colour(m.checker->color_a, t) << " color "
            << pigment_colour(m.checker->color_b, t) << " scale " << num(m.checker->size);
    } else {
        out << "color " << pigment_colour(m.color, t);
    }
    out << " }\n  finish {\n";
    // Ambient: our I_a Kd C is POV's ambient_light (global) * ambient Kd * pigment C.
    out << "    ambient " << num(m.diffuse * opacity_compensation) << "\n";
    out << "    diffuse " << num(m.diffuse * opacity_compensation) << "\n";
    if (m.specular > 0.0) {
        // POV highlights take the light's colour only: a coloured highlight becomes its grey mean.
        const Color ks = m.specular * m.specular_color;
        const double roughness = m.shininess > 0.0 ? 1.0 / m.shininess : 1e30; // exponent 0: a constant highlight
        out << "    specular " << num((ks.r + ks.g + ks.b) / 3.0) << " roughness " << num(roughness) << "\n";
    }
    if (t > 0.0) {
        out << "    reflection { 0, 1 fresnel on }\n    conserve_energy\n";
    } else if (m.specular > 0.0) {
        out << "    reflection { rgb " << vec(m.specular * m.specular_color) << " }\n";
    }
    out << "  }\n}\n";
    if (t > 0.0) out << "#declare " << interior_name(index) << " = interior { ior " << num(m.ior) << " }\n";
}

// Everything that follows an object's geometry: its texture, interior and shadow flags.
struct Appearance {
    std::string modifiers;       // for the visible object
    bool needs_shadow_proxy = false;
};

Appearance appearance(const SceneData& data, std::uint32_t material, const PovOptions& options) {
    const bool transparent = data.materials[material].transmittance > 0.0;
    Appearance a;
    a.modifiers = " texture { " + texture_name(material) + " }";
    if (transparent) a.modifiers += " interior { " + interior_name(material) + " }";
    if (transparent && options.opaque_shadows) {
        a.modifiers += " no_shadow";
        a.needs_shadow_proxy = true;
    }
    return a;
}

// Writes `geometry` once with its appearance, and once more as an invisible shadow caster when needed.
void write_object(std::ostream& out, const std::string& geometry_open, const std::string& geometry_body,
                  const Appearance& a) {
    out << geometry_open << geometry_body << a.modifiers << " }\n";
    if (a.needs_shadow_proxy)
        out << geometry_open << geometry_body << " texture { pigment { rgb 0 } } no_image no_reflection }\n";
}

std::string sphere_text(const Sphere& s) { return "sphere { " + vec(s.center) + ", " + num(s.radius); }

void write_cone(std::ostream& out, const Cone& c, const Appearance& a) {
    std::string body;
    if (c.base_radius == c.apex_radius) {
        body = vec(c.base) + ", " + vec(c.apex) + ", " + num(c.base_radius) + " open";
        if (c.inward) body += " inverse";
        write_object(out, "cylinder { ", body, a);
    } else {
        body = vec(c.base) + ", " + num(c.base_radius) + ", " + vec(c.apex) + ", " + num(c.apex_radius) + " open";
        if (c.inward) body += " inverse";
        write_object(out, "cone { ", body, a);
    }
}

// Pairs each inward sphere with an outer sphere of the same centre and material (a
// hollow shell), when there is one; returns, per primitive, the index of its partner.
std::vector<std::ptrdiff_t> find_shells(const SceneData& data) {
    std::vector<std::ptrdiff_t> partner(data.primitives.size(), -1);
    using Key = std::tuple<double, double, double, std::uint32_t>;
    std::map<Key, std::vector<std::size_t>> outer;
    bool any_inward = false;
    for (std::size_t i = 0; i < data.primitives.size(); ++i) {
        const auto* s = std::get_if<Sphere>(&data.primitives[i].shape);
        if (!s) continue;
        if (s->inward) any_inward = true;
        else outer[{s->center.x, s->center.y, s->center.z, data.primitives[i].material}].push_back(i);
    }
    if (!any_inward) return partner;
    for (std::size_t i = 0; i < data.primitives.size(); ++i) {
        const auto* s = std::get_if<Sphere>(&data.primitives[i].shape);
        if (!s || !s->inward) continue;
        auto found = outer.find({s->center.x, s->center.y, s->center.z, data.primitives[i].material});
        if (found == outer.end()) continue;
        for (std::size_t candidate : found->second) {
            const auto& o = std::get<Sphere>(data.primitives[candidate].shape);
            if (partner[candidate] < 0 && o.radius > s->radius) {
                partner[candidate] = static_cast<std::ptrdiff_t>(i);
                partner[i] = static_cast<std::ptrdiff_t>(candidate);
                break;
            }
        }
    }
    return partner;
}

void write_triangle(std::ostream& out, const SceneData& data, const Primitive& p, const Triangle& t) {
    if (p.vertex_normals >= 0) {
        const VertexNormals& n = data.vertex_normals[static_cast<std::size_t>(p.vertex_normals)];
        out << "  smooth_triangle { " << vec(t.p0) << ", " << vec(n[0]) << ", " << vec(t.p1) << ", " << vec(n[1])
            << ", " << vec(t.p2) << ", " << vec(n[2]) << " }\n";
    } else {
        out << "  triangle { " << vec(t.p0) << ", " << vec(t.p1) << ", " << vec(t.p2) << " }\n";
    }
}

void write_meshes(std::ostream& out, const SceneData& data, const PovOptions& options) {
    std::map<std::uint32_t, std::vector<std::size_t>> by_material;
    for (std::size_t i = 0; i < data.primitives.size(); ++i)
        if (std::holds_alternative<Triangle>(data.primitives[i].shape)) by_material[data.primitives[i].material].push_back(i);
    for (const auto& [material, indices] : by_material) {
        const Appearance a = appearance(data, material, options);
        const int copies = a.needs_shadow_proxy ? 2 : 1;
        for (int copy = 0; copy < copies; ++copy) {
            out << "mesh {\n";
            for (std::size_t i : indices)
                write_triangle(out, data, data.primitives[i], std::get<Triangle>(data.primitives[i].shape));
            if (copy == 0) out << " " << a.modifiers << "\n}\n";
            else out << "  texture { pigment { rgb 0 } } no_image no_reflection\n}\n";
        }
    }
}

} // namespace

// Derivation: our eye ray through viewport point (x, y) (pixels from the bottom
// left) has direction w (x/W - 1/2) xe + h (y/H - 1/2) ye - df ze. POV-Ray's is
// direction + x0 right + y0 up with x0 = (col + 1/2)/W - 1/2 and y0 = 1/2 -
// (row + 1/2)/H, rows counted from the top. Our image row `row` is y = H - 1 -
// row, so y/H - 1/2 at its centre is (H - row - 1/2)/H - 1/2 = y0, and the column
// is x: the two agree term by term with direction = -df ze, right = w xe and
// up = h ye. The horizontal field of view POV would call `angle` is then
// 2 atan(w / (2 df)).
PovCamera pov_camera(const Camera& camera) {
    PovCamera c;
    c.location = camera.eye;
    c.direction = -camera.df * camera.ze;
    c.right = camera.w * camera.xe;
    c.up = camera.h * camera.ye;
    c.horizontal_angle = 2.0 * std::atan(camera.w / (2.0 * camera.df)) * 180.0 / kPi;
    return c;
}

void write_pov_scene(const SceneData& data, const PovOptions& options, std::ostream& out) {
    out << "// POV-Ray 3.7 scene written by whitted's POV-Ray scene writer";
    if (!options.source.empty()) out << " from " << options.source;
    out << ".\n// Render without antialiasing, e.g. povray +I file.pov +O file.png +W" << data.camera.res_x << " +H"
        << data.camera.res_y << " -A +FN -D\n";
    out << "#version 3.7;\n\n";
    out << "global_settings {\n  max_trace_level " << options.max_trace_level
        << "\n  adc_bailout 0\n  assumed_gamma 1.0\n  ambient_light rgb " << vec(data.ambient) << "\n}\n\n";

    const PovCamera c = pov_camera(data.camera);
    out << "// Our camera's frame, given explicitly; horizontal angle " << num(c.horizontal_angle) << " degrees.\n";
    out << "camera {\n  perspective\n  location " << vec(c.location) << "\n  direction " << vec(c.direction)
        << "\n  right " << vec(c.right) << "\n  up " << vec(c.up) << "\n}\n\n";
    out << "background { color rgb " << vec(data.background) << " }\n\n";
    for (const PointLight& light : data.lights)
        out << "light_source { " << vec(light.position) << " color rgb " << vec(light.color) << " }\n";
    out << "\n";

    std::vector<bool> used(data.materials.size(), false);
    for (const Primitive& p : data.primitives) used[p.material] = true;
    for (std::uint32_t i = 0; i < data.materials.size(); ++i)
        if (used[i]) write_material(out, i, data.materials[i]);
    out << "\n";

    const std::vector<std::ptrdiff_t> shell_partner = find_shells(data);
    for (std::size_t i = 0; i < data.primitives.size(); ++i) {
        const Primitive& p = data.primitives[i];
        const Appearance a = appearance(data, p.material, options);
        if (const auto* s = std::get_if<Sphere>(&p.shape)) {
            if (shell_partner[i] >= 0) {
                if (s->inward) continue; // written with its outer sphere
                const auto& inner = std::get<Sphere>(data.primitives[static_cast<std::size_t>(shell_partner[i])].shape);
                write_object(out, "difference { ", sphere_text(*s) + " } " + sphere_text(inner) + " }", a);
            } else {
                write_object(out, "", sphere_text(*s) + (s->inward ? " inverse" : ""), a);
            }
        } else if (const auto* plane = std::get_if<Plane>(&p.shape)) {
            write_object(out, "plane { ", vec(plane->normal) + ", " + num(glm::dot(plane->normal, plane->point)), a);
        } else if (const auto* box = std::get_if<Box>(&p.shape)) {
            write_object(out, "box { ", vec(box->min) + ", " + vec(box->max), a);
        } else if (const auto* cone = std::get_if<Cone>(&p.shape)) {
            write_cone(out, *cone, a);
        }
    }
    write_meshes(out, data, options);
}

} // namespace whitted::bench
