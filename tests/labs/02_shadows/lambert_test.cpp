// The reference shading on scenes small enough to work out by hand.
#include "whitted/labs.hpp"
#include "whitted/render.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;


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
    // A small sphere halfway between the floor point and the light: no light arrives (Lambert only, stage 2).
    SceneData data;
    data.materials = {diffuse_material(Color(1.0))};
    data.primitives.push_back({Plane{Point3(0.0), Vec3(0.0, 1.0, 0.0)}, 0});
    data.primitives.push_back({Sphere{Point3(0.0, 2.0, 0.0), 0.2}, 0});
    data.lights = {PointLight{Point3(0.0, 4.0, 0.0), Color(1.0)}};
    const Scene scene(std::move(data));
    const Ray down{Point3(0.5, 1.0, 0.5), glm::normalize(Vec3(-0.5, -1.0, -0.5))}; // hits the origin
    EXPECT_EQ(trace_one(scene, down, 2).x, 0.0);
    // One unit to the side the feeler passes the blocker: n . L = 4 / sqrt(17).
    const Ray beside{Point3(1.0, 1.0, 0.0), Vec3(0.0, -1.0, 0.0)};
    EXPECT_NEAR(trace_one(scene, beside, 2).x, 4.0 / std::sqrt(17.0), 1e-12);
}
