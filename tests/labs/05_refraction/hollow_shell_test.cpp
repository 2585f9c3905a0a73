// Lab 5, refraction() through nested surfaces: a hollow glass shell, whose inner
// wall is an inward sphere (its outward side faces the air-filled cavity).
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

using namespace whitted;
using namespace whitted::testing_helpers;

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
    data.materials = {glass_material(1.4), diffuse_material(Color(1.0, 0.0, 0.0))};
    data.primitives.push_back({Sphere{Point3(0.0), 1.0}, 0});
    data.primitives.push_back({Sphere{Point3(0.0), 0.96, true}, 0});
    data.primitives.push_back({Sphere{Point3(0.0), 0.3}, 1});
    const Scene scene(std::move(data));
    const Color through_centre = trace_one(scene, Ray{Point3(0.2, 0.0, 5.0), Vec3(0.0, 0.0, -1.0)}, 5);
    const Color past_ball = trace_one(scene, Ray{Point3(0.5, 0.0, 5.0), Vec3(0.0, 0.0, -1.0)}, 5);
    ASSERT_TRUE(is_finite(through_centre) && is_finite(past_ball)) << "NaN or infinity in a colour";
    EXPECT_GT(through_centre.x, 0.8) << "at b = 0.2 the ray must reach the red ball in the cavity";
    EXPECT_LT(through_centre.z, 0.1);
    EXPECT_LT(past_ball.x, 0.1) << "at b = 0.5 the ray must pass the red ball: at the inner wall (front_face "
                                   "false) the ray leaves the glass, from material.ior into air";
    EXPECT_GT(past_ball.z, 0.8);
}
