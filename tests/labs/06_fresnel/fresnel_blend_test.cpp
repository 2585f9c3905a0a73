// Lab 6, fresnel_blend(): Kr x (reflected light) + (1 - Kr) x T x (refracted light).
// The glass surface is the plane z = 0 (outward normal +z); a red lamp plane at
// z = 5 and a blue one at z = -5 (ambient 1, Kd = 1, no lights: they show exactly
// their colour), so red and blue tell the two rays apart.
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"
#include "test_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;

namespace {

SceneData lamps_around_glass(double transmittance, double ior) {
    SceneData data;
    data.ambient = Color(1.0);
    data.materials = {glass_material(ior, transmittance), diffuse_material(Color(1.0, 0.0, 0.0)),
                      diffuse_material(Color(0.0, 0.0, 1.0))};
    data.primitives.push_back({Plane{Point3(0.0, 0.0, 5.0), -kUp}, 1});
    data.primitives.push_back({Plane{Point3(0.0, 0.0, -5.0), kUp}, 2});
    return data;
}

} // namespace

TEST(FresnelBlend, WeightsTheReflectedRayKrAndTheRefractedOneOneMinusKrTimesT) {
    // From air at 45 degrees onto glass with T = 0.5: Kr = 0.050240. The reflected
    // ray sees red, the refracted one blue: (Kr, 0, (1 - Kr) T) = (0.050240, 0, 0.474880).
    // The same glass with a highlight (Ks = 0.5, specular colour (0.5, 1, 0.25)) blends
    // the same: for a dielectric Kr replaces Ks x specular colour as the mirror weight.
    for (const double ks : {0.0, 0.5}) {
        SCOPED_TRACE(::testing::Message() << "Ks = " << ks);
        SceneData data = lamps_around_glass(0.5, 1.5);
        data.materials[0].specular = ks;
        data.materials[0].specular_color = Color(0.5, 1.0, 0.25);
        TracerRig rig(std::move(data), 6, 5);
        const Vec3 wo = direction_at(45.0);
        const Color c = fresnel_blend(rig.tracer, hit_seen_from(Point3(0.0), kUp, wo), wo, 1);
        ASSERT_TRUE(is_finite(c)) << "NaN or infinity in (" << c.x << ", " << c.y << ", " << c.z << ")";
        EXPECT_NEAR(c.x, 0.050240, 1e-6) << "the reflected ray's weight must be Kr";
        EXPECT_NEAR(c.z, (1.0 - 0.050240) * 0.5, 1e-6) << "the refracted ray's weight must be (1 - Kr) T";
        EXPECT_EQ(rig.stats.reflected, 1u);
        EXPECT_EQ(rig.stats.refracted, 1u);
    }
}

TEST(FresnelBlend, WeakRaysAreCutOffByTheAdaptiveDepthControl) {
    // Eight sheets of glass of index 1 with T = 0.1, crossed straight down; max_depth 10, min_weight 1/1024.
    // Equal indices reflect nothing (Kr = 0): the reflected rays' weight 0 is too weak to trace, and the
    // k-th refracted ray carries (1 - 0) 0.1^k: 0.1, 0.01, 0.001 are traced, 0.0001 < 0.000977 is not.
    // So 0 reflected and 3 refracted rays, and a black pixel (the fourth sheet is black itself, Kd = 0).
    // The tracer only knows the weights if fresnel_blend() passes Kr and (1 - Kr) T to trace().
    TracerRig rig(glass_sheets(8, 1.0, 0.1), 6, 10, 1.0 / 1024.0);
    const Color c = rig.trace(Ray{Point3(0.0, 0.0, 1.0), -kUp});
    EXPECT_EQ(rig.stats.reflected, 0u) << "pass the weight Kr to trace(), do not multiply afterwards";
    EXPECT_EQ(rig.stats.refracted, 3u) << "pass the weight (1 - Kr) T to trace(), do not multiply afterwards";
    EXPECT_TRUE(near(c, Color(0.0), 0.0));
}

TEST(FresnelBlend, WithFullTransmittanceTheWeightsAddUpToOne) {
    // T = 1: what is not reflected is transmitted, Kr + (1 - Kr) = 1, at every angle.
    TracerRig rig(lamps_around_glass(1.0, 1.5), 6, 5);
    for (double theta : {0.0, 20.0, 45.0, 70.0, 85.0}) {
        const Vec3 wo = direction_at(theta, 15.0);
        const Color c = fresnel_blend(rig.tracer, hit_seen_from(Point3(0.0), kUp, wo), wo, 1);
        ASSERT_TRUE(is_finite(c)) << "NaN or infinity in (" << c.x << ", " << c.y << ", " << c.z << ")";
        EXPECT_NEAR(c.x + c.z, 1.0, 1e-12) << "reflected + transmitted light at " << theta << " degrees";
        EXPECT_NEAR(c.x, fresnel_reflectance(wo.z, 1.0, 1.5), 1e-12) << "Kr at " << theta << " degrees";
    }
}

TEST(FresnelBlend, LeavingGlassUsesTheGlassToAirReflectance) {
    // From inside (front_face false) at 30 degrees: glass -> air, Kr = 0.0551902.
    // Now the reflected ray goes down to blue and the refracted ray up to red: with
    // T = 0.8, (0.8 (1 - Kr), 0, Kr) = (0.755848, 0, 0.055190).
    TracerRig rig(lamps_around_glass(0.8, 1.5), 6, 5);
    const Vec3 wo = -direction_at(30.0);
    const Hit inside = hit_seen_from(Point3(0.0), kUp, wo);
    ASSERT_FALSE(inside.front_face);
    const Color c = fresnel_blend(rig.tracer, inside, wo, 1);
    ASSERT_TRUE(is_finite(c)) << "NaN or infinity in (" << c.x << ", " << c.y << ", " << c.z << ")";
    EXPECT_NEAR(c.z, 0.0551902, 1e-7) << "inside the glass Kr is the glass -> air reflectance";
    EXPECT_NEAR(c.x, 0.8 * (1.0 - 0.0551902), 1e-7);
}

TEST(FresnelBlend, TotalInternalReflectionReflectsEverythingAndRefractsNothing) {
    // From inside at 60 degrees, past the critical angle: Kr = 1, all blue, no refracted ray.
    TracerRig rig(lamps_around_glass(1.0, 1.5), 6, 5);
    const Vec3 wo = -direction_at(60.0);
    const Color c = fresnel_blend(rig.tracer, hit_seen_from(Point3(0.0), kUp, wo), wo, 1);
    EXPECT_TRUE(near(c, Color(0.0, 0.0, 1.0), 1e-12)) << "total internal reflection: everything is reflected";
    EXPECT_EQ(rig.stats.refracted, 0u) << "no refracted ray on total internal reflection";
    EXPECT_EQ(rig.stats.reflected, 1u);
}

TEST(FresnelBlend, AGlassSphereSeenHeadOnIsMostlyClear) {
    // An eye ray through the centre of a glass sphere (ior 1.5, T = 1) in front of a
    // blue lamp wall, black background, max_depth 3. At normal incidence Kr = 0.04 at
    // both walls: the ray straight through keeps (1 - 0.04)^2 = 0.9216 of the blue.
    // The ray reflected at the front goes to the black background; the one reflected
    // inside at the back wall stops at the front wall at depth 3 (Kd = 0: black).
    SceneData data;
    data.ambient = Color(1.0);
    data.materials = {glass_material(1.5, 1.0), diffuse_material(Color(0.0, 0.0, 1.0))};
    data.primitives.push_back({Sphere{Point3(0.0), 1.0}, 0});
    data.primitives.push_back({Plane{Point3(0.0, 0.0, -5.0), kUp}, 1});
    TracerRig rig(std::move(data), 6, 3);
    const Color c = rig.trace(Ray{Point3(0.0, 0.0, 5.0), -kUp});
    EXPECT_NEAR(c.z, 0.96 * 0.96, 1e-9) << "two interfaces, each letting 1 - 0.04 through";
}
