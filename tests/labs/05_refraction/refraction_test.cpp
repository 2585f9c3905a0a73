// Lab 5, refraction(): the refracted ray, traced one level deeper with weight T,
// entering or leaving depending on hit.front_face. No lights: a Kd = 1 surface
// under ambient light 1 shows exactly its colour.
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"
#include "test_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;

namespace {

// A glass slab 1 thick (-0.5 < z < 0.5), much wider than anything the tests look at.
Primitive slab(std::uint32_t material) {
    return {Box{Point3(-50.0, -50.0, -0.5), Point3(50.0, 50.0, 0.5)}, material};
}

} // namespace

TEST(Refraction, WeightIsTheTransmittance) {
    // A glass surface (T = 0.6) with nothing behind it: the refracted ray sees the
    // background (1, 0.5, 0.25), so refraction() returns 0.6 x background. The same
    // glass with a highlight (Ks = 0.3, specular colour (1, 0.5, 0.25)) transmits the
    // same: the mirror term is reflection()'s, refraction() weights its ray by T alone.
    Material shiny_glass = glass_material(1.5, 0.6);
    shiny_glass.specular = 0.3;
    shiny_glass.specular_color = Color(1.0, 0.5, 0.25);
    for (const Material& glass : {glass_material(1.5, 0.6), shiny_glass}) {
        SCOPED_TRACE(::testing::Message() << "Ks = " << glass.specular);
        SceneData data;
        data.background = Color(1.0, 0.5, 0.25);
        data.materials = {glass};
        data.primitives.push_back({Plane{Point3(0.0), kUp}, 0});
        TracerRig rig(std::move(data), 5, 5);
        const Vec3 wo = direction_at(30.0);
        const Color c = refraction(rig.tracer, hit_seen_from(Point3(0.0), kUp, wo), wo, 1);
        EXPECT_TRUE(near(c, Color(0.6, 0.3, 0.15), 1e-12)) << "expected T * (colour seen through the surface)";
        EXPECT_EQ(rig.stats.refracted, 1u) << "one ray, traced as RayKind::refracted";
        EXPECT_EQ(rig.stats.reflected, 0u);
    }
}

TEST(Refraction, WeakTransmissionIsCutOffByTheAdaptiveDepthControl) {
    // Eight sheets of glass of index 1 (no bending) with T = 0.1, crossed straight down; max_depth 10,
    // min_weight 1/1024 = 0.000977. The k-th refracted ray carries the path weight 0.1^k: 0.1, 0.01 and
    // 0.001 are traced, 0.0001 is too weak to change the pixel and is not (3 refracted rays). The third
    // stops on the fourth sheet, black itself (Kd = 0): the pixel is black. The tracer only knows a ray's
    // weight if refraction() passes T to trace(); weight 1 and the colour times T afterwards crosses all 8.
    TracerRig rig(glass_sheets(8, 1.0, 0.1), 5, 10, 1.0 / 1024.0);
    const Color c = rig.trace(Ray{Point3(0.0, 0.0, 1.0), -kUp});
    EXPECT_EQ(rig.stats.refracted, 3u) << "pass the weight T to trace(), do not multiply afterwards";
    EXPECT_TRUE(near(c, Color(0.0), 0.0));
}

TEST(Refraction, ASlabShiftsTheRayWhichLeavesParallelToHowItEntered) {
    // The eye ray meets the slab at (0, 0, 0.5) at 45 degrees. Inside it bends to
    // 28.1255 degrees and crosses to (tan 28.1255, 0, -0.5) = (0.534522, 0, -0.5).
    // Leaving (front_face false: glass -> air) it bends back to 45 degrees, so 3
    // further down it passes (3.534522, 0, -3.5), the centre of a red ball (r 0.5).
    // Two interfaces with T = 0.8: the ball shows at 0.8^2 = 0.64. Treating the exit
    // as air -> glass again bends the ray to 18.3 degrees and misses the ball (blue).
    SceneData data;
    data.background = Color(0.0, 0.0, 1.0);
    data.ambient = Color(1.0);
    data.materials = {glass_material(1.5, 0.8), diffuse_material(Color(1.0, 0.0, 0.0))};
    data.primitives.push_back(slab(0));
    data.primitives.push_back({Sphere{Point3(0.5345224838248487 + 3.0, 0.0, -3.5), 0.5}, 1});
    TracerRig rig(std::move(data), 5, 5);
    const Vec3 d = glm::normalize(Vec3(1.0, 0.0, -1.0));
    const Color seen = rig.trace(Ray{Point3(0.0, 0.0, 0.5) - 5.0 * d, d});
    EXPECT_TRUE(near(seen, Color(0.64, 0.0, 0.0), 1e-9))
        << "leaving the glass (hit.front_face false) must go from material.ior into air";
    EXPECT_EQ(rig.stats.refracted, 2u) << "one refracted ray into the slab, one out of it";
}

TEST(Refraction, TotalInternalReflectionGivesBlackAndNoRay) {
    // Inside glass (front_face false) at 60 degrees, beyond the critical angle of
    // 41.8103: nothing is transmitted, so refraction() adds black and casts no ray,
    // even though the background behind the surface is white.
    SceneData data;
    data.background = Color(1.0);
    data.materials = {glass_material(1.5, 1.0)};
    TracerRig rig(std::move(data), 5, 5);
    const Vec3 wo = -direction_at(60.0); // on the inner side of a surface whose outward normal is +z
    const Hit inside = hit_seen_from(Point3(0.0), kUp, wo);
    ASSERT_FALSE(inside.front_face);
    EXPECT_TRUE(near(refraction(rig.tracer, inside, wo, 1), Color(0.0), 0.0)) << "total internal reflection: black";
    EXPECT_EQ(rig.stats.total(), 0u) << "no ray may be traced on total internal reflection";
    // At 40 degrees, just inside the critical angle, the light gets out: T x white.
    const Vec3 wo_40 = -direction_at(40.0);
    EXPECT_TRUE(near(refraction(rig.tracer, hit_seen_from(Point3(0.0), kUp, wo_40), wo_40, 1), Color(1.0), 1e-12));
}

TEST(Refraction, IsTracedOneLevelDeeperThanTheHit) {
    // Straight down into the slab (max_depth 3). Called at depth 2, refraction()
    // traces its ray at depth 3 = max_depth: it reaches the bottom face and stops
    // there (Kd = 0: black). Called at depth 1 it also leaves through the bottom
    // face and sees the green background: T^2 green, two refracted rays.
    SceneData data;
    data.background = Color(0.0, 1.0, 0.0);
    data.materials = {glass_material(1.5, 0.5)};
    data.primitives.push_back(slab(0));
    TracerRig rig(std::move(data), 5, 3);
    const Hit top = hit_seen_from(Point3(0.0, 0.0, 0.5), kUp, kUp);
    EXPECT_TRUE(near(refraction(rig.tracer, top, kUp, 2), Color(0.0), 1e-12));
    EXPECT_EQ(rig.stats.refracted, 1u) << "refraction() at depth 2 must trace its ray at depth 3 (= max_depth)";
    rig.stats = RayStats{};
    EXPECT_TRUE(near(refraction(rig.tracer, top, kUp, 1), Color(0.0, 0.25, 0.0), 1e-12));
    EXPECT_EQ(rig.stats.refracted, 2u) << "refraction() at depth 1: rays at depths 2 and 3";
}

TEST(Refraction, RaysThroughTheCentreOfAFarAwayBallReachTheFarWall) {
    // A glass ball (T = 0.5) around coordinates of 1000: rays aimed at its centre go
    // straight in and out (normal incidence) and see the white background at T^2 = 0.25.
    // A refracted ray started at the bare hit point can meet the surface it starts
    // on again (rounding errors of about 1e-13): use spawn_ray().
    SceneData data;
    data.background = Color(1.0);
    data.materials = {glass_material(1.5, 0.5)};
    const Point3 centre(1000.3, -999.1, 1000.7);
    data.primitives.push_back({Sphere{centre, 2.5}, 0});
    TracerRig rig(std::move(data), 5, 6);
    int wrong = 0;
    for (int i = 0; i < 500; ++i) {
        const Vec3 n = direction_at(5.0 + i * 0.33, i * 7.1);
        if (!near(rig.trace(Ray{centre + 10.0 * n, -n}), Color(0.25), 1e-9)) ++wrong;
    }
    EXPECT_EQ(wrong, 0) << "rays through the centre that did not come out at 0.25";
}
