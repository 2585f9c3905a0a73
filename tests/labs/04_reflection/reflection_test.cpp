// Lab 4, reflection(): one more level of the ray tree, in the mirror direction,
// weighted Ks x specular colour. Scenes small enough to work out by hand; no
// lights, so a surface's own colour is just ambient x Kd x C.
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"
#include "test_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;

namespace {

// With ambient light 1 and no lights, a Kd = 1 surface shows exactly its colour.
Material lamp(Color color) { return diffuse_material(color); }

/// Two facing mirrors z = 0 and z = 1, each showing its own colour C = (0.2, 0.4, 0.6) (ambient 1, Kd = 1,
/// no lights) plus a mirror term Ks = ks of colour `specular_color`.
SceneData facing_mirrors(double ks, Color specular_color = Color(1.0)) {
    SceneData data;
    data.ambient = Color(1.0);
    Material m = lamp(Color(0.2, 0.4, 0.6));
    m.specular = ks;
    m.specular_color = specular_color;
    data.materials = {m};
    data.primitives.push_back({Plane{Point3(0.0), kUp}, 0});
    data.primitives.push_back({Plane{Point3(0.0, 0.0, 1.0), -kUp}, 0});
    return data;
}

/// A mirror (Kd = 0, Ks = ks) and a red ball (ambient 1, Kd = 1: exactly red) before a blue background.
Scene mirror_and_red_ball(Shape mirror, double ks, Sphere ball) {
    SceneData data;
    data.background = Color(0.0, 0.0, 1.0);
    data.ambient = Color(1.0);
    data.materials = {mirror_material(ks), lamp(Color(1.0, 0.0, 0.0))};
    data.primitives.push_back({std::move(mirror), 0});
    data.primitives.push_back({ball, 1});
    return Scene(std::move(data));
}

} // namespace

TEST(Reflection, WeightIsKsTimesTheSpecularColour) {
    // A mirror facing +z with nothing above it: the reflected ray sees the white
    // background, so reflection() returns Ks x specular colour x 1 = 0.5 x (1, 0.5, 0.25).
    SceneData data;
    data.background = Color(1.0);
    data.materials = {mirror_material(0.5, Color(1.0, 0.5, 0.25))};
    data.primitives.push_back({Plane{Point3(0.0), kUp}, 0});
    const TracerRig rig(std::move(data), 4, 5);
    const Vec3 wo = direction_at(30.0);
    const Color c = reflection(rig.tracer, hit_seen_from(Point3(0.0), kUp, wo), wo, 1);
    EXPECT_TRUE(near(c, Color(0.5, 0.25, 0.125), 1e-12)) << "expected Ks * specular_color * (colour seen)";
}

TEST(Reflection, AMirrorShowsWhatLiesInTheMirrorDirection) {
    // Eye ray from (-5, 0, 5) down at 45 degrees hits the mirror z = 0 at the origin;
    // the mirror direction is (1, 0, 1) / sqrt(2), straight at a red ball around
    // (5, 0, 5). The mirror (Kd = 0, Ks = 0.8) shows 0.8 x red; the background is blue.
    const Scene scene = mirror_and_red_ball(Plane{Point3(0.0), kUp}, 0.8, Sphere{Point3(5.0, 0.0, 5.0), 1.0});
    const Color seen = trace_one(scene, make_ray(Point3(-5.0, 0.0, 5.0), Vec3(1.0, 0.0, -1.0)), 4);
    EXPECT_TRUE(near(seen, Color(0.8, 0.0, 0.0), 1e-12)) << "the mirror should show the red ball at 0.8";
    // Looking down steeper (wo at 30 degrees), the reflected ray misses the ball: 0.8 x blue.
    const Color sky = trace_one(scene, Ray{Point3(-5.0, 0.0, 5.0 * std::sqrt(3.0)), -direction_at(-30.0)}, 4);
    EXPECT_TRUE(near(sky, Color(0.0, 0.0, 0.8), 1e-12)) << "the mirror should show the blue background at 0.8";
}

TEST(Reflection, FacingMirrorsCastOneReflectedRayPerLevelBelowMaxDepth) {
    // Two parallel mirrors z = 0 and z = 1, each with colour C = (0.2, 0.4, 0.6)
    // (ambient 1, Kd = 1) and Ks = 0.5 with specular colour (1, 0.5, 0): a ray between
    // them bounces forever, but the eye ray is depth 1 and each reflection one deeper,
    // so max_depth D gives D - 1 reflected rays and the colour
    // C (1 + w + ... + w^(D-1)) with w = Ks x specular colour = (0.5, 0.25, 0).
    // (Path weights stay above min_weight = 1/1024 here: only max_depth stops the rays.)
    for (int max_depth = 1; max_depth <= 6; ++max_depth) {
        SCOPED_TRACE(::testing::Message() << "max_depth " << max_depth);
        TracerRig rig(facing_mirrors(0.5, Color(1.0, 0.5, 0.0)), 4, max_depth, 1.0 / 1024.0);
        const Color seen = rig.trace(make_ray(Point3(0.0, 0.0, 0.5), Vec3(0.6, 0.0, -0.8)));
        EXPECT_EQ(rig.stats.reflected, static_cast<std::uint64_t>(max_depth - 1))
            << "each reflected ray must be traced at depth + 1 as RayKind::reflected";
        EXPECT_EQ(rig.stats.refracted, 0u);
        const Color w(0.5, 0.25, 0.0);
        Color series(0.0), power(1.0);
        for (int k = 0; k < max_depth; ++k, power *= w) series += power;
        EXPECT_TRUE(near(seen, Color(0.2, 0.4, 0.6) * series, 1e-12));
    }
}

TEST(Reflection, WeakReflectionsAreCutOffByTheAdaptiveDepthControl) {
    // The facing mirrors with a white Ks = 0.1, max_depth 10, min_weight 1/1024 = 0.000977: the k-th
    // reflected ray carries the path weight 0.1^k. 0.1, 0.01 and 0.001 are traced; 0.0001 is too weak to
    // change the pixel and is not (ray statistics count 3 reflected rays). The colour is C (1 + 0.1 + 0.01
    // + 0.001). The tracer only knows a ray's weight if reflection() passes Ks x specular colour to trace():
    // tracing with weight 1 and multiplying the colour by Ks afterwards traces every level down to max_depth.
    TracerRig rig(facing_mirrors(0.1), 4, 10, 1.0 / 1024.0);
    const Color seen = rig.trace(make_ray(Point3(0.0, 0.0, 0.5), Vec3(0.6, 0.0, -0.8)));
    EXPECT_EQ(rig.stats.reflected, 3u) << "pass the weight Ks x specular colour to trace(), do not multiply afterwards";
    EXPECT_TRUE(near(seen, 1.111 * Color(0.2, 0.4, 0.6), 1e-12));
}

TEST(Reflection, IsTracedOneLevelDeeperThanTheHit) {
    // The same facing mirrors, max_depth 4. Called for a hit at depth 3, reflection()
    // traces at depth 4 = max_depth: that ray hits the other mirror and stops there
    // (one reflected ray, colour w C). Called at depth 2 it goes one level further.
    TracerRig rig(facing_mirrors(0.5), 4, 4, 1.0 / 1024.0);
    const Vec3 wo = direction_at(20.0);
    const Color last = reflection(rig.tracer, hit_seen_from(Point3(0.0), kUp, wo), wo, 3);
    EXPECT_EQ(rig.stats.reflected, 1u) << "reflection() at depth 3 must trace its ray at depth 4 (= max_depth)";
    EXPECT_TRUE(near(last, 0.5 * Color(0.2, 0.4, 0.6), 1e-12));
    rig.stats = RayStats{};
    const Color two = reflection(rig.tracer, hit_seen_from(Point3(0.0), kUp, wo), wo, 2);
    EXPECT_EQ(rig.stats.reflected, 2u) << "reflection() at depth 2: rays at depths 3 and 4";
    EXPECT_TRUE(near(two, (0.5 + 0.25) * Color(0.2, 0.4, 0.6), 1e-12));
}

TEST(Reflection, ReflectedRaysStartOffTheMirrorSoTheyDoNotHitItAgain) {
    // A tilted mirror (Ks = 0.5, Kd = 0) around coordinates of 1000, where the hit
    // point is off the plane by rounding errors of about 1e-13. Every reflected ray
    // leaves upwards and must see only the white background: 0.5. A ray started at
    // the bare hit point sometimes hits the mirror again from behind ("acne"):
    // more reflected rays and a darker 0.25. Start it with spawn_ray().
    SceneData data;
    data.background = Color(1.0);
    data.materials = {mirror_material(0.5)};
    const Vec3 normal = glm::normalize(Vec3(0.1, 1.0, 0.3));
    data.primitives.push_back({Plane{Point3(1000.1, 1000.3, -999.7), normal}, 0});
    TracerRig rig(std::move(data), 4, 3);
    int wrong = 0;
    const int rays = 2000;
    for (int i = 0; i < rays; ++i) {
        const Ray eye{Point3(1000.0 + i * 0.37, 1020.0, -1000.0 - i * 0.11), glm::normalize(Vec3(0.3, -1.0, 0.2 + i * 1e-3))};
        if (!near(rig.trace(eye), Color(0.5), 1e-9)) ++wrong;
    }
    EXPECT_EQ(wrong, 0) << "pixels of the mirror darkened by self-intersection";
    EXPECT_EQ(rig.stats.reflected, static_cast<std::uint64_t>(rays)) << "one reflected ray per eye ray";
}

TEST(Reflection, UsesTheShadingNormalOfSmoothTriangles) {
    // A flat triangle in z = 0 whose vertex normals all lean 30 degrees towards +x:
    // the shading normal is n = (sin 30, 0, cos 30). Looking straight down (wo = +z),
    // r = 2 cos 30 n - wo = (sin 60, 0, cos 60), towards a red ball 6 units away.
    // The geometric normal (+z) would send the ray straight back up, to the blue sky.
    SceneData data;
    data.background = Color(0.0, 0.0, 1.0);
    data.ambient = Color(1.0);
    data.materials = {mirror_material(1.0), lamp(Color(1.0, 0.0, 0.0))};
    data.vertex_normals.push_back({direction_at(30.0), direction_at(30.0), direction_at(30.0)});
    Primitive triangle{Triangle{Point3(-10.0, -10.0, 0.0), Point3(10.0, -10.0, 0.0), Point3(0.0, 10.0, 0.0)}, 0};
    triangle.vertex_normals = 0;
    data.primitives.push_back(triangle);
    data.primitives.push_back({Sphere{6.0 * direction_at(60.0), 1.0}, 1});
    const Scene scene(std::move(data));
    const Color seen = trace_one(scene, Ray{Point3(0.0, 0.0, 5.0), -kUp}, 4);
    EXPECT_TRUE(near(seen, Color(1.0, 0.0, 0.0), 1e-12)) << "reflect about hit.normal, not hit.geometric_normal";
}

TEST(Reflection, AMirrorSeenFromBehindOrFromInsideReflectsTheSame) {
    // The mirror plane z = 0 (outward normal +z, Ks = 0.8, Kd = 0) seen from below: the eye ray from
    // (-5, 0, -5) along (1, 0, 1) / sqrt 2 meets its back face at the origin (front_face false, hit.normal
    // turned to -z). The mirror direction 2 (wo . n) n - wo = (1, 0, -1) / sqrt 2 goes down to the red
    // ball around (5, 0, -5): 0.8 x red, as from the front. Planes are two-sided, and so are mirrors.
    const Scene plane = mirror_and_red_ball(Plane{Point3(0.0), kUp}, 0.8, Sphere{Point3(5.0, 0.0, -5.0), 1.0});
    EXPECT_TRUE(near(trace_one(plane, make_ray(Point3(-5.0, 0.0, -5.0), Vec3(1.0, 0.0, 1.0)), 4), Color(0.8, 0.0, 0.0), 1e-12))
        << "the back of the mirror should show the red ball at 0.8";
    // Inside a mirror ball (radius 1 around the origin, Ks = 0.5): the eye ray from (0.5, 0, 0) along +x
    // meets the inside of the wall at (1, 0, 0) (front_face false, normal -x) and is sent straight back,
    // along -x, past its start to a red ball of radius 0.2 around (-0.5, 0, 0): 0.5 x red.
    const Scene ball = mirror_and_red_ball(Sphere{Point3(0.0), 1.0}, 0.5, Sphere{Point3(-0.5, 0.0, 0.0), 0.2});
    EXPECT_TRUE(near(trace_one(ball, Ray{Point3(0.5, 0.0, 0.0), Vec3(1.0, 0.0, 0.0)}, 4), Color(0.5, 0.0, 0.0), 1e-12))
        << "the inside of a mirror ball reflects like its outside: the red ball at 0.5";
}
