// blinn_phong: I = Ia kd + sum over the lights that reach the point of
// Il (kd (n . L) + ks (h . n)^shininess), with kd = Kd C, ks = Ks Cs and the halfway vector
// h = normalize(L + wo). The floor z = 0 faces +z, so direction_at(theta) is theta degrees from
// its normal; light and eye directions in the xz-plane make h lie at the mean of their angles.
#include "test_helpers.hpp"
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;

namespace {

// C = (0.5, 0.4, 0.2), Kd = 0.8: kd = (0.4, 0.32, 0.16). Cs = (1, 0.5, 0.25), Ks = 0.4: ks = (0.4, 0.2, 0.1).
const Color kKd(0.4, 0.32, 0.16);
const Color kKs(0.4, 0.2, 0.1);
const Color kAmbient(0.2, 0.3, 0.4);

Material material(double shininess = 20.0) {
    return shiny_material(Color(0.5, 0.4, 0.2), 0.8, Color(1.0, 0.5, 0.25), 0.4, shininess);
}

/// blinn_phong() at the floor's origin, seen from direction wo, with these lights and extra shapes.
Color shade(std::vector<PointLight> lights, const Vec3& wo, const Material& m = material(),
            std::vector<Shape> extra = {}, Color ambient = kAmbient) {
    extra.push_back(floor_z0());
    const Scene scene = scene_of(std::move(extra), m, std::move(lights), ambient);
    const TestTracer t(scene, 3);
    return blinn_phong(t.tracer, surface_hit(Point3(0.0), kUp), wo);
}

double cos_deg(double degrees) { return std::cos(radians(degrees)); }

} // namespace

TEST(BlinnPhong, WithoutLightsOnlyAmbientTimesKdRemains) {
    // Ia kd = (0.2, 0.3, 0.4) x (0.4, 0.32, 0.16) = (0.08, 0.096, 0.064).
    EXPECT_TRUE(near(shade({}, kUp), {0.08, 0.096, 0.064}, 1e-15))
        << "the ambient term is scene.ambient() x kd (Kd x colour_at), even with no light at all";
}

TEST(BlinnPhong, DiffuseTermIsLambert) {
    // A material without highlight (Ks = 0), white light at 60 degrees: Ia kd + kd cos 60.
    const Material matte = shiny_material(Color(0.5, 0.4, 0.2), 0.8);
    const Color c = shade({{3.0 * direction_at(60.0), Color(1.0)}}, direction_at(-10.0), matte);
    EXPECT_TRUE(near(c, kAmbient * kKd + 0.5 * kKd, 1e-12))
        << "expected Ia kd + Il kd (n . L) with n . L = 0.5";
}

TEST(BlinnPhong, HighlightAtTheMirrorDirectionIsKsTimesTheSpecularColour) {
    // Light at 45 degrees, eye at -45: L + wo is along n, so h = n and (h . n)^20 = 1.
    const Color c = shade({{3.0 * direction_at(45.0), Color(1.0)}}, direction_at(-45.0));
    EXPECT_TRUE(near(c, kAmbient * kKd + kKd * cos_deg(45.0) + kKs, 1e-12))
        << "at the mirror angle h = normalize(L + wo) = n: the highlight is ks = Ks x specular colour";
}

TEST(BlinnPhong, HighlightFollowsTheHalfwayVectorAtSeveralAngles) {
    // h lies at (theta_L + theta_eye) / 2 from n. With Phong's mirror vector r . v = cos(theta_L + theta_eye)
    // instead, which differs from (h . n) = cos((theta_L + theta_eye) / 2) in every case below.
    const double cases[][2] = {{60.0, 0.0}, {40.0, -20.0}, {70.0, 10.0}, {-30.0, -80.0}, {20.0, 30.0}};
    for (const auto& [light_deg, eye_deg] : cases) {
        const Color c = shade({{2.0 * direction_at(light_deg), Color(1.0)}}, direction_at(eye_deg));
        const double highlight = std::pow(cos_deg((light_deg + eye_deg) / 2.0), 20.0);
        EXPECT_TRUE(near(c, kAmbient * kKd + kKd * cos_deg(light_deg) + kKs * highlight, 1e-12))
            << "light at " << light_deg << " degrees, eye at " << eye_deg << ": expected the highlight ks (h . n)^20 = "
            << highlight << " x ks with h = normalize(L + wo) (Blinn), not (r . v)^20 (Phong)";
    }
}

TEST(BlinnPhong, ExponentSharpensTheHighlight) {
    // Light at 60 degrees, eye overhead: h . n = cos 30. Exponent 1 gives ks cos 30, exponent 100 ks cos^100 30.
    // Exponents need not be whole numbers (the SPD scenes use 3.0827): cos^3.0827 30 = 0.6419..., not
    // cos^3 30 = 0.6495... (an int exponent) nor cos^4 30 = 0.5625 (a loop that multiplies until it passes 3.0827).
    for (const double shininess : {1.0, 3.0827, 100.0}) {
        const Color c = shade({{2.0 * direction_at(60.0), Color(1.0)}}, kUp, material(shininess));
        EXPECT_TRUE(near(c, kAmbient * kKd + 0.5 * kKd + kKs * std::pow(cos_deg(30.0), shininess), 1e-12))
            << "shininess " << shininess << ": the highlight is (h . n) raised to the material's shininess";
    }
}

TEST(BlinnPhong, ColouredLightsEachAddTheirDiffuseAndHighlight) {
    // Eye at -45. Red (1, 0, 0) at 45 degrees (mirror: h . n = 1): red channel kd.r cos 45 + ks.r.
    // Blue (0, 0, 1) overhead (h at -22.5 degrees): blue channel kd.b + ks.b cos^20 22.5.
    const Color c = shade({{3.0 * direction_at(45.0), Color(1, 0, 0)}, {2.0 * kUp, Color(0, 0, 1)}}, direction_at(-45.0));
    const Color expected = kAmbient * kKd + Color(0.4 * cos_deg(45.0) + 0.4, 0.0, 0.16 + 0.1 * std::pow(cos_deg(22.5), 20.0));
    EXPECT_TRUE(near(c, expected, 1e-12)) << "each light's colour multiplies both its diffuse and its specular term";
}

TEST(BlinnPhong, LightInShadowGivesNeitherDiffuseNorHighlight) {
    // The mirror configuration of the test above, with a sphere across the feeler to the light.
    const Color c = shade({{3.0 * direction_at(45.0), Color(1.0)}}, direction_at(-45.0), material(),
                          {Sphere{1.5 * direction_at(45.0), 0.3}});
    EXPECT_TRUE(near(c, kAmbient * kKd, 1e-12))
        << "a shadowed light adds nothing, not even a highlight: only the ambient term is left";
}

TEST(BlinnPhong, AShadowedFirstLightDoesNotDarkenTheSecond) {
    // The shadowed light of the test above comes first; a tinted light (0.5, 1, 0.25) at -45 degrees comes
    // second, with the eye at 45: the mirror configuration again (h = n), so the second light adds
    // (0.5, 1, 0.25) x (kd cos 45 + ks), and the first nothing.
    const Color tint(0.5, 1.0, 0.25);
    const Color c = shade({{3.0 * direction_at(45.0), Color(1.0)}, {3.0 * direction_at(-45.0), tint}}, direction_at(45.0),
                          material(), {Sphere{1.5 * direction_at(45.0), 0.3}});
    EXPECT_TRUE(near(c, kAmbient * kKd + tint * (kKd * cos_deg(45.0) + kKs), 1e-12))
        << "a light in shadow is skipped (continue), the lights after it still count, each with its own feeler";
}

TEST(BlinnPhong, CheckerboardColoursTheAmbientTerm) {
    // No lights: only Ia kd, with kd = Kd x colour_at(p). Checker cubes of side 1: (0.5, 0.5, 0) is in cube
    // (0, 0, 0), colour a = (1, 0.5, 0); (1.5, 0.5, 0) in cube (1, 0, 0), colour b = (0, 0.5, 1). Kd = 0.8:
    // Ia kd = (0.2, 0.3, 0.4) x 0.8 x (1, 0.5, 0) = (0.16, 0.12, 0) and (0.2, 0.3, 0.4) x 0.8 x (0, 0.5, 1) = (0, 0.12, 0.32).
    Material checkered = material();
    checkered.checker = Checker{Color(1.0, 0.5, 0.0), Color(0.0, 0.5, 1.0), 1.0};
    const Scene scene = scene_of({floor_z0()}, checkered, {}, kAmbient);
    const TestTracer t(scene, 3);
    EXPECT_TRUE(near(blinn_phong(t.tracer, surface_hit({0.5, 0.5, 0}, kUp), kUp), {0.16, 0.12, 0.0}, 1e-12))
        << "the ambient term is Ia x Kd x colour_at(hit.point): the checker colour, not material.color";
    EXPECT_TRUE(near(blinn_phong(t.tracer, surface_hit({1.5, 0.5, 0}, kUp), kUp), {0.0, 0.12, 0.32}, 1e-12))
        << "the ambient term is Ia x Kd x colour_at(hit.point): the checker colour, not material.color";
}

TEST(BlinnPhong, SmoothSurfaceHighlightFollowsTheShadingNormal) {
    // A flat triangle in z = 0 whose vertex normals lean 30 degrees towards +x: hit.normal = n = direction_at(30),
    // hit.geometric_normal = +z. The eye ray comes straight down (wo = +z); a tinted light (1, 0.8, 0.6) at
    // direction_at(60). L and wo lie 30 degrees either side of n, so n . L = cos 30 and h = normalize(L + wo) = n:
    // the full highlight ks, whatever the exponent (3.0827 here). The geometric normal would give cos 60 and
    // cos^3.0827 30 instead.
    const Color tint(1.0, 0.8, 0.6);
    const Scene scene = smooth_floor_scene(direction_at(30.0), {}, material(3.0827), {{3.0 * direction_at(60.0), tint}}, kAmbient);
    const Color c = trace_one(scene, ray_down_to(), 3);
    EXPECT_TRUE(near(c, kAmbient * kKd + tint * (kKd * cos_deg(30.0) + kKs), 1e-12))
        << "shade with hit.normal, the shading normal, for n . L and for h . n";
}

TEST(BlinnPhong, LightBehindTheSurfaceGivesNoHighlight) {
    // Light 5 degrees under the horizon (95 degrees), eye at -80: h lies at 7.5 degrees and h . n > 0,
    // but n . L < 0: the light does not reach this side of the surface, so it adds nothing.
    const Color c = shade({{3.0 * direction_at(95.0), Color(1.0)}}, direction_at(-80.0));
    EXPECT_TRUE(near(c, kAmbient * kKd, 1e-12)) << "skip lights with n . L <= 0 for the highlight too";
}

TEST(BlinnPhong, TracedEyeRayAtStage3UsesWoFromTheRay) {
    // Eye and light symmetric about the normal: wo = -ray.direction, h = n, so the highlight is ks.
    // A grey material (0.2, Kd 1, white highlight Ks 0.5, exponent 40) without ambient light.
    const Scene scene = scene_of({floor_z0()}, shiny_material(Color(0.2), 1.0, Color(1.0), 0.5, 40.0),
                                 {{Point3(3, 0, 3), Color(1.0)}});
    const Color c = trace_one(scene, Ray{Point3(-3, 0, 3), glm::normalize(Vec3(1, 0, -1))}, 3);
    EXPECT_TRUE(near(c, Color(0.2 * cos_deg(45.0) + 0.5), 1e-12));
}

TEST(BlinnPhong, LightsComeFromTheTracer) {
    // A lamp with a size (`arealight`) lights through tracer.lights(); before lab 8 it is one
    // point light at its centre. Matte floor, lamp straight above: Ia kd + kd (n . L = 1).
    const Material matte = shiny_material(Color(0.5, 0.4, 0.2), 0.8);
    SceneData data = scene_data_of({floor_z0()}, matte, {}, kAmbient);
    data.area_lights = {AreaLight{Point3(0.0, 0.0, 3.0), Color(1.0), Vec3(0.5, 0.0, 0.0), Vec3(0.0, 0.5, 0.0), 9}};
    const Scene scene(data);
    const TestTracer t(scene, 3);
    EXPECT_TRUE(near(blinn_phong(t.tracer, surface_hit(Point3(0.0), kUp), kUp), kAmbient * kKd + kKd, 1e-12))
        << "loop over tracer.lights(): scene.point_lights() leaves out the scene's area lights";
}
