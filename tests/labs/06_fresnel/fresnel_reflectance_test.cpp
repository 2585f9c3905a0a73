// Lab 6, fresnel_reflectance(): Kr = (Rs + Rp) / 2 with
//   Rs = ((eta_i cos_i - eta_t cos_t) / (eta_i cos_i + eta_t cos_t))^2,
//   Rp = ((eta_i cos_t - eta_t cos_i) / (eta_i cos_t + eta_t cos_i))^2,
// cos_t from Snell's law, and Kr = 1 on total internal reflection.
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;

namespace {
double kr_at(double theta_degrees, double eta_i, double eta_t) {
    return fresnel_reflectance(std::cos(radians(theta_degrees)), eta_i, eta_t);
}
} // namespace

TEST(FresnelReflectance, IsFourPercentAtNormalIncidenceOnGlass) {
    // cos_i = cos_t = 1: Rs = Rp = ((1 - 1.5) / (1 + 1.5))^2 = 0.04, so Kr = 0.04.
    EXPECT_NEAR(kr_at(0.0, 1.0, 1.5), 0.04, 1e-12) << "Rs = Rp = 0.04 here: is (Rs + Rp) halved?";
}

TEST(FresnelReflectance, MatchesTheExactEquationsAt45And80Degrees) {
    // Exact Fresnel, air into glass: 0.050240 at 45 degrees, 0.387704 at 80.
    // Schlick's approximation would give 0.409910 at 80 degrees: too much.
    EXPECT_NEAR(kr_at(45.0, 1.0, 1.5), 0.050240, 1e-6);
    EXPECT_NEAR(kr_at(80.0, 1.0, 1.5), 0.387704, 1e-6) << "0.409910 would be Schlick's approximation, not (Rs + Rp) / 2";
}

TEST(FresnelReflectance, IsHalfOfRsAtBrewstersAngle) {
    // At Brewster's angle tan(theta_i) = 1.5 the reflected and refracted rays are
    // perpendicular: cos_t = sin_i, so Rp = 0 and Rs = ((1 - 1.5^2) / (1 + 1.5^2))^2
    // = (1.25 / 3.25)^2 = 0.147929. Kr = Rs / 2 = 0.0739645.
    EXPECT_NEAR(fresnel_reflectance(std::cos(std::atan(1.5)), 1.0, 1.5), 0.0739645, 1e-7)
        << "Rp vanishes here: Kr must be Rs / 2";
}

TEST(FresnelReflectance, LeavingGlassAt30Degrees) {
    // Glass into air: sin_t = 1.5 sin(30) = 0.75, cos_t = 0.661438, cos_i = 0.866025.
    // Rs = ((1.299038 - 0.661438) / 1.960476)^2 = 0.105773,
    // Rp = ((0.992157 - 0.866025) / 1.858182)^2 = 0.004608, Kr = 0.055190.
    EXPECT_NEAR(kr_at(30.0, 1.5, 1.0), 0.0551902, 1e-7) << "cos_t comes from sin_t = eta_i / eta_t sin_i";
}

TEST(FresnelReflectance, TotalInternalReflectionReflectsEverything) {
    // Glass into air beyond asin(1 / 1.5) = 41.8103 degrees: Kr is exactly 1 (no NaN).
    EXPECT_EQ(kr_at(41.82, 1.5, 1.0), 1.0);
    EXPECT_EQ(kr_at(60.0, 1.5, 1.0), 1.0);
    EXPECT_EQ(kr_at(89.0, 1.5, 1.0), 1.0);
    // Just inside the critical angle, at 41.80 degrees, much but not all is reflected: cos_t = 0.020064,
    // Rs = 0.930738, Rp = 0.850806, Kr = 0.890772.
    EXPECT_NEAR(kr_at(41.80, 1.5, 1.0), 0.890772, 1e-6) << "below the critical angle Kr comes from the equations";
}

TEST(FresnelReflectance, IsOneAtExactlyTheCriticalAngle) {
    // From eta 1.25 into air at cos(theta_i) = 0.6: sin^2(theta_t) = 1.5625 x 0.64 = 1
    // exactly, lab 5's condition for total internal reflection; the equations
    // agree there (cos_t = 0 gives Rs = 1, Rp = 1), and nothing may be NaN.
    EXPECT_EQ(fresnel_reflectance(0.6, 1.25, 1.0), 1.0);
    // A little steeper, cos(theta_i) = 0.61: cos_t = 0.1375 (see lab 5), Rs = (0.625 / 0.9)^2 = 0.482253,
    // Rp = (0.438125 / 0.781875)^2 = 0.313994, Kr = 0.398124.
    EXPECT_NEAR(fresnel_reflectance(0.61, 1.25, 1.0), 0.398124, 1e-6);
}

TEST(FresnelReflectance, IsTheSameOnBothSidesAlongTheSamePath) {
    // Light entering at 45 degrees and light leaving along the refracted path
    // (theta_t = 28.1255 degrees) reflect the same fraction.
    const double theta_t = std::asin(std::sin(radians(45.0)) / 1.5);
    EXPECT_NEAR(kr_at(45.0, 1.0, 1.5), fresnel_reflectance(std::cos(theta_t), 1.5, 1.0), 1e-12);
    EXPECT_NEAR(fresnel_reflectance(std::cos(theta_t), 1.5, 1.0), 0.050240, 1e-6) << "both are 0.050240";
}

TEST(FresnelReflectance, GrazingLightIsAlmostAllReflected) {
    // As theta_i -> 90 degrees cos_i -> 0 and Rs, Rp -> 1.
    EXPECT_GT(fresnel_reflectance(1e-6, 1.0, 1.5), 0.9999);
    EXPECT_LE(fresnel_reflectance(1e-6, 1.0, 1.5), 1.0);
    // Not yet at 89 degrees: Rs = 0.939472, Rp = 0.868898, Kr = 0.904185.
    EXPECT_NEAR(kr_at(89.0, 1.0, 1.5), 0.904185, 1e-6);
}

TEST(FresnelReflectance, GrowsWithTheAngleFromAirIntoGlass) {
    // From air into glass Kr rises from 0.04 to 1 without ever falling (Rp dips to 0
    // at Brewster's angle, but Rs grows faster).
    double previous = kr_at(0.0, 1.0, 1.5);
    EXPECT_NEAR(previous, 0.04, 1e-12) << "at 0 degrees";
    for (double theta = 1.0; theta < 90.0; theta += 1.0) {
        const double kr = kr_at(theta, 1.0, 1.5);
        EXPECT_GE(kr, previous) << "Kr fell between " << theta - 1.0 << " and " << theta << " degrees";
        EXPECT_LE(kr, 1.0) << "at " << theta << " degrees";
        previous = kr;
        if (testing_helpers::enough_failures()) return;
    }
    EXPECT_GT(previous, 0.9) << "at 89 degrees";
}

TEST(FresnelReflectance, EqualIndicesReflectNothing) {
    // eta_i = eta_t: no interface, cos_t = cos_i, Rs = Rp = 0.
    for (double theta : {0.0, 30.0, 60.0, 85.0}) {
        EXPECT_NEAR(kr_at(theta, 1.0, 1.0), 0.0, 1e-15) << "air to air at " << theta << " degrees";
        EXPECT_NEAR(kr_at(theta, 1.5, 1.5), 0.0, 1e-15) << "glass to glass at " << theta << " degrees";
    }
    // Air to glass at those angles reflects 0.04 (0 degrees) to 0.089187 (60 degrees): the indices differ.
    EXPECT_NEAR(kr_at(60.0, 1.0, 1.5), 0.089187, 1e-6) << "air to glass at 60 degrees";
}
