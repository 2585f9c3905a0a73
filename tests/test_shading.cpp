// The reference shading on scenes small enough to work out by hand.
#include "whitted/labs.hpp"
#include "whitted/render.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;

namespace {

Material diffuse_material(Color color) {
    Material m;
    m.color = color;
    m.diffuse = 1.0;
    return m;
}

// The colour seen along one ray, traced as an eye ray.
Color trace_one(const Scene& scene, const Ray& ray, int stage = 6, int max_depth = 10) {
    RenderSettings settings;
    settings.stage = stage;
    settings.max_depth = max_depth;
    RayStats stats;
    const Tracer tracer(scene, settings, stats);
    return tracer.trace(ray, 1, RayKind::eye, Color(1.0));
}

} // namespace

TEST(Shading, LambertOnAPlaneLitAt60Degrees) {
    // Light at distance 2 from the origin, 60 degrees from the normal: n . L = cos 60 = 0.5.
    // Colour = light (0.8) x kd colour (0.5, 1, 0.25) x 0.5.
    SceneData data;
    data.materials = {diffuse_material(Color(0.5, 1.0, 0.25))};
    data.primitives.push_back({Plane{Point3(0.0), Vec3(0.0, 1.0, 0.0)}, 0});
    data.lights = {PointLight{Point3(2.0 * std::sin(radians(60.0)), 2.0 * std::cos(radians(60.0)), 0.0), Color(0.8)}};
    const Scene scene(std::move(data));
    const Color c = trace_one(scene, Ray{Point3(0.0, 1.0, 0.0), Vec3(0.0, -1.0, 0.0)}, 2);
    EXPECT_NEAR(c.x, 0.8 * 0.5 * 0.5, 1e-12);
    EXPECT_NEAR(c.y, 0.8 * 1.0 * 0.5, 1e-12);
    EXPECT_NEAR(c.z, 0.8 * 0.25 * 0.5, 1e-12);
}

TEST(Shading, ABlockerBetweenPointAndLightCastsAShadow) {
    // A small sphere halfway between the floor point and the light: only ambient remains.
    SceneData data;
    data.ambient = Color(0.1);
    data.materials = {diffuse_material(Color(1.0))};
    data.primitives.push_back({Plane{Point3(0.0), Vec3(0.0, 1.0, 0.0)}, 0});
    data.primitives.push_back({Sphere{Point3(0.0, 2.0, 0.0), 0.2}, 0});
    data.lights = {PointLight{Point3(0.0, 4.0, 0.0), Color(1.0)}};
    const Scene scene(std::move(data));
    const Ray down{Point3(0.5, 1.0, 0.5), glm::normalize(Vec3(-0.5, -1.0, -0.5))}; // hits the origin
    EXPECT_NEAR(trace_one(scene, down, 3).x, 0.1, 1e-12);
    // One unit to the side the feeler passes the blocker: ambient + n . L.
    const Ray beside{Point3(1.0, 1.0, 0.0), Vec3(0.0, -1.0, 0.0)};
    EXPECT_NEAR(trace_one(scene, beside, 3).x, 0.1 + 4.0 / std::sqrt(17.0), 1e-12);
}

TEST(Shading, BlinnPhongHighlightAtTheMirrorAngle) {
    // Eye and light symmetric about the normal: h = n, so the specular term is ks (h.n)^s = ks.
    SceneData data;
    Material m = diffuse_material(Color(0.2));
    m.specular = 0.5;
    m.shininess = 40.0;
    data.materials = {m};
    data.primitives.push_back({Plane{Point3(0.0), Vec3(0.0, 1.0, 0.0)}, 0});
    data.lights = {PointLight{Point3(3.0, 3.0, 0.0), Color(1.0)}};
    const Scene scene(std::move(data));
    const Color c = trace_one(scene, Ray{Point3(-3.0, 3.0, 0.0), glm::normalize(Vec3(1.0, -1.0, 0.0))}, 3);
    EXPECT_NEAR(c.x, 0.2 * std::cos(radians(45.0)) + 0.5, 1e-12);
}

TEST(Refraction, AHollowShellKeepsTheRaysImpactParameterInsideTheCavity) {
    // For concentric spheres n r sin(theta) is conserved along a refracted ray,
    // so in the air-filled cavity of a glass shell (ior 1.4, radii 1 and 0.96)
    // a ray keeps its impact parameter b. If the inner wall were treated as
    // air -> glass again, the ray would bend to b / 1.4^2 instead.
    // A red ball of radius 0.3 at the centre: b = 0.2 must hit it, b = 0.5 must miss
    // (the wrong nesting would give 0.255 and hit it).
    SceneData data;
    data.background = Color(0.0, 0.0, 1.0);
    data.ambient = Color(1.0);
    Material glass;
    glass.diffuse = 0.0;
    glass.transmittance = 1.0;
    glass.ior = 1.4;
    data.materials = {glass, diffuse_material(Color(1.0, 0.0, 0.0))};
    data.primitives.push_back({Sphere{Point3(0.0), 1.0}, 0});
    data.primitives.push_back({Sphere{Point3(0.0), 0.96, true}, 0});
    data.primitives.push_back({Sphere{Point3(0.0), 0.3}, 1});
    const Scene scene(std::move(data));
    const Color through_centre = trace_one(scene, Ray{Point3(0.2, 0.0, 5.0), Vec3(0.0, 0.0, -1.0)}, 5);
    const Color past_ball = trace_one(scene, Ray{Point3(0.5, 0.0, 5.0), Vec3(0.0, 0.0, -1.0)}, 5);
    EXPECT_GT(through_centre.x, 0.8);
    EXPECT_LT(through_centre.z, 0.1);
    EXPECT_LT(past_ball.x, 0.1);
    EXPECT_GT(past_ball.z, 0.8);
}
