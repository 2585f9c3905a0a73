// Lab 4, mirror_direction(): r = 2 (wo . n) n - wo, checked against values worked out by hand.
// Both wo and r point away from the surface (unlike GLSL's reflect(), whose input points at it).
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"
#include "test_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;

TEST(MirrorDirection, At30DegreesKeepsTheNormalPartAndFlipsTheTangent) {
    // wo = (sin 30, 0, cos 30) = (1/2, 0, sqrt(3)/2), n = +z: wo . n = sqrt(3)/2, so
    // r = 2 (sqrt(3)/2) (0, 0, 1) - wo = (-1/2, 0, sqrt(3)/2).
    EXPECT_TRUE(near(mirror_direction(direction_at(30.0), kUp), Vec3(-0.5, 0.0, std::sqrt(3.0) / 2.0), 1e-15));
}

TEST(MirrorDirection, StaysOnTheSameSideOfTheSurfaceAsWo) {
    // wo points away from the surface, and so must r: r . n = wo . n = cos(60) = 1/2.
    // A result below the surface (r . n < 0) usually means the GLSL convention
    // wo - 2 (wo . n) n, which expects the incoming direction, not wo.
    const Vec3 r = mirror_direction(direction_at(60.0), kUp);
    EXPECT_NEAR(glm::dot(r, kUp), 0.5, 1e-15) << "r must leave the surface on the side of wo and n";
    // Along the surface it goes the other way: wo leans towards +x (sin 60), r as much towards -x.
    EXPECT_NEAR(r.x, -std::sin(radians(60.0)), 1e-15) << "r leans away from wo along the surface";
}

TEST(MirrorDirection, NormalIncidenceReflectsStraightBack) {
    // wo = n: r = 2 (1) n - n = n, for n = +z and for n = (1, 2, 2) / 3.
    EXPECT_TRUE(near(mirror_direction(kUp, kUp), kUp, 1e-15));
    const Vec3 n = Vec3(1.0, 2.0, 2.0) / 3.0;
    EXPECT_TRUE(near(mirror_direction(n, n), n, 1e-15));
    // One degree off the normal, r is one degree off on the other side: (-sin 1, 0, cos 1).
    EXPECT_TRUE(near(mirror_direction(direction_at(1.0), kUp), Vec3(-std::sin(radians(1.0)), 0.0, std::cos(radians(1.0))), 1e-15));
}

TEST(MirrorDirection, GrazingIncidenceContinuesAlongTheSurface) {
    // wo at 90 degrees lies in the surface: wo . n = 0, so r = -wo.
    const Vec3 wo(1.0, 0.0, 0.0);
    EXPECT_TRUE(near(mirror_direction(wo, kUp), -wo, 1e-15));
    // Just above the surface (89.9 degrees) r is wo with its tangent flipped.
    const Vec3 almost = direction_at(89.9);
    EXPECT_TRUE(near(mirror_direction(almost, kUp), Vec3(-almost.x, 0.0, almost.z), 1e-15));
}

TEST(MirrorDirection, WorksForANormalThatIsNotAnAxis) {
    // n = (1, 1, 1) / sqrt(3), wo = (1, 0, 0): wo . n = 1/sqrt(3), so
    // r = 2 / sqrt(3) (1, 1, 1) / sqrt(3) - (1, 0, 0) = (-1/3, 2/3, 2/3).
    const Vec3 n = glm::normalize(Vec3(1.0, 1.0, 1.0));
    EXPECT_TRUE(near(mirror_direction(Vec3(1.0, 0.0, 0.0), n), Vec3(-1.0, 2.0, 2.0) / 3.0, 1e-15));
}

TEST(MirrorDirection, IsAUnitVectorSymmetricToWoAboutTheNormal) {
    // For unit wo and n: |r| = 1, r . n = wo . n (same angle to the normal), and
    // wo + r = 2 (wo . n) n lies along n (r is in the plane of wo and n, on the other side).
    for (double theta : {5.0, 25.0, 47.0, 71.0, 88.0}) {
        for (double phi : {0.0, 40.0, 135.0, 260.0}) {
            SCOPED_TRACE(::testing::Message() << "wo at theta " << theta << ", phi " << phi << " degrees");
            const Vec3 wo = direction_at(theta, phi);
            const Vec3 r = mirror_direction(wo, kUp);
            EXPECT_NEAR(glm::length(r), 1.0, 1e-14) << "r must be a unit vector";
            EXPECT_NEAR(glm::dot(r, kUp), glm::dot(wo, kUp), 1e-14) << "angle of incidence = angle of reflection";
            EXPECT_NEAR(glm::length(glm::cross(wo + r, kUp)), 0.0, 1e-14) << "wo + r must lie along n";
            if (enough_failures()) return;
        }
    }
}

TEST(MirrorDirection, ReflectingTwiceGivesWoBack) {
    // r(r(wo)) = 2 (r . n) n - r = 2 (wo . n) n - (2 (wo . n) n - wo) = wo.
    const Vec3 n = glm::normalize(Vec3(-0.3, 0.8, 0.5));
    const Vec3 wo = glm::normalize(Vec3(0.2, 0.9, -0.1));
    EXPECT_TRUE(near(mirror_direction(mirror_direction(wo, n), n), wo, 1e-14));
    // Once is not the identity: r - wo = 2 ((wo . n) n - wo), twice the part of wo along the surface,
    // whose length is sin(theta) = sqrt(1 - (wo . n)^2).
    const double c = glm::dot(wo, n);
    EXPECT_NEAR(glm::length(mirror_direction(wo, n) - wo), 2.0 * std::sqrt(1.0 - c * c), 1e-14);
}
