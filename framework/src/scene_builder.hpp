// What the NFF and P3F parsers share: the scene under construction, its checks
// and limits, and the entities both dialects write the same way.
//
// Why: the two dialects differ in a handful of keywords only. Spheres,
// polygons, the viewpoint's words, lights and the framework's extensions are
// read here once, so both dialects give the same messages for the same mistakes.
#pragma once

#include "scene_tokens.hpp"

#include "whitted/scene_loader.hpp"

#include <cstdint>
#include <future>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace whitted::detail {

/// What a `v` block says, before the dialect turns its angle into a camera.
struct Viewpoint {
    Point3 from{0.0}, at{0.0};
    Vec3 up{0.0};
    double angle = 0.0; // degrees, meaning depends on the dialect
    int res_x = 0, res_y = 0;
    Token keyword;      // the `v`
    Token res_y_token;  // the second resolution number
};

class SceneBuilder {
  public:
    SceneBuilder(TokenStream& tokens, const SceneLimits& limits);

    TokenStream& tokens() { return tokens_; }
    SceneData& data() { return scene_.data; }

    /// Records a warning "file:line:col: warning: message" at the token.
    void warn(const Token& at, const std::string& message);

    /// Reads the keyword's entity if it is one both dialects share; false otherwise.
    bool read_shared(const Token& keyword);

    /// Reads the words of a `v` block up to `resolution W H` (and NFF's optional `yon`).
    Viewpoint read_viewpoint(const Token& keyword);

    /// Checks the viewpoint and stores the camera with the full vertical field of view `fovy`.
    void set_camera(const Viewpoint& view, double fovy);

    /// Makes `material` the one for the shapes that follow.
    void add_material(const Material& material);

    /// Adds a light; without a colour, it gets the SPD default intensity once all lights are known.
    void add_light(const Point3& position, const std::optional<Color>& color);

    /// Adds a shape with the current material; `at` is where errors about it point.
    void add_shape(const Token& at, const Shape& shape, std::int32_t vertex_normals = -1);

    /// Triangulates the polygon and adds its triangles, with per-corner unit normals when given.
    /// A polygon without area is an error, unless `skip_if_flat` (then it is skipped with a warning).
    void add_polygon(const Token& at, std::span<const Point3> vertices, std::span<const Vec3> normals = {},
                     bool skip_if_flat = false);

    /// Reads `p n` followed by n vertices (and n normals after each vertex when `with_normals`).
    void read_polygon(const Token& keyword, bool with_normals);

    /// The finished scene; the file must have had a `v`.
    LoadedScene finish();

  private:
    void read_checker(const Token& keyword);
    void read_area_light(const Token& keyword);

    TokenStream& tokens_;
    SceneLimits limits_;
    LoadedScene scene_;
    bool has_camera_ = false;
    bool has_ambient_ = false;
    bool has_material_ = false;
    std::vector<std::size_t> uncoloured_lights_;
    std::future<void> prefaulted_; // the primitives' pages, mapped in on another thread (after scene_: ends first)
};

/// Reads the three numbers that end both dialects' `f`: Shine T ior. An opaque
/// material (T = 0) may give ior 0, as SPD files do; it is stored as 1.
void read_shine_and_transmission(NumberReader& numbers, TokenStream& tokens, Material& material);

/// Parses an NFF 3.9 token stream.
LoadedScene parse_nff(TokenStream& tokens, const SceneLimits& limits);

/// Parses a P3F token stream.
LoadedScene parse_p3f(TokenStream& tokens, const SceneLimits& limits);

/// Fails at a token where a keyword was expected: a number there means the entity before it had too many.
[[noreturn]] void fail_unknown_keyword(TokenStream& tokens, const Token& token, Dialect dialect);

} // namespace whitted::detail
