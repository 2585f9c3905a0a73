// The reference shading on scenes small enough to work out by hand.
#include "whitted/labs.hpp"
#include "whitted/render.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;


TEST(Shading, BlinnPhongHighlightAtTheMirrorAngle) {
    // Eye and light symmetric about the normal: h = n, so the specular term is ks (h.n)^s = ks.
    SceneData data;
    Material m = diffuse_material(Color(0.2));
    m.specular = 0.5;
    m.shininess = 40.0;
    data.materials = {m};
    data.primitives.push_back({Plane{Point3(0.0), Vec3(0.0, 1.0, 0.0)}, 0});
    data.lights = {PointLight{Point3(3.0, 3.0, 0.0), Color(1.0)}};
    const Scene scene(std::move(data));
    const Color c = trace_one(scene, Ray{Point3(-3.0, 3.0, 0.0), glm::normalize(Vec3(1.0, -1.0, 0.0))}, 3);
    EXPECT_NEAR(c.x, 0.2 * std::cos(radians(45.0)) + 0.5, 1e-12);
}
