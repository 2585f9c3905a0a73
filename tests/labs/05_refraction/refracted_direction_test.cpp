// Lab 5, refracted_direction(): Snell's law eta_i sin(theta_i) = eta_t sin(theta_t),
// checked against values worked out by hand. wo points back along the incoming
// ray; the refracted direction continues on the other side of the surface (-n).
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"
#include "test_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;

TEST(RefractedDirection, At45DegreesIntoGlassBendsTo28Point1255Degrees) {
    // sin(theta_t) = sin(45) / 1.5 = 0.471405, theta_t = 28.1255 degrees. The ray keeps
    // going forward: wo leans towards +x, so wt = (-sin(theta_t), 0, -cos(theta_t)).
    const auto wt = refracted_direction(direction_at(45.0), kUp, 1.0, 1.5);
    ASSERT_TRUE(wt.has_value()) << "45 degrees from air into glass is not total internal reflection";
    EXPECT_NEAR(degrees_between(*wt, -kUp), 28.1255, 1e-4) << "angle between wt and -n";
    const double sin_t = std::sin(radians(45.0)) / 1.5;
    EXPECT_TRUE(near(*wt, Vec3(-sin_t, 0.0, -std::sqrt(1.0 - sin_t * sin_t)), 1e-14));
}

TEST(RefractedDirection, At80DegreesIntoGlassBendsTo41Point0364Degrees) {
    // sin(theta_t) = sin(80) / 1.5 = 0.656539, theta_t = 41.0364 degrees.
    const auto wt = refracted_direction(direction_at(80.0), kUp, 1.0, 1.5);
    ASSERT_TRUE(wt.has_value());
    EXPECT_NEAR(degrees_between(*wt, -kUp), 41.0364, 1e-4);
    EXPECT_LT(wt->x, 0.0) << "the refracted ray must keep going forward (tangent part opposite to wo's)";
}

TEST(RefractedDirection, NormalIncidenceGoesStraightThrough) {
    // theta_i = 0 gives theta_t = 0: wt = -n, with no NaN from the zero tangent.
    const auto wt = refracted_direction(kUp, kUp, 1.0, 1.5);
    ASSERT_TRUE(wt.has_value());
    EXPECT_TRUE(near(*wt, -kUp, 1e-15));
    // One degree off the normal the ray bends towards it: sin(theta_t) = sin(1) / 1.5, theta_t = 0.666648 degrees.
    const auto tilted = refracted_direction(direction_at(1.0), kUp, 1.0, 1.5);
    ASSERT_TRUE(tilted.has_value());
    const double sin_t = std::sin(radians(1.0)) / 1.5;
    EXPECT_TRUE(near(*tilted, Vec3(-sin_t, 0.0, -std::sqrt(1.0 - sin_t * sin_t)), 1e-15))
        << "at 1 degree from the normal the ray bends to 0.666648 degrees";
}

TEST(RefractedDirection, LeavingGlassBendsAwayFromTheNormal) {
    // From glass into air at 20 degrees: sin(theta_t) = 1.5 sin(20) = 0.513030,
    // theta_t = 30.8659 degrees (larger than theta_i).
    const auto wt = refracted_direction(direction_at(20.0), kUp, 1.5, 1.0);
    ASSERT_TRUE(wt.has_value());
    EXPECT_NEAR(degrees_between(*wt, -kUp), 30.8659, 1e-4);
    // The way back: leaving at 28.1255 degrees comes out at 45 (the path is reversible).
    const auto back = refracted_direction(direction_at(std::asin(std::sin(radians(45.0)) / 1.5) * 180.0 / kPi), kUp, 1.5, 1.0);
    ASSERT_TRUE(back.has_value());
    EXPECT_NEAR(degrees_between(*back, -kUp), 45.0, 1e-9);
}

TEST(RefractedDirection, IsAUnitVectorOnTheFarSideOfTheSurface) {
    for (double theta : {0.0, 10.0, 35.0, 60.0, 89.0}) {
        for (double eta_t : {1.2, 1.5, 2.0}) {
            SCOPED_TRACE(::testing::Message() << "air into eta " << eta_t << " at " << theta << " degrees");
            const auto wt = refracted_direction(direction_at(theta, 30.0), kUp, 1.0, eta_t);
            ASSERT_TRUE(wt.has_value());
            EXPECT_NEAR(glm::length(*wt), 1.0, 1e-14) << "wt must be a unit vector";
            EXPECT_LT(glm::dot(*wt, kUp), 0.0) << "wt must go through the surface, against n";
            EXPECT_NEAR(std::sin(radians(degrees_between(*wt, -kUp))), std::sin(radians(theta)) / eta_t, 1e-9)
                << "Snell's law: sin(theta_t) = sin(theta_i) / eta_t";
        }
    }
}

TEST(RefractedDirection, StaysInThePlaneOfIncidence) {
    // wo at 50 degrees, azimuth 120 degrees: wt is a mix of n and wo's tangent part,
    // so it is perpendicular to n x wo, and its tangent part points away from wo's.
    const Vec3 wo = direction_at(50.0, 120.0);
    const auto wt = refracted_direction(wo, kUp, 1.0, 1.5);
    ASSERT_TRUE(wt.has_value());
    EXPECT_NEAR(glm::dot(*wt, glm::cross(kUp, wo)), 0.0, 1e-14) << "wt must lie in the plane of wo and n";
    EXPECT_LT(wt->x * wo.x + wt->y * wo.y, 0.0) << "the tangent part of wt must be opposite to wo's";
    // Its tangent part is sin(theta_t) = sin(50) / 1.5 = 0.510689 long, shorter than wo's: bent towards -n.
    EXPECT_NEAR(std::hypot(wt->x, wt->y), std::sin(radians(50.0)) / 1.5, 1e-14);
}

TEST(RefractedDirection, WorksForANormalThatIsNotAnAxis) {
    // Rotating the whole setup must rotate the answer: n = (0, 1, 0), wo at 45 degrees
    // in the xy-plane gives wt = (-sin(theta_t), -cos(theta_t), 0) with sin(theta_t) = 0.471405.
    const Vec3 n(0.0, 1.0, 0.0);
    const Vec3 wo(std::sin(radians(45.0)), std::cos(radians(45.0)), 0.0);
    const auto wt = refracted_direction(wo, n, 1.0, 1.5);
    ASSERT_TRUE(wt.has_value());
    const double sin_t = std::sin(radians(45.0)) / 1.5;
    EXPECT_TRUE(near(*wt, Vec3(-sin_t, -std::sqrt(1.0 - sin_t * sin_t), 0.0), 1e-14));
}

TEST(RefractedDirection, TotalInternalReflectionGivesNoDirectionJustPastTheCriticalAngle) {
    // Critical angle from glass into air: asin(1 / 1.5) = 41.8103 degrees.
    // At 41.82 degrees 1.5 sin(theta_i) > 1: there is no refracted ray (std::nullopt).
    EXPECT_FALSE(refracted_direction(direction_at(41.82), kUp, 1.5, 1.0).has_value())
        << "past the critical angle there must be no refracted direction (not NaN, not the mirror direction)";
    EXPECT_FALSE(refracted_direction(direction_at(70.0), kUp, 1.5, 1.0).has_value());
    // Below it, at 40 degrees, the ray gets out: sin(theta_t) = 1.5 sin(40) = 0.964181, theta_t = 74.6186 degrees.
    const auto out = refracted_direction(direction_at(40.0), kUp, 1.5, 1.0);
    ASSERT_TRUE(out.has_value()) << "40 degrees is below the critical angle of 41.8103";
    EXPECT_NEAR(degrees_between(*out, -kUp), 74.6186, 1e-4);
}

TEST(RefractedDirection, AtExactlyTheCriticalAngleThereIsNoRefractedRay) {
    // From eta 1.25 into air with cos(theta_i) = 0.6, sin(theta_i) = 0.8:
    // sin^2(theta_t) = 1.25^2 (1 - 0.6^2) = 1.5625 x 0.64 = 1, exactly in doubles
    // (and 1.25 x sqrt(0.64) = 1 too). The refracted ray would run along the
    // surface: the contract (labs.hpp) counts sin^2(theta_t) >= 1 as total
    // internal reflection, as lab 6's fresnel_reflectance() does.
    const Vec3 wo(0.8, 0.0, 0.6); // kUp is +z
    ASSERT_EQ(glm::dot(wo, kUp), 0.6);
    EXPECT_FALSE(refracted_direction(wo, kUp, 1.25, 1.0).has_value())
        << "at exactly the critical angle (sin^2 theta_t = 1) there is no refracted direction";
    // A little steeper, cos(theta_i) = 0.61: sin^2(theta_t) = 1.5625 (1 - 0.3721) = 0.98109375 < 1, so
    // cos(theta_t) = sqrt(0.01890625) = 0.1375 and the ray gets out close to the surface.
    const auto out = refracted_direction(Vec3(std::sqrt(1.0 - 0.61 * 0.61), 0.0, 0.61), kUp, 1.25, 1.0);
    ASSERT_TRUE(out.has_value()) << "cos(theta_i) = 0.61 is inside the critical angle";
    EXPECT_NEAR(out->z, -0.1375, 1e-12) << "cos(theta_t) = 0.1375";
}

TEST(RefractedDirection, JustBeforeTheCriticalAngleTheRayLeavesAlmostAlongTheSurface) {
    // At 41.80 degrees: sin(theta_t) = 1.5 sin(41.80) = 0.999799, theta_t = 88.8504 degrees.
    const auto wt = refracted_direction(direction_at(41.80), kUp, 1.5, 1.0);
    ASSERT_TRUE(wt.has_value()) << "41.80 degrees is below the critical angle of 41.8103";
    EXPECT_NEAR(degrees_between(*wt, -kUp), 88.8504, 1e-4);
}
