#include "scene_builder.hpp"

#include "polygon.hpp"
#include "prefault.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace whitted::detail {

namespace {

constexpr int kDeepestRayTree = 100;
constexpr long long kMostLightSamples = 4096; // points an area light takes a pixel sample: 64 x 64 // `maxdepth` limit: deeper trees only cost time (and stack)

/// Takes the next token, which must be `word`; `context` names the enclosing entity.
Token expect_word(TokenStream& tokens, std::string_view word, std::string_view context) {
    const Token token = tokens.next();
    if (token.text != word)
        tokens.fail(token, "expected " + quoted(word) + " in " + std::string(context) + ", found " + describe(token));
    return token;
}

/// True when the word holds no control bytes and is well-formed UTF-8 (plain ASCII is).
bool is_text(std::string_view word) {
    for (std::size_t i = 0; i < word.size(); ++i) {
        const auto byte = static_cast<unsigned char>(word[i]);
        const int more = byte < 0x80 ? 0 : byte < 0xc2 ? -1 : byte < 0xe0 ? 1 : byte < 0xf0 ? 2 : byte < 0xf5 ? 3 : -1;
        if (byte < 0x20 || byte == 0x7f || more < 0 || word.size() - i <= static_cast<std::size_t>(more)) return false;
        for (int k = 0; k < more; ++k)
            if ((static_cast<unsigned char>(word[++i]) & 0xc0) != 0x80) return false;
    }
    return true;
}

// How many lines start with "s " (the first line, too).
std::size_t sphere_lines(std::string_view text) {
    std::size_t count = text.starts_with("s ") ? 1 : 0;
    for (const char* c = text.data(), *end = c + text.size();
         (c = static_cast<const char*>(std::memchr(c, '\n', static_cast<std::size_t>(end - c)))); ++c)
        if (end - c > 2 && c[1] == 's' && c[2] == ' ') ++count;
    return count;
}

} // namespace

SceneBuilder::SceneBuilder(TokenStream& tokens, const SceneLimits& limits) : tokens_(tokens), limits_(limits) {
    // Room for a primitive every 32 bytes of the file (a sphere line is longer), so
    // that the list is rarely copied as it grows (a mesh's short faces and a polygon
    // of many corners can outgrow it). Room left unused is never touched: it costs
    // address space (which a `ulimit -v` or strict overcommit counts), not memory.
    const std::string_view text = tokens.text();
    data().primitives.reserve(std::min(text.size() / 32 + 1, limits.max_primitives));
    // The spheres' pages (one a line starting "s ") are mapped in on another thread
    // while this one parses; that thread counts them too. Pages for the triangles of
    // polygons are not: their count is not known from the lines.
    const std::size_t room = data().primitives.capacity() * sizeof(Primitive);
    prefaulted_ = prefault_behind(data().primitives.data(), room, [text] { return sphere_lines(text) * sizeof(Primitive); });
}

void SceneBuilder::warn(const Token& at, const std::string& message) {
    scene_.warnings.push_back(tokens_.where(at) + ": warning: " + message);
}

bool SceneBuilder::read_shared(const Token& keyword) {
    const std::string_view word = keyword.text;
    if (word == "s") {
        NumberReader numbers(tokens_, "'s'", 4);
        const Point3 center = numbers.vec3("the sphere centre");
        const double radius = numbers.number("the sphere radius");
        if (radius == 0.0)
            tokens_.fail(numbers.last(), "expected a non-zero sphere radius, found " + describe(numbers.last()));
        add_shape(keyword, Sphere{center, std::abs(radius), radius < 0.0});
    } else if (word == "p") {
        read_polygon(keyword, false);
    } else if (word == "ambient") {
        NumberReader numbers(tokens_, "'ambient'", 3);
        data().ambient = numbers.color("the ambient light intensity");
        has_ambient_ = true;
    } else if (word == "checker") {
        read_checker(keyword);
    } else if (word == "arealight") {
        read_area_light(keyword);
    } else if (word == "maxdepth") {
        NumberReader numbers(tokens_, "'maxdepth'", 1);
        data().max_depth = static_cast<int>(numbers.integer("the deepest ray tree level", 1, kDeepestRayTree));
    } else {
        return false;
    }
    return true;
}

void SceneBuilder::read_checker(const Token& keyword) {
    if (!has_material_)
        tokens_.fail(keyword, "expected a material 'f' before 'checker' (it patterns the current material), found "
                              "none yet");
    NumberReader numbers(tokens_, "'checker'", 7);
    Checker checker;
    checker.size = numbers.positive("the checker square size");
    checker.color_a = numbers.color("the first checker colour");
    checker.color_b = numbers.color("the second checker colour");
    // A new material, so shapes that already use the plain one keep it.
    Material patterned = data().materials.back();
    patterned.checker = checker;
    add_material(patterned);
}

void SceneBuilder::read_area_light(const Token& keyword) {
    NumberReader numbers(tokens_, "'arealight'", 13);
    AreaLight light;
    light.center = numbers.vec3("the area light's centre");
    light.color = numbers.color("the area light's colour");
    light.edge_u = numbers.vec3("the area light's first edge");
    light.edge_v = numbers.vec3("the area light's second edge");
    const Vec3 normal = glm::cross(light.edge_u, light.edge_v);
    if (!(max_abs_component(normal) > 0.0) || !std::isfinite(glm::length(normal)))
        tokens_.fail(keyword, "expected two edges that span a parallelogram after 'arealight', found edges along one "
                              "line (a light without area is a point light: 'l')");
    light.samples = static_cast<int>(numbers.integer("the area light's sample count", 1, kMostLightSamples));
    data().area_lights.push_back(light);
}

Viewpoint SceneBuilder::read_viewpoint(const Token& keyword) {
    constexpr std::string_view context = "the viewpoint 'v'";
    Viewpoint view;
    view.keyword = keyword;
    expect_word(tokens_, "from", context);
    view.from = NumberReader(tokens_, "'from'", 3).vec3("the eye position 'from'");
    const Token at_word = expect_word(tokens_, "at", context);
    view.at = NumberReader(tokens_, "'at'", 3).vec3("the look-at point 'at'");
    const Token up_word = expect_word(tokens_, "up", context);
    view.up = NumberReader(tokens_, "'up'", 3).vec3("the up direction 'up'");
    expect_word(tokens_, "angle", context);
    NumberReader angle(tokens_, "'angle'", 1);
    view.angle = angle.number("the field of view 'angle'");
    if (!(view.angle > 0.0 && view.angle < 180.0))
        tokens_.fail(angle.last(), "expected an angle between 0 and 180 degrees (both excluded), found " +
                                       describe(angle.last()));
    expect_word(tokens_, "hither", context);
    NumberReader(tokens_, "'hither'", 1).number("the near distance 'hither'"); // accepted, not used
    if (tokens_.peek().text == "yon") {
        tokens_.next();
        NumberReader(tokens_, "'yon'", 1).number("the far distance 'yon'"); // accepted, not used
    }
    expect_word(tokens_, "resolution", context);
    NumberReader resolution(tokens_, "'resolution'", 2);
    view.res_x = static_cast<int>(resolution.integer("the image width", 1, limits_.max_resolution));
    view.res_y = static_cast<int>(resolution.integer("the image height", 1, limits_.max_resolution));
    view.res_y_token = resolution.last();
    if (static_cast<std::size_t>(view.res_x) * static_cast<std::size_t>(view.res_y) > limits_.max_pixels)
        tokens_.fail(view.res_y_token, "expected an image of at most " + std::to_string(limits_.max_pixels) +
                                           " pixels, found " + std::to_string(view.res_x) + " x " +
                                           std::to_string(view.res_y));

    // The frame must exist: eye and at apart, up neither zero nor along the view direction.
    const Vec3 backwards = view.from - view.at;
    if (glm::length(backwards) == 0.0)
        tokens_.fail(at_word, "expected a look-at point 'at' away from the eye 'from', found the same point");
    if (glm::length(view.up) == 0.0) tokens_.fail(up_word, "expected a non-zero up direction, found 0 0 0");
    if (glm::length(glm::cross(view.up, backwards)) <= 1e-9 * glm::length(view.up) * glm::length(backwards))
        tokens_.fail(up_word, "expected an up direction not parallel to the view direction (from 'from' to 'at'), "
                              "found a parallel one");
    return view;
}

void SceneBuilder::set_camera(const Viewpoint& view, double fovy) {
    if (has_camera_) warn(view.keyword, "a second viewpoint 'v' replaces the first");
    has_camera_ = true;
    data().camera = Camera::create(view.from, view.at, view.up, fovy, view.res_x, view.res_y);
}

void SceneBuilder::add_material(const Material& material) {
    data().materials.push_back(material);
    has_material_ = true;
}

void SceneBuilder::add_light(const Point3& position, const std::optional<Color>& color) {
    if (!color) uncoloured_lights_.push_back(data().lights.size());
    data().lights.push_back(PointLight{position, color.value_or(Color(1.0))});
}

void SceneBuilder::add_shape(const Token& at, const Shape& shape, std::int32_t vertex_normals) {
    if (data().primitives.size() >= limits_.max_primitives)
        tokens_.fail(at, "expected at most " + std::to_string(limits_.max_primitives) +
                             " primitives in the scene, found more");
    if (data().materials.empty()) data().materials.push_back(Material{}); // white, Kd 1, before any `f`
    Primitive primitive;
    primitive.shape = shape;
    primitive.material = static_cast<std::uint32_t>(data().materials.size() - 1);
    primitive.vertex_normals = vertex_normals;
    primitive.line = static_cast<std::uint32_t>(at.line);
    // A full list moves to a bigger block and frees this one: the pages being mapped in first.
    if (data().primitives.size() == data().primitives.capacity() && prefaulted_.valid()) prefaulted_.get();
    data().primitives.push_back(primitive);
}

void SceneBuilder::add_polygon(const Token& at, std::span<const Point3> vertices, std::span<const Vec3> normals,
                               bool skip_if_flat) {
    const std::vector<TriangleIndices> triangles = triangulate_polygon(vertices);
    if (triangles.empty()) {
        if (!skip_if_flat)
            tokens_.fail(at, "expected a polygon with an area, found " + std::to_string(vertices.size()) +
                                 " vertices on one line or point");
        warn(at, "skipped a polygon without area (its vertices lie on one line)");
        return;
    }
    for (const auto& [i, j, k] : triangles) {
        std::int32_t normals_index = -1;
        if (!normals.empty()) {
            normals_index = static_cast<std::int32_t>(data().vertex_normals.size());
            data().vertex_normals.push_back(VertexNormals{normals[i], normals[j], normals[k]});
        }
        add_shape(at, Triangle{vertices[i], vertices[j], vertices[k]}, normals_index);
    }
}

void SceneBuilder::read_polygon(const Token& keyword, bool with_normals) {
    const std::string entity = quoted(keyword.text);
    NumberReader numbers(tokens_, entity, 1);
    const auto most = static_cast<long long>(limits_.max_polygon_vertices);
    const auto count = static_cast<std::size_t>(numbers.integer("the number of polygon vertices", 3, most));
    numbers.expect_more(static_cast<long long>(count) * (with_normals ? 6 : 3));
    std::vector<Point3> vertices;
    std::vector<Vec3> normals;
    vertices.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        vertices.push_back(numbers.vec3("a polygon vertex"));
        if (!with_normals) continue;
        const Token normal_start = tokens_.peek();
        const Vec3 normal = numbers.vec3("a vertex normal");
        const double largest = max_abs_component(normal);
        if (largest == 0.0) tokens_.fail(normal_start, "expected a non-zero vertex normal, found 0 0 0");
        normals.push_back(glm::normalize(normal / largest)); // scaled first: no overflow for 1e300, no underflow for 1e-300
    }
    // Tessellators write zero-area `pp` triangles (the SPD teapot does): those are skipped.
    add_polygon(keyword, vertices, normals, with_normals);
}

LoadedScene SceneBuilder::finish() {
    if (!has_camera_) tokens_.fail(tokens_.peek(), "expected a viewpoint 'v' in the file, found end of file");
    // The SPD rule (Haines' Readme) for scenes that give no intensities: each light,
    // and the ambient light, gets sqrt(N) / (2 N) for N lights.
    if (!uncoloured_lights_.empty()) {
        const double n = static_cast<double>(data().lights.size() + data().area_lights.size());
        const double intensity = std::sqrt(n) / (2.0 * n);
        for (const std::size_t i : uncoloured_lights_) data().lights[i].color = Color(intensity);
        if (!has_ambient_) data().ambient = Color(intensity);
    }
    return std::move(scene_);
}

void read_shine_and_transmission(NumberReader& numbers, TokenStream& tokens, Material& material) {
    material.shininess = numbers.non_negative("the highlight exponent Shine");
    material.transmittance = numbers.non_negative("the transmittance T");
    const double ior = numbers.number("the index of refraction");
    if (ior < 0.0 || (ior == 0.0 && material.transmittance > 0.0))
        tokens.fail(numbers.last(), "expected a positive index of refraction" +
                                        std::string(ior == 0.0 ? " for a transmitting material (T > 0)" : "") +
                                        ", found " + describe(numbers.last()));
    material.ior = ior == 0.0 ? 1.0 : ior;
}

void fail_unknown_keyword(TokenStream& tokens, const Token& token, Dialect dialect) {
    if (looks_like_number(token.text))
        tokens.fail(token, "expected a keyword, found the number " + describe(token) +
                               (tokens.taken() == 1 ? " (every entity starts with a keyword such as 'v' or 's')"
                                                    : " (the entity before it has too many numbers)"));
    if (!is_text(token.text))
        tokens.fail(token, "unknown keyword " + describe(token) +
                               " (the file is not plain text: is it really a scene file?)");
    static constexpr std::string_view nff_only[] = {"b", "c", "pp"};
    static constexpr std::string_view p3f_only[] = {"accel", "spp", "bclr", "env", "pl", "box", "mesh"};
    const bool is_nff = dialect == Dialect::nff;
    std::string hint;
    const std::span<const std::string_view> other = is_nff ? std::span<const std::string_view>(p3f_only)
                                                             : std::span<const std::string_view>(nff_only);
    for (const std::string_view word : other)
        if (token.text == word)
            hint = std::string(" (it is ") + (is_nff ? "a P3F" : "an NFF") +
                   " keyword; the dialect comes from the file extension)";
    tokens.fail(token, "unknown keyword " + describe(token) + hint);
}

} // namespace whitted::detail
