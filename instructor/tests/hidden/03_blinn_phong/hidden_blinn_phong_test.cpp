// Hidden lab 3 tests of blinn_phong: grazing mirror angles, very sharp highlights, purely specular
// materials, spheres, checkers and mixtures of lit, shadowed and hidden lights.
#include "test_helpers.hpp"
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;

namespace {

double cos_deg(double degrees) { return std::cos(radians(degrees)); }

/// blinn_phong() at the origin of the floor z = 0 seen from wo.
Color shade_floor(const Material& m, std::vector<PointLight> lights, const Vec3& wo, Color ambient,
                  std::vector<Shape> extra = {}) {
    extra.push_back(floor_z0());
    const Scene scene = scene_of(std::move(extra), m, std::move(lights), ambient);
    const TestTracer t(scene, 3);
    return blinn_phong(t.tracer, surface_hit(Point3(0.0), kUp), wo);
}

} // namespace

TEST(HiddenBlinnPhong, GrazingMirrorAngleStillGivesTheFullHighlight) {
    // Light at 80 degrees, eye at -80: h = n. kd = 0.5 (0.8, 0.6, 0.4), ks = 0.7 (0.9, 0.9, 0.3).
    const Material m = shiny_material(Color(0.8, 0.6, 0.4), 0.5, Color(0.9, 0.9, 0.3), 0.7, 60.0);
    const Color kd = 0.5 * Color(0.8, 0.6, 0.4), ks = 0.7 * Color(0.9, 0.9, 0.3);
    const Color c = shade_floor(m, {{5.0 * direction_at(80.0), Color(1.0)}}, direction_at(-80.0), Color(0.1));
    EXPECT_TRUE(near(c, 0.1 * kd + kd * cos_deg(80.0) + ks, 1e-12));
}

TEST(HiddenBlinnPhong, VerySharpHighlightJustOffTheMirrorAngle) {
    // Light at 45, eye at -44: h is 0.5 degrees from n; exponent 1000: ks cos^1000(0.5 degrees).
    const Material m = shiny_material(Color(0.0), 0.0, Color(1.0), 1.0, 1000.0);
    const Color c = shade_floor(m, {{3.0 * direction_at(45.0), Color(1.0)}}, direction_at(-44.0), Color(0.3));
    EXPECT_TRUE(near(c, Color(std::pow(cos_deg(0.5), 1000.0)), 1e-12));
}

TEST(HiddenBlinnPhong, PurelySpecularMaterialShowsOnlyTheHighlight) {
    // Kd = 0: no ambient and no diffuse light; light at 10, eye at 50: h at 30 degrees, exponent 3.
    const Material m = shiny_material(Color(0.7), 0.0, Color(0.2, 0.6, 1.0), 0.5, 3.0);
    const Color c = shade_floor(m, {{2.0 * direction_at(10.0), Color(1.0, 0.5, 1.0)}}, direction_at(50.0), Color(0.5));
    EXPECT_TRUE(near(c, Color(0.1, 0.15, 0.5) * std::pow(cos_deg(30.0), 3.0), 1e-12));
}

TEST(HiddenBlinnPhong, EyeAtTheLightSeesHEqualToL) {
    // wo = L at 60 degrees: h = L, h . n = cos 60; exponent 2: ks / 4.
    const Material m = shiny_material(Color(1.0, 0.5, 0.0), 0.4, Color(1.0), 0.8, 2.0);
    const Color c = shade_floor(m, {{2.0 * direction_at(60.0), Color(1.0)}}, direction_at(60.0), Color(0.0));
    EXPECT_TRUE(near(c, 0.4 * 0.5 * Color(1.0, 0.5, 0.0) + Color(0.8 * 0.25), 1e-12));
}

TEST(HiddenBlinnPhong, ShadowedAndHiddenLightsAddNothingButAmbientRemains) {
    // Red light at 30 (blocked), green at 110 (behind), blue at -30 with the eye at 30 (mirror: h = n).
    const Material m = shiny_material(Color(0.5, 0.5, 0.5), 1.0, Color(1.0), 0.25, 10.0);
    const Color c = shade_floor(m,
                                {{4.0 * direction_at(30.0), Color(1, 0, 0)},
                                 {4.0 * direction_at(110.0), Color(0, 1, 0)},
                                 {4.0 * direction_at(-30.0), Color(0, 0, 1)}},
                                direction_at(30.0), Color(0.2, 0.4, 0.6), {Sphere{2.0 * direction_at(30.0), 0.3}});
    EXPECT_TRUE(near(c, Color(0.1, 0.2, 0.3) + Color(0, 0, 0.5 * cos_deg(30.0) + 0.25), 1e-12));
}

TEST(HiddenBlinnPhong, CheckerColourDrivesAmbientAndDiffuseButNotTheHighlight) {
    // Cube (1, 0, 0) of side 1 at (1.5, 0.5, 0): colour b = (0, 0.4, 0.8); Kd 0.5. Light overhead, eye overhead:
    // ambient 0.2 kd + kd + white highlight 0.3.
    Material m = shiny_material(Color(1.0), 0.5, Color(1.0), 0.3, 50.0);
    m.checker = Checker{Color(1.0, 0.2, 0.2), Color(0.0, 0.4, 0.8), 1.0};
    const Scene scene = scene_of({floor_z0()}, m, {{Point3(1.5, 0.5, 3), Color(1.0)}}, Color(0.2));
    const TestTracer t(scene, 3);
    const Color kd = 0.5 * Color(0.0, 0.4, 0.8);
    EXPECT_TRUE(near(blinn_phong(t.tracer, surface_hit({1.5, 0.5, 0}, kUp), kUp), 0.2 * kd + kd + Color(0.3), 1e-12));
}

TEST(HiddenBlinnPhong, SphereSeenThroughAnEyeRayAtStage3) {
    // Sphere (0, 0, -5) r 1, eye ray from the origin along -z: point (0, 0, -4), n = wo = +z. Light at
    // (0, 4, -4) + (0, 0, 4) direction (0, 1, 1) / sqrt 2: n . L = cos 45, h at 22.5 degrees.
    const Material m = shiny_material(Color(0.9, 0.3, 0.1), 0.6, Color(0.5, 1.0, 1.0), 0.4, 16.0);
    const Scene scene = scene_of({Sphere{{0, 0, -5}, 1.0}}, m, {{Point3(0, 4, 0), Color(1.0)}}, Color(0.05, 0.1, 0.15));
    const Color kd = 0.6 * Color(0.9, 0.3, 0.1), ks = 0.4 * Color(0.5, 1.0, 1.0);
    const Color c = trace_one(scene, Ray{Point3(0.0), Vec3(0, 0, -1)}, 3);
    EXPECT_TRUE(near(c, Color(0.05, 0.1, 0.15) * kd + kd * cos_deg(45.0) + ks * std::pow(cos_deg(22.5), 16.0), 1e-12));
}
