// Hidden tests of lab 5: water (1.33) and diamond (2.42), other angles and other shapes.
#include "whitted/labs.hpp"

#include "image_check.hpp"
#include "lab_helpers.hpp"
#include "test_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;

TEST(HiddenRefractedDirection, IntoWaterAt60DegreesBendsTo40Point6281) {
    // sin(theta_t) = sin(60) / 1.33 = 0.651143, theta_t = 40.6281 degrees.
    const auto wt = refracted_direction(direction_at(60.0), kUp, 1.0, 1.33);
    ASSERT_TRUE(wt.has_value());
    EXPECT_NEAR(degrees_between(*wt, -kUp), 40.6281, 1e-4);
    EXPECT_LT(wt->x, 0.0);
}

TEST(HiddenRefractedDirection, IntoDiamondAt30DegreesBendsTo11Point9239) {
    // sin(theta_t) = 0.5 / 2.42 = 0.206612, theta_t = 11.9239 degrees, azimuth kept (250 degrees).
    const Vec3 wo = direction_at(30.0, 250.0);
    const auto wt = refracted_direction(wo, kUp, 1.0, 2.42);
    ASSERT_TRUE(wt.has_value());
    const double sin_t = 0.5 / 2.42;
    EXPECT_TRUE(near(*wt, Vec3(-wo.x / 0.5 * sin_t, -wo.y / 0.5 * sin_t, -std::sqrt(1.0 - sin_t * sin_t)), 1e-14));
}

TEST(HiddenRefractedDirection, OutOfWaterAt30DegreesBendsTo41Point6823) {
    // sin(theta_t) = 1.33 sin(30) = 0.665, theta_t = 41.6823 degrees.
    const auto wt = refracted_direction(direction_at(30.0), kUp, 1.33, 1.0);
    ASSERT_TRUE(wt.has_value());
    EXPECT_NEAR(degrees_between(*wt, -kUp), 41.6823, 1e-4);
}

TEST(HiddenRefractedDirection, DiamondHasACriticalAngleOf24Point4075) {
    // asin(1 / 2.42) = 24.4075 degrees: at 24.40 the ray just gets out, at
    // sin(theta_t) = 2.42 sin(24.40), theta_t = 88.6266 degrees; at 24.42 it cannot.
    const auto wt = refracted_direction(direction_at(24.40), kUp, 2.42, 1.0);
    ASSERT_TRUE(wt.has_value());
    EXPECT_NEAR(degrees_between(*wt, -kUp), 88.6266, 1e-4);
    EXPECT_FALSE(refracted_direction(direction_at(24.42), kUp, 2.42, 1.0).has_value());
    EXPECT_FALSE(refracted_direction(direction_at(50.0), kUp, 1.33, 1.0).has_value()) << "water: critical 48.7535";
}

TEST(HiddenRefractedDirection, SameIndexOnBothSidesDoesNotBend) {
    const Vec3 wo = glm::normalize(Vec3(-0.4, 0.3, 0.8));
    const Vec3 n = glm::normalize(Vec3(0.1, 0.2, 1.0));
    const auto wt = refracted_direction(wo, n, 1.33, 1.33);
    ASSERT_TRUE(wt.has_value());
    EXPECT_TRUE(near(*wt, -wo, 1e-14));
    // From water into glass (1.33 -> 1.5) the same ray bends: sin(theta_t) = 1.33 / 1.5 sin(theta_i).
    const auto bent = refracted_direction(wo, n, 1.33, 1.5);
    ASSERT_TRUE(bent.has_value());
    EXPECT_NEAR(glm::length(glm::cross(*bent, n)), 1.33 / 1.5 * glm::length(glm::cross(wo, n)), 1e-14);
}

TEST(HiddenRefractedDirection, WorksForANormalAlongMinusX) {
    // n = (-1, 0, 0), wo at 70 degrees from it towards +z: theta_t = 38.7896 degrees into glass.
    const Vec3 n(-1.0, 0.0, 0.0);
    const Vec3 wo(-std::cos(radians(70.0)), 0.0, std::sin(radians(70.0)));
    const auto wt = refracted_direction(wo, n, 1.0, 1.5);
    ASSERT_TRUE(wt.has_value());
    EXPECT_NEAR(degrees_between(*wt, -n), 38.7896, 1e-4);
    EXPECT_LT(wt->z, 0.0);
    EXPECT_NEAR(wt->y, 0.0, 1e-15);
}

namespace {
SceneData lamp_and_glass(const Material& glass, Color lamp_colour) {
    SceneData data;
    data.background = Color(0.0, 0.0, 1.0);
    data.ambient = Color(1.0);
    data.materials = {glass, diffuse_material(lamp_colour)};
    return data;
}
} // namespace

TEST(HiddenRefraction, ACoinAtTheBottomOfAPoolIsSeenWhereSnellPutsIt) {
    // Water surface z = 0 (T = 0.9). Looking in at 60 degrees through (0, 0, 0) the ray
    // bends to 40.6281 degrees and 2 deeper passes (2 tan 40.6281, 0, -2) = (1.715911, 0, -2):
    // a yellow coin there shows at 0.9.
    SceneData data = lamp_and_glass(glass_material(1.33, 0.9), Color(1.0, 1.0, 0.0));
    data.primitives.push_back({Plane{Point3(0.0), kUp}, 0});
    data.primitives.push_back({Sphere{Point3(2.0 * 0.8579556736640435, 0.0, -2.0), 0.2}, 1});
    TracerRig rig(std::move(data), 5, 5);
    const Color c = rig.trace(Ray{3.0 * direction_at(-60.0), -direction_at(-60.0)});
    EXPECT_TRUE(near(c, Color(0.9, 0.9, 0.0), 1e-9));
}

TEST(HiddenRefraction, LookingUpOutOfTheWaterBendsAwayFromTheNormal) {
    // Under the water surface z = 0 (seen from below: front_face false), looking up at
    // 30 degrees: the ray leaves at 41.6823 degrees, still leaning towards -x, and hits a
    // red ball 3 away from (0, 0, 0).
    SceneData data = lamp_and_glass(glass_material(1.33, 1.0), Color(1.0, 0.0, 0.0));
    data.primitives.push_back({Plane{Point3(0.0), kUp}, 0});
    data.primitives.push_back({Sphere{3.0 * direction_at(-41.68232539333951), 0.2}, 1});
    TracerRig rig(std::move(data), 5, 5);
    const Color c = rig.trace(Ray{-2.0 * direction_at(-30.0), direction_at(-30.0)});
    EXPECT_TRUE(near(c, Color(1.0, 0.0, 0.0), 1e-9));
}

TEST(HiddenRefraction, AGlassBallDeflectsAnOffCentreRayByTwiceThetaIMinusThetaT) {
    // Ball r = 1, ior 1.5, ray down at x = 0.5: theta_i = 30, theta_t = 19.4712 degrees.
    // It leaves at polar angle 30 + 180 - 2 theta_t = 171.0576 degrees, at
    // (0.155442, 0, -0.987845), deflected by 2 (30 - 19.4712) = 21.0576 degrees towards the axis.
    SceneData data = lamp_and_glass(glass_material(1.5, 1.0), Color(0.0, 1.0, 0.0));
    data.primitives.push_back({Sphere{Point3(0.0), 1.0}, 0});
    const Point3 exit(0.15544216506292896, 0.0, -0.9878449945819178);
    const double deflection = radians(21.057558731018613);
    data.primitives.push_back({Sphere{exit + 4.0 * Vec3(-std::sin(deflection), 0.0, -std::cos(deflection)), 0.2}, 1});
    TracerRig rig(std::move(data), 5, 5);
    EXPECT_TRUE(near(rig.trace(Ray{Point3(0.5, 0.0, 5.0), -kUp}), Color(0.0, 1.0, 0.0), 1e-9));
}

TEST(HiddenRefraction, TotalInternalReflectionInsideAGlassCubeGivesBlack) {
    // Entering the top of a glass cube (ior 1.5) at 60 degrees the ray bends to 35.2644
    // and meets the side face x = 1 at 54.7356 degrees > 41.8103: no light gets out
    // there, so at stage 5 (no Fresnel yet) that path is black, background or not.
    SceneData data = lamp_and_glass(glass_material(1.5, 1.0), Color(1.0));
    data.background = Color(1.0);
    data.primitives.push_back({Box{Point3(-1.0), Point3(1.0)}, 0});
    TracerRig rig(std::move(data), 5, 6);
    const Vec3 d(std::sin(radians(60.0)), -0.5, 0.0);
    EXPECT_TRUE(near(rig.trace(Ray{Point3(0.5, 1.0, 0.0) - 2.0 * d, d}), Color(0.0), 1e-12));
    EXPECT_EQ(rig.stats.refracted, 1u) << "only the ray into the cube";
}

TEST(HiddenRefraction, StackedSlabsNeedOneLevelPerInterface) {
    // Three slabs of diamond (T = 0.9) crossed head-on: six interfaces, so the
    // background is reached by the 7th-level ray (0.9^6 of white) and max_depth 4
    // stops inside the second slab (black, 3 refracted rays).
    for (int max_depth : {4, 7}) {
        SceneData data = lamp_and_glass(glass_material(2.42, 0.9), Color(1.0));
        data.background = Color(1.0);
        for (double z : {0.0, -2.0, -4.0})
            data.primitives.push_back({Box{Point3(-5.0, -5.0, z - 0.5), Point3(5.0, 5.0, z + 0.5)}, 0});
        TracerRig rig(std::move(data), 5, max_depth);
        const Color c = rig.trace(Ray{Point3(0.1, 0.2, 3.0), -kUp});
        EXPECT_EQ(rig.stats.refracted, max_depth == 4 ? 3u : 6u) << "max_depth " << max_depth;
        EXPECT_TRUE(near(c, Color(max_depth == 4 ? 0.0 : std::pow(0.9, 6)), 1e-12)) << "max_depth " << max_depth;
    }
}

TEST(HiddenLab5Image, HiddenSceneMatchesTheReference) {
    expect_matches_reference(ImageCheck{"instructor/tests/hidden/scenes/05_refraction_hidden.p3f",
                                        "instructor/tests/hidden/05_refraction/05_refraction_hidden.png", 5});
}
