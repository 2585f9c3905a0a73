// Hidden tests of lab 6: Fresnel reflectance of water (1.33) and diamond (2.42), and
// the blend on other materials and angles than the public tests.
#include "whitted/labs.hpp"

#include "image_check.hpp"
#include "lab_helpers.hpp"
#include "test_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;

namespace {
double kr_at(double theta_degrees, double eta_i, double eta_t) {
    return fresnel_reflectance(std::cos(radians(theta_degrees)), eta_i, eta_t);
}
} // namespace

TEST(HiddenFresnelReflectance, WaterReflectsTwoPercentHeadOnAndSixPercentAt60Degrees) {
    // ((1.33 - 1) / 2.33)^2 = 0.0200593; at 60 degrees (Rs + Rp) / 2 = 0.0591256.
    EXPECT_NEAR(kr_at(0.0, 1.0, 1.33), 0.0200593, 1e-7);
    EXPECT_NEAR(kr_at(60.0, 1.0, 1.33), 0.0591256, 1e-7);
    EXPECT_NEAR(kr_at(85.0, 1.0, 1.33), 0.5827282, 1e-7);
}

TEST(HiddenFresnelReflectance, DiamondReflectsSeventeenPercentHeadOn) {
    // ((2.42 - 1) / 3.42)^2 = 0.172395; at 30 degrees 0.173883, at 60 degrees 0.211598.
    EXPECT_NEAR(kr_at(0.0, 1.0, 2.42), 0.1723949, 1e-7);
    EXPECT_NEAR(kr_at(30.0, 1.0, 2.42), 0.1738830, 1e-7);
    EXPECT_NEAR(kr_at(60.0, 1.0, 2.42), 0.2115976, 1e-7);
}

TEST(HiddenFresnelReflectance, InsideDiamondReflectsTotallyPast24Point4075Degrees) {
    // Diamond into air: 0.199066 at 20 degrees, 0.866129 at 24.4 (close to the critical
    // angle the reflectance shoots up), and exactly 1 at 24.5 and beyond.
    EXPECT_NEAR(kr_at(20.0, 2.42, 1.0), 0.1990662, 1e-7);
    EXPECT_NEAR(kr_at(24.4, 2.42, 1.0), 0.8661288, 1e-6);
    EXPECT_EQ(kr_at(24.5, 2.42, 1.0), 1.0);
    EXPECT_EQ(kr_at(55.0, 1.33, 1.0), 1.0) << "water: critical angle 48.7535 degrees";
}

TEST(HiddenFresnelReflectance, AtBrewstersAngleForWaterOnlyRsIsLeft) {
    // tan(theta_B) = 1.33: Rp = 0, Rs = ((1 - 1.33^2) / (1 + 1.33^2))^2 = 0.0771126, Kr = 0.0385563.
    EXPECT_NEAR(fresnel_reflectance(std::cos(std::atan(1.33)), 1.0, 1.33), 0.0385563, 1e-7);
}

TEST(HiddenFresnelReflectance, DiamondIsTheSameOnBothSidesAlongTheSamePath) {
    for (double theta : {10.0, 50.0, 80.0}) {
        const double theta_t = std::asin(std::sin(radians(theta)) / 2.42);
        EXPECT_NEAR(kr_at(theta, 1.0, 2.42), fresnel_reflectance(std::cos(theta_t), 2.42, 1.0), 1e-12)
            << "entering at " << theta << " degrees";
    }
    // Exact values entering: 0.172411 at 10 degrees, 0.433328 at 80.
    EXPECT_NEAR(kr_at(10.0, 1.0, 2.42), 0.172411, 1e-6);
    EXPECT_NEAR(kr_at(80.0, 1.0, 2.42), 0.433328, 1e-6);
}

namespace {
// A surface z = 0 of the given material between a red lamp above and a green one below.
SceneData between_lamps(const Material& material) {
    SceneData data;
    data.ambient = Color(1.0);
    data.materials = {material, diffuse_material(Color(1.0, 0.0, 0.0)), diffuse_material(Color(0.0, 1.0, 0.0))};
    data.primitives.push_back({Plane{Point3(0.0, 0.0, 3.0), -kUp}, 1});
    data.primitives.push_back({Plane{Point3(0.0, 0.0, -3.0), kUp}, 2});
    return data;
}
} // namespace

TEST(HiddenFresnelBlend, WaterAt60DegreesSendsSixPercentUpAndTheRestDown) {
    // Kr = 0.0591256 to the red lamp, (1 - Kr) T = 0.9408744 x 0.9 to the green one.
    TracerRig rig(between_lamps(glass_material(1.33, 0.9)), 6, 4);
    const Vec3 wo = direction_at(60.0, 300.0);
    const Color c = fresnel_blend(rig.tracer, hit_seen_from(Point3(0.0), kUp, wo), wo, 2);
    EXPECT_TRUE(near(c, Color(0.0591256, 0.9408744 * 0.9, 0.0), 1e-7));
}

TEST(HiddenFresnelBlend, InsideDiamondPastTheCriticalAngleEverythingGoesBackIn) {
    // From below (front_face false) at 30 degrees > 24.4075: Kr = 1, all green, no refracted ray.
    TracerRig rig(between_lamps(glass_material(2.42, 1.0)), 6, 4);
    const Vec3 wo = -direction_at(30.0, 45.0);
    const Color c = fresnel_blend(rig.tracer, hit_seen_from(Point3(0.0), kUp, wo), wo, 1);
    EXPECT_TRUE(near(c, Color(0.0, 1.0, 0.0), 1e-12));
    EXPECT_EQ(rig.stats.refracted, 0u);
}

TEST(HiddenFresnelBlend, ConservesEnergyForDiamondFromBothSides) {
    // T = 1: the two weights add up to 1 entering and leaving (below the critical angle).
    TracerRig rig(between_lamps(glass_material(2.42, 1.0)), 6, 4);
    for (double theta : {5.0, 20.0, 24.0}) {
        const Vec3 wo = -direction_at(theta);
        const Color c = fresnel_blend(rig.tracer, hit_seen_from(Point3(0.0), kUp, wo), wo, 1);
        EXPECT_NEAR(c.x + c.y, 1.0, 1e-12) << "leaving diamond at " << theta << " degrees";
    }
    for (double theta : {5.0, 50.0, 88.0}) {
        const Vec3 wo = direction_at(theta);
        const Color c = fresnel_blend(rig.tracer, hit_seen_from(Point3(0.0), kUp, wo), wo, 1);
        EXPECT_NEAR(c.x + c.y, 1.0, 1e-12) << "entering diamond at " << theta << " degrees";
    }
    // Entering at 5 degrees, Kr = 0.172396 goes up to the red lamp.
    const Vec3 wo = direction_at(5.0);
    EXPECT_NEAR(fresnel_blend(rig.tracer, hit_seen_from(Point3(0.0), kUp, wo), wo, 1).x, 0.172396, 1e-6);
}

TEST(HiddenFresnelBlend, ThePaneOfAWindowLetsThrough92PercentHeadOn) {
    // A glass pane (box 0.1 thick, T = 1, max_depth 3) seen head-on in front of a
    // green lamp: 0.96 at each face, 0.9216 of the green. The 4 % reflected at the
    // front goes to the black background.
    SceneData data = between_lamps(glass_material(1.5, 1.0));
    data.primitives.erase(data.primitives.begin()); // no red lamp behind the viewer
    data.primitives.push_back({Box{Point3(-2.0, -2.0, -0.05), Point3(2.0, 2.0, 0.05)}, 0});
    TracerRig rig(std::move(data), 6, 3);
    EXPECT_NEAR(rig.trace(Ray{Point3(0.3, -0.2, 2.0), -kUp}).y, 0.9216, 1e-9);
}

TEST(HiddenLab6Image, HiddenSceneMatchesTheReference) {
    expect_matches_reference(ImageCheck{"instructor/tests/hidden/scenes/06_fresnel_hidden.p3f",
                                        "instructor/tests/hidden/06_fresnel/06_fresnel_hidden.png", 6});
}
