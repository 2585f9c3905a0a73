// NFF 3.9, Eric Haines' Neutral File Format, as the SPD generators write it.
#include "scene_builder.hpp"

#include <cmath>

namespace whitted::detail {

namespace {

/// `v`: the NFF angle spans the centres of the top and bottom pixel rows.
void read_nff_viewpoint(SceneBuilder& scene, const Token& keyword) {
    const Viewpoint view = scene.read_viewpoint(keyword);
    if (view.res_y < 2)
        scene.tokens().fail(view.res_y_token, "expected at least 2 pixel rows (the NFF angle is measured between the "
                                              "centres of the top and bottom rows), found " +
                                                  describe(view.res_y_token));
    // The row centres lie (H - 1) / H of the full height apart, so the full height
    // is h = 2 d tan(angle / 2) H / (H - 1), and fovy = 2 atan(tan(angle / 2) H / (H - 1)).
    const double rows = view.res_y;
    const double half_angle = radians(view.angle) / 2.0;
    const double fovy = 2.0 * std::atan(std::tan(half_angle) * rows / (rows - 1.0)) * (180.0 / kPi);
    scene.set_camera(view, fovy);
}

/// `l x y z [r g b]`: the colour is there when a number follows the position.
void read_light(SceneBuilder& scene) {
    NumberReader numbers(scene.tokens(), "'l'", 3);
    const Point3 position = numbers.vec3("the light position");
    std::optional<Color> color;
    if (scene.tokens().next_is_number()) {
        numbers.expect_more(3);
        color = numbers.color("the light colour");
    }
    scene.add_light(position, color);
}

/// `f r g b Kd Ks Shine T ior`: highlights and mirror reflections are white in NFF.
void read_nff_material(SceneBuilder& scene) {
    NumberReader numbers(scene.tokens(), "'f'", 8);
    Material material;
    material.color = numbers.color("the material colour");
    material.diffuse = numbers.non_negative("the diffuse weight Kd");
    material.specular_color = Color(1.0);
    material.specular = numbers.non_negative("the specular weight Ks");
    read_shine_and_transmission(numbers, scene.tokens(), material);
    scene.add_material(material);
}

/// `c base.xyz base_radius apex.xyz apex_radius`: negative radii make the cone seen from inside.
void read_cone(SceneBuilder& scene, const Token& keyword) {
    TokenStream& tokens = scene.tokens();
    NumberReader numbers(tokens, "'c'", 8);
    Cone cone;
    cone.base = numbers.vec3("the cone's base centre");
    const double base_radius = numbers.number("the cone's base radius");
    cone.apex = numbers.vec3("the cone's apex centre");
    const double apex_radius = numbers.number("the cone's apex radius");
    const Token& last = numbers.last();
    if (base_radius == 0.0 && apex_radius == 0.0)
        tokens.fail(last, "expected a cone with a non-zero radius at one end at least, found both radii 0");
    if ((base_radius < 0.0 && apex_radius > 0.0) || (base_radius > 0.0 && apex_radius < 0.0))
        tokens.fail(last, "expected cone radii of one sign (both negative: seen from inside), found " +
                              describe(last) + " after a radius of the other sign");
    if (cone.base == cone.apex) tokens.fail(keyword, "expected a cone whose apex differs from its base, found one point");
    cone.base_radius = std::abs(base_radius);
    cone.apex_radius = std::abs(apex_radius);
    cone.inward = base_radius < 0.0 || apex_radius < 0.0;
    scene.add_shape(keyword, cone);
}

} // namespace

LoadedScene parse_nff(TokenStream& tokens, const SceneLimits& limits) {
    SceneBuilder scene(tokens, limits);
    for (Token keyword = tokens.next(); !keyword.is_end(); keyword = tokens.next()) {
        const std::string_view word = keyword.text;
        if (scene.read_shared(keyword)) continue;
        if (word == "v") {
            read_nff_viewpoint(scene, keyword);
        } else if (word == "b") {
            scene.data().background = NumberReader(tokens, "'b'", 3).color("the background colour");
        } else if (word == "l") {
            read_light(scene);
        } else if (word == "f") {
            read_nff_material(scene);
        } else if (word == "c") {
            read_cone(scene, keyword);
        } else if (word == "pp") {
            scene.read_polygon(keyword, true);
        } else {
            fail_unknown_keyword(tokens, keyword, Dialect::nff);
        }
    }
    return scene.finish();
}

} // namespace whitted::detail
