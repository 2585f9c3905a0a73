// P3F, the course's NFF-derived format.
#include "scene_builder.hpp"

#include "whitted/image.hpp"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <limits>

namespace whitted::detail {

namespace {

constexpr long long kMostSamplesPerPixel = 1 << 16;

/// Takes the word after a keyword (`accel bvh`, `env sky/`), which must be there.
Token read_word(TokenStream& tokens, std::string_view keyword, std::string_view what) {
    const Token token = tokens.next();
    if (token.is_end())
        tokens.fail(token, "expected " + std::string(what) + " after '" + std::string(keyword) + "', found end of file");
    return token;
}

/// `v`: the P3F angle is the full view-plane height, optionally followed by
/// `aperture a` (the lens diameter in pixel widths) and `focal f` (the distance
/// in focus over the view distance), and by the motion-blur shutter `time0 t0 time1 t1`.
void read_p3f_viewpoint(SceneBuilder& scene, const Token& keyword) {
    TokenStream& tokens = scene.tokens();
    const Viewpoint view = scene.read_viewpoint(keyword);
    double aperture = 0.0, focal_ratio = 1.0;
    if (tokens.peek().text == "aperture") {
        tokens.next();
        aperture = NumberReader(tokens, "'aperture'", 1).non_negative("the lens aperture (in pixel widths)");
    }
    if (tokens.peek().text == "focal") {
        tokens.next();
        focal_ratio = NumberReader(tokens, "'focal'", 1).positive("the focal ratio (distance in focus / view distance)");
    }
    if (tokens.peek().text == "time0") {
        const Token word = tokens.next();
        const double time0 = NumberReader(tokens, "'time0'", 1).number("the shutter's opening time");
        if (tokens.peek().text != "time1")
            tokens.fail(tokens.peek(), "expected 'time1' after 'time0 " + format_number(time0) + "', found " +
                                           describe(tokens.peek()));
        tokens.next();
        const double time1 = NumberReader(tokens, "'time1'", 1).number("the shutter's closing time");
        if (time1 < time0)
            tokens.fail(word, "expected time0 <= time1, found " + format_number(time0) + " > " + format_number(time1));
        if (time1 > time0) scene.warn(word, "motion blur is not rendered (the shutter is treated as instantaneous)");
    }
    scene.set_camera(view, view.angle);
    Camera& camera = scene.data().camera;
    camera.aperture = aperture * camera.w / camera.res_x;
    camera.focal_ratio = focal_ratio;
}

/// `accel 0|1|2` (or `none`, `grid`, `bvh`): the acceleration structure of a student build.
Acceleration read_acceleration(TokenStream& tokens, const Token& keyword) {
    const Token word = read_word(tokens, keyword.text, "an acceleration structure (0 none, 1 grid, 2 bvh)");
    if (word.text == "0" || word.text == "none") return Acceleration::none;
    if (word.text == "1" || word.text == "grid") return Acceleration::grid;
    if (word.text == "2" || word.text == "bvh") return Acceleration::bvh;
    tokens.fail(word, "expected 0 (none), 1 (grid) or 2 (bvh) after 'accel', found " + describe(word));
}

/// `env DIR`: the six skybox faces in DIR, relative to the scene file's folder.
void read_environment(SceneBuilder& scene, const Token& keyword) {
    TokenStream& tokens = scene.tokens();
    const Token word = read_word(tokens, keyword.text, "the skybox folder");
    // Messages name the folder as it is written, so it must be printable.
    if (!std::all_of(word.text.begin(), word.text.end(), [](char c) { return c > ' ' && c < 0x7f; }))
        tokens.fail(word, "expected a skybox folder name of plain ASCII letters, digits and signs, found " + describe(word));
    const std::filesystem::path folder =
        std::filesystem::path(tokens.file_name()).parent_path() / std::filesystem::path(std::string(word.text));
    try {
        scene.data().skybox = std::make_shared<const Skybox>(Skybox::load(folder));
    } catch (const ImageError& error) {
        tokens.fail(word, std::string("cannot load the skybox: ") + error.what());
    }
}

/// `f Rd Gd Bd Kd Rs Gs Bs Ks Shine T ior`, optionally followed by the course's `roughness`.
void read_p3f_material(SceneBuilder& scene) {
    NumberReader numbers(scene.tokens(), "'f'", 11);
    Material material;
    material.color = numbers.color("the diffuse colour");
    material.diffuse = numbers.non_negative("the diffuse weight Kd");
    material.specular_color = numbers.color("the specular colour");
    material.specular = numbers.non_negative("the specular weight Ks");
    read_shine_and_transmission(numbers, scene.tokens(), material);
    if (scene.tokens().next_is_number()) { // a twelfth number: the roughness of glossy reflection
        const Token at = scene.tokens().peek();
        if (NumberReader(scene.tokens(), "'f'", 1).non_negative("the roughness") > 0.0)
            scene.warn(at, "glossy (rough) reflection is not rendered: the reflection is a perfect mirror");
    }
    scene.add_material(material);
}

/// `pl x y z x y z x y z`: the plane through three points, front side where they run counter-clockwise.
void read_plane(SceneBuilder& scene, const Token& keyword) {
    NumberReader numbers(scene.tokens(), "'pl'", 9);
    const Point3 p0 = numbers.vec3("the plane's first point");
    const Point3 p1 = numbers.vec3("the plane's second point");
    const Point3 p2 = numbers.vec3("the plane's third point");
    const Vec3 normal = glm::cross(p1 - p0, p2 - p0);
    const double scale = std::max(glm::length(p1 - p0), glm::length(p2 - p0));
    if (!(glm::length(normal) > 1e-12 * scale * scale))
        scene.tokens().fail(keyword, "expected three points of a plane, found points on one line");
    scene.add_shape(keyword, Plane{p0, glm::normalize(normal)});
}

/// `box xmin ymin zmin xmax ymax zmax`.
void read_box(SceneBuilder& scene, const Token& keyword) {
    NumberReader numbers(scene.tokens(), "'box'", 6);
    const Point3 low = numbers.vec3("the box's minimum corner");
    const Point3 high = numbers.vec3("the box's maximum corner");
    for (int axis = 0; axis < 3; ++axis) {
        if (low[axis] < high[axis]) continue;
        const char* name = axis == 0 ? "x" : (axis == 1 ? "y" : "z");
        scene.tokens().fail(keyword, std::string("expected a box with min < max on every axis, found ") + name +
                                         " min " + format_number(low[axis]) + " >= max " +
                                         format_number(high[axis]));
    }
    scene.add_shape(keyword, Box{low, high});
}

/// `mesh nv nf`, nv vertices, nf triangles of 1-based vertex indices (negative: -1 is the last vertex).
void read_mesh(SceneBuilder& scene, const SceneLimits& limits) {
    TokenStream& tokens = scene.tokens();
    NumberReader numbers(tokens, "'mesh'", 2);
    const auto most = static_cast<long long>(std::min<std::size_t>(limits.max_primitives, 1ull << 40));
    const long long vertex_count = numbers.integer("the number of mesh vertices", 3, 3 * most);
    const long long face_count = numbers.integer("the number of mesh faces", 1, most);
    numbers.expect_more(3 * vertex_count + 3 * face_count);
    std::vector<Point3> vertices;
    vertices.reserve(static_cast<std::size_t>(std::min(vertex_count, 1ll << 20)));
    for (long long i = 0; i < vertex_count; ++i) vertices.push_back(numbers.vec3("a mesh vertex"));
    for (long long face = 0; face < face_count; ++face) {
        std::array<Point3, 3> corners;
        const Token face_start = tokens.peek();
        for (Point3& corner : corners) {
            long long index = numbers.integer("a mesh vertex index", std::numeric_limits<long long>::min(),
                                               std::numeric_limits<long long>::max());
            if (index < 0) index += vertex_count + 1; // -1 is the last vertex
            if (index < 1 || index > vertex_count)
                tokens.fail(numbers.last(), "expected a vertex index from 1 to " + std::to_string(vertex_count) +
                                                " (or -1 to -" + std::to_string(vertex_count) + " from the end), found " +
                                                describe(numbers.last()));
            corner = vertices[static_cast<std::size_t>(index - 1)];
        }
        scene.add_polygon(face_start, corners, {}, true);
    }
}

} // namespace

LoadedScene parse_p3f(TokenStream& tokens, const SceneLimits& limits) {
    SceneBuilder scene(tokens, limits);
    for (Token keyword = tokens.next(); !keyword.is_end(); keyword = tokens.next()) {
        const std::string_view word = keyword.text;
        if (scene.read_shared(keyword)) continue;
        if (word == "v") {
            read_p3f_viewpoint(scene, keyword);
        } else if (word == "accel") {
            scene.data().acceleration = read_acceleration(tokens, keyword);
        } else if (word == "spp") {
            // 0: Whitted ray tracing, one ray through each pixel centre; n > 0: n samples a pixel.
            const long long samples =
                NumberReader(tokens, "'spp'", 1).integer("the samples per pixel", 0, kMostSamplesPerPixel);
            scene.data().samples_per_pixel = static_cast<int>(samples);
        } else if (word == "bclr") {
            scene.data().background = NumberReader(tokens, "'bclr'", 3).color("the background colour");
        } else if (word == "env") {
            read_environment(scene, keyword);
        } else if (word == "l") {
            NumberReader numbers(tokens, "'l'", 6);
            const Point3 position = numbers.vec3("the light position");
            scene.add_light(position, numbers.color("the light colour"));
        } else if (word == "f") {
            read_p3f_material(scene);
        } else if (word == "pl") {
            read_plane(scene, keyword);
        } else if (word == "box") {
            read_box(scene, keyword);
        } else if (word == "mesh") {
            read_mesh(scene, limits);
        } else {
            fail_unknown_keyword(tokens, keyword, Dialect::p3f);
        }
    }
    return scene.finish();
}

} // namespace whitted::detail
