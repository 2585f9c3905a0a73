// The ray tree the Tracer records (whitted trace, --pass): analytic scenes
// whose trees can be worked out by hand, and the promise that recording never
// changes a colour.
#include "lab_helpers.hpp"
#include "whitted/render.hpp"

#include <gtest/gtest.h>

#include <cstring>

using namespace whitted;
using namespace whitted::testing_helpers;

namespace {

bool same_bits(const Color& a, const Color& b) { return std::memcmp(&a, &b, sizeof(Color)) == 0; }

// A mirror, a glass ball and a hollow glass shell over a checkered floor, two lights.
SceneData busy_scene(int size) {
    SceneData data;
    data.camera = Camera::create(Point3(0.0, 1.5, 6.0), Point3(0.0, 1.0, 0.0), Vec3(0.0, 1.0, 0.0), 45.0, size, size);
    data.background = Color(0.2, 0.3, 0.5);
    data.ambient = Color(0.1);
    data.lights = {PointLight{Point3(5.0, 8.0, 5.0), Color(0.8)}, PointLight{Point3(-6.0, 4.0, 2.0), Color(0.4)}};
    Material floor;
    floor.checker = Checker{Color(0.9), Color(0.2), 1.0};
    Material glass = glass_material(1.5, 0.9);
    glass.specular = 0.1;
    data.materials = {floor, mirror_material(0.6), glass};
    data.primitives.push_back({Plane{Point3(0.0), Vec3(0.0, 1.0, 0.0)}, 0});
    data.primitives.push_back({Sphere{Point3(-1.1, 1.0, 0.0), 1.0}, 1});
    data.primitives.push_back({Sphere{Point3(1.1, 1.0, 0.5), 0.9}, 2});
    data.primitives.push_back({Sphere{Point3(0.0, 1.0, 2.0), 0.7}, 2});
    data.primitives.push_back({Sphere{Point3(0.0, 1.0, 2.0), 0.65, true}, 2});
    return data;
}

} // namespace

TEST(RayTree, RecordingChangesNoPixelAndTheRootHoldsThePixelsColour) {
    const Scene scene(busy_scene(40));
    for (int stage = 1; stage <= 6; ++stage) {
        RenderSettings settings;
        settings.stage = stage;
        const Image image = render(scene, settings, 1).image;
        RayStats stats;
        RayTree tree;
        const Tracer tracer(scene, settings, stats, &tree);
        for (int row = 0; row < 40; ++row) {
            for (int x = 0; x < 40; ++x) {
                const Color color = tracer.trace_pixel(x + 0.5, (39 - row) + 0.5);
                ASSERT_TRUE(same_bits(color, image.at(x, row))) << "stage " << stage << " pixel " << x << " " << row;
                ASSERT_TRUE(same_bits(tree.nodes.front().color, color));
            }
        }
    }
}

TEST(RayTree, EveryRayAddsWeightTimesItsPartsToItsParent) {
    // color = weight * (local + reflection + refraction + fresnel), and each part
    // a secondary-ray function returned is the sum of its rays' colours.
    const Scene scene(busy_scene(24));
    RenderSettings settings;
    RayStats stats;
    RayTree tree;
    const Tracer tracer(scene, settings, stats, &tree);
    int checked = 0;
    for (int y = 0; y < 24; ++y) {
        for (int x = 0; x < 24; ++x) {
            tracer.trace_pixel(x + 0.5, y + 0.5);
            for (const RayNode& node : tree.nodes) {
                if (node.kind == RayKind::shadow || node.fate != RayFate::traced || !node.hit) continue;
                Color parts = *node.local;
                if (node.reflection) parts += *node.reflection;
                if (node.refraction) parts += *node.refraction;
                if (node.fresnel) parts += *node.fresnel;
                ASSERT_TRUE(same_bits(node.color, node.weight * parts));
                Color children(0.0);
                for (int child : node.children) children += tree.nodes[child].color;
                if (node.fresnel) {
                    EXPECT_NEAR(glm::length(children - *node.fresnel), 0.0, 1e-12);
                }
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 24 * 24);
}

TEST(RayTree, HeadOnIntoAGlassBall) {
    // Eye ray from (0, 0, 5) along -z into a glass ball of radius 1 at the origin
    // (ior 1.5, T = 0.9). It hits the front at t = 4, from outside. At normal
    // incidence Fresnel gives Kr = ((1 - 1.5) / (1 + 1.5))^2 = 0.04, so the
    // reflected ray has weight 0.04 and the refracted one (1 - 0.04) * 0.9 = 0.864;
    // the refracted ray goes straight on and leaves through the back after t = 2,
    // from inside. No light: no shadow feelers.
    SceneData data;
    data.materials = {glass_material(1.5, 0.9)};
    data.primitives.push_back({Sphere{Point3(0.0), 1.0}, 0});
    const Scene scene(std::move(data));
    RenderSettings settings;
    settings.max_depth = 2;
    RayStats stats;
    RayTree tree;
    const Tracer tracer(scene, settings, stats, &tree);
    tracer.trace(Ray{Point3(0.0, 0.0, 5.0), Vec3(0.0, 0.0, -1.0)}, 1, RayKind::eye, Color(1.0));

    ASSERT_EQ(tree.nodes.size(), 3u);
    const RayNode& eye = tree.nodes[0];
    ASSERT_TRUE(eye.hit);
    EXPECT_DOUBLE_EQ(eye.hit->t, 4.0);
    EXPECT_TRUE(eye.hit->front_face);
    ASSERT_EQ(eye.children.size(), 2u);
    const RayNode& reflected = tree.nodes[eye.children[0]];
    const RayNode& refracted = tree.nodes[eye.children[1]];
    EXPECT_EQ(reflected.kind, RayKind::reflected);
    EXPECT_NEAR(reflected.weight.x, 0.04, 1e-12);
    EXPECT_EQ(refracted.kind, RayKind::refracted);
    EXPECT_EQ(refracted.depth, 2);
    EXPECT_EQ(refracted.parent, 0);
    EXPECT_NEAR(refracted.weight.x, 0.864, 1e-12);
    EXPECT_NEAR(refracted.path_weight.x, 0.864, 1e-12);
    EXPECT_NEAR(glm::length(refracted.ray.direction - Vec3(0.0, 0.0, -1.0)), 0.0, 1e-12);
    ASSERT_TRUE(refracted.hit);
    EXPECT_NEAR(refracted.hit->t, 2.0, 1e-6);
    EXPECT_FALSE(refracted.hit->front_face);
    EXPECT_TRUE(eye.fresnel.has_value());
    EXPECT_FALSE(eye.reflection.has_value()); // stage 6: fresnel_blend() replaces reflection() and refraction()
}

TEST(RayTree, ABlockedFeelerNamesItsBlockerAndWhere) {
    // The floor y = 0 seen at the origin; the light at (0, 5, 0) straight above;
    // a ball of radius 0.5 at (0, 2, 0) in between. The feeler goes up from the
    // origin and meets the ball's bottom at t = 1.5 of its 5.
    SceneData data;
    data.lights = {PointLight{Point3(0.0, 5.0, 0.0), Color(1.0)}};
    data.materials = {diffuse_material(Color(1.0))};
    data.primitives.push_back({Plane{Point3(0.0), Vec3(0.0, 1.0, 0.0)}, 0});
    data.primitives.push_back({Sphere{Point3(0.0, 2.0, 0.0), 0.5}, 0});
    const Scene scene(std::move(data));
    RenderSettings settings;
    settings.stage = 2;
    RayStats stats;
    RayTree tree;
    const Tracer tracer(scene, settings, stats, &tree);
    const Color color = tracer.trace(Ray{Point3(3.0, 1.0, 0.0), glm::normalize(Vec3(-3.0, -1.0, 0.0))}, 1, RayKind::eye, Color(1.0));

    EXPECT_EQ(color, Color(0.0));
    ASSERT_EQ(tree.nodes.size(), 2u);
    const RayNode& feeler = tree.nodes[1];
    EXPECT_EQ(feeler.kind, RayKind::shadow);
    EXPECT_EQ(feeler.parent, 0);
    EXPECT_TRUE(feeler.blocked);
    EXPECT_NEAR(feeler.light_distance, 5.0, 1e-6);
    ASSERT_TRUE(feeler.hit);
    EXPECT_TRUE(std::holds_alternative<Sphere>(scene.primitives()[feeler.hit->primitive].shape));
    EXPECT_NEAR(feeler.hit->t, 1.5, 1e-6);
    EXPECT_NEAR(feeler.t_range.max, 5.0 * (1.0 - 1e-6), 1e-6);
}

TEST(RayTree, RaysBelowTheMinimumWeightAreRecordedButNotCast) {
    // A mirror with Ks = 0.5: its reflected ray's weight 0.5 is below a minimum of 0.6.
    SceneData data;
    data.materials = {mirror_material(0.5)};
    data.primitives.push_back({Sphere{Point3(0.0), 1.0}, 0});
    const Scene scene(std::move(data));
    RenderSettings settings;
    settings.min_weight = 0.6;
    RayStats stats;
    RayTree tree;
    const Tracer tracer(scene, settings, stats, &tree);
    tracer.trace(Ray{Point3(0.0, 0.0, 5.0), Vec3(0.0, 0.0, -1.0)}, 1, RayKind::eye, Color(1.0));
    ASSERT_EQ(tree.nodes.size(), 2u);
    EXPECT_EQ(tree.nodes[1].kind, RayKind::reflected);
    EXPECT_EQ(tree.nodes[1].fate, RayFate::below_min_weight);
    EXPECT_FALSE(tree.nodes[1].hit.has_value());
    EXPECT_EQ(stats.reflected, 0u);
}
