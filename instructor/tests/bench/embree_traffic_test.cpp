// The Embree harness: its scene answers the ray queries as our Scene does, for
// every kind of shape, and its ray traffic is the ray tree whitted shoots.
#include "embree_scene.hpp"
#include "embree_traffic.hpp"
#include "test_helpers.hpp"
#include "whitted/lab_status.hpp"
#include "whitted/render.hpp"
#include "whitted/scene_loader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

using namespace whitted;
using whitted::bench::EmbreeScene;
using whitted::bench::EmbreeSettings;
using whitted::bench::RayCounts;
using whitted::bench::shoot_ray_traffic;
using whitted::testing_helpers::make_ray;
using whitted::testing_helpers::near;

namespace {

Primitive primitive(Shape shape, std::uint32_t material, std::int32_t normals = -1) {
    Primitive p;
    p.shape = shape;
    p.material = material;
    p.vertex_normals = normals;
    return p;
}

// A small room with one of every shape: mirror, glass and matte materials.
SceneData every_kind() {
    SceneData data;
    data.camera = Camera::create({0, 1.5, 6}, {0, 1, 0}, {0, 1, 0}, 55.0, 48, 36);
    data.ambient = Color(0.1);
    data.lights.push_back(PointLight{{3, 5, 4}, Color(0.8)});
    data.lights.push_back(PointLight{{-4, 3, 2}, Color(0.5)});
    Material matte;
    matte.color = Color(0.7, 0.6, 0.5);
    matte.diffuse = 0.9;
    Material mirror = matte;
    mirror.specular = 0.6;
    mirror.shininess = 40.0;
    Material glass = matte;
    glass.diffuse = 0.1;
    glass.specular = 0.2;
    glass.transmittance = 0.9;
    glass.ior = 1.5;
    data.materials = {matte, mirror, glass};
    data.primitives.push_back(primitive(Plane{{0, 0, 0}, {0, 1, 0}}, 1));
    data.primitives.push_back(primitive(Sphere{{-1.2, 1, 0}, 0.7, false}, 1));
    data.primitives.push_back(primitive(Sphere{{1.2, 1, 0.5}, 0.6, false}, 2));
    data.primitives.push_back(primitive(Sphere{{1.2, 1, 0.5}, 0.5, true}, 2));
    data.primitives.push_back(primitive(Box{{-2.5, 0, -2}, {-1.5, 1, -1}}, 0));
    data.primitives.push_back(primitive(Cone{{2, 0, -1.5}, 0.6, {2, 1.5, -1.5}, 0.1, false}, 1));
    data.primitives.push_back(primitive(Cone{{0, 0, -2}, 0.5, {0, 2, -2}, 0.5, true}, 0));
    data.primitives.push_back(primitive(Triangle{{-3, 0, -3}, {3, 0, -3}, {0, 3, -3}}, 1));
    data.vertex_normals.push_back(VertexNormals{glm::normalize(Vec3(-0.3, 0, 1)), glm::normalize(Vec3(0.3, 0, 1)),
                                                glm::normalize(Vec3(0, 0.3, 1))});
    data.primitives.push_back(primitive(Triangle{{-0.5, 2.2, 0}, {0.5, 2.2, 0}, {0, 2.9, 0.2}}, 1, 0));
    return data;
}

// Whitted's own ray counts for the same render (stage 6, every ray to max_depth).
RayStats whitted_counts(const SceneData& data, int max_depth) {
    RenderSettings settings;
    settings.stage = 6;
    settings.max_depth = max_depth;
    settings.min_weight = 0.0;
    const Scene scene(data);
    return render(scene, settings, 2).stats;
}

::testing::AssertionResult close(std::uint64_t embree, std::uint64_t whitted, const char* kind) {
    const double allowed = std::max(2.0, 1e-3 * static_cast<double>(whitted));
    if (std::abs(static_cast<double>(embree) - static_cast<double>(whitted)) <= allowed)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << kind << ": embree " << embree << ", whitted " << whitted;
}

void expect_same_traffic(const SceneData& data, int max_depth) {
    const EmbreeScene scene(data, EmbreeSettings{2, RTC_BUILD_QUALITY_HIGH});
    const RayCounts embree = shoot_ray_traffic(scene, data, max_depth, 2).rays;
    const RayStats ours = whitted_counts(data, max_depth);
    EXPECT_EQ(embree.eye, ours.eye);
    EXPECT_TRUE(close(embree.shadow, ours.shadow, "shadow"));
    EXPECT_TRUE(close(embree.reflected, ours.reflected, "reflected"));
    EXPECT_TRUE(close(embree.refracted, ours.refracted, "refracted"));
    EXPECT_GT(embree.refracted + embree.reflected, 0u);
}

bool labs_done() { return highest_complete_stage(probe_labs()) >= 6; }

} // namespace

TEST(EmbreeScene, FindsTheNearestSurfaceOfEveryKind) {
    const SceneData data = every_kind();
    const EmbreeScene scene(data, {});
    // Straight down onto the floor plane (outside Embree).
    auto hit = scene.closest_hit(make_ray({0, 5, 3}, {0, -1, 0}));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 5.0, 1e-12);
    EXPECT_EQ(hit->primitive, 0u);
    // Along -z through the mirror sphere's centre: its front at z = 0.7.
    hit = scene.closest_hit(make_ray({-1.2, 1, 5}, {0, 0, -1}));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 4.3, 1e-9);
    EXPECT_TRUE(near(hit->normal, {0, 0, 1}, 1e-9));
    EXPECT_TRUE(hit->front_face);
    EXPECT_EQ(hit->material, 1u);
    // From inside the glass shell's air pocket: the inner wall's outward side faces the centre.
    hit = scene.closest_hit(make_ray({1.2, 1, 0.5}, {1, 0, 0}));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 0.5, 1e-9);
    EXPECT_TRUE(hit->front_face);
    EXPECT_EQ(hit->primitive, 3u);
    // The box (user geometry): its face x = -1.5 seen from +x.
    hit = scene.closest_hit(make_ray({-1.0, 0.5, -1.5}, {-1, 0, 0}));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 0.5, 1e-12);
    EXPECT_TRUE(near(hit->normal, {1, 0, 0}));
    EXPECT_EQ(hit->primitive, 4u);
    // The inward cylinder (user geometry) from inside: the wall faces its axis, so the ray hits its front.
    hit = scene.closest_hit(make_ray({0, 1, -2}, {1, 0, 0}));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 0.5, 1e-9);
    EXPECT_TRUE(hit->front_face);
    EXPECT_EQ(hit->primitive, 6u);
    // The pp triangle: its shading normal is interpolated, its geometric normal is the face's.
    hit = scene.closest_hit(make_ray({0.05, 2.4, 5}, {0, 0, -1}));
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->primitive, 8u);
    EXPECT_GT(glm::dot(hit->normal, hit->geometric_normal), 0.9);
    EXPECT_GT(glm::length(hit->normal - hit->geometric_normal), 1e-3);
    // Nothing up there.
    EXPECT_FALSE(scene.closest_hit(make_ray({0, 5, 0}, {0, 1, 0})));
}

TEST(EmbreeScene, OcclusionStopsAtTheGivenDistance) {
    const SceneData data = every_kind();
    const EmbreeScene scene(data, {});
    const Ray towards_sphere = make_ray({-1.2, 1, 5}, {0, 0, -1}); // the sphere's front is 4.3 away
    EXPECT_TRUE(scene.occluded(towards_sphere, 4.4));
    EXPECT_FALSE(scene.occluded(towards_sphere, 4.2));
    EXPECT_TRUE(scene.occluded(make_ray({0, 5, 3}, {0, -1, 0}), 5.1)); // the plane
    EXPECT_FALSE(scene.occluded(make_ray({0, 5, 3}, {0, -1, 0}), 4.9));
    const Ray towards_cone = make_ray({2, 0.5, 3}, {0, 0, -1}); // its wall is about 4.07 away
    EXPECT_TRUE(scene.occluded(towards_cone, 4.2));
    EXPECT_FALSE(scene.occluded(towards_cone, 4.0));
}

TEST(EmbreeTraffic, CountsOneEyeRayPerPixelAndNoMoreWithoutLightsOrMirrors) {
    SceneData data = every_kind();
    data.lights.clear();
    for (Material& m : data.materials) {
        m.specular = 0.0;
        m.transmittance = 0.0;
    }
    const EmbreeScene scene(data, {});
    const RayCounts counts = shoot_ray_traffic(scene, data, 5, 3).rays;
    EXPECT_EQ(counts.eye, 48u * 36u);
    EXPECT_EQ(counts.total(), counts.eye);
}

TEST(EmbreeTraffic, DepthOneShootsEyeAndShadowRaysOnly) {
    const SceneData data = every_kind();
    const EmbreeScene scene(data, {});
    const RayCounts counts = shoot_ray_traffic(scene, data, 1, 2).rays;
    EXPECT_GT(counts.shadow, 0u);
    EXPECT_EQ(counts.reflected + counts.refracted, 0u);
}

TEST(EmbreeTraffic, ShootsTheRayTreeWhittedShootsOnEveryKindOfShape) {
    if (!labs_done()) GTEST_SKIP() << "comparing with whitted needs every lab";
    expect_same_traffic(every_kind(), 5);
}

TEST(EmbreeTraffic, ShootsTheRayTreeWhittedShootsOnTheClassicScene) {
    if (!labs_done()) GTEST_SKIP() << "comparing with whitted needs every lab";
    LoadedScene loaded = load_scene(std::filesystem::path(WHITTED_SOURCE_DIR) / "scenes" / "whitted_1980.p3f");
    loaded.data.camera = loaded.data.camera.with_resolution(64, 64);
    expect_same_traffic(loaded.data, 6);
}

TEST(EmbreeTraffic, UsesTheThreadsItIsGivenAndTheSameCountsWithAny) {
    const SceneData data = every_kind();
    const EmbreeScene scene(data, {});
    const auto one = shoot_ray_traffic(scene, data, 5, 1);
    const auto three = shoot_ray_traffic(scene, data, 5, 3);
    EXPECT_EQ(one.threads, 1);
    EXPECT_EQ(three.threads, 3);
    EXPECT_EQ(one.rays.total(), three.rays.total());
    EXPECT_EQ(one.rays.refracted, three.rays.refracted);
}

TEST(EmbreeTraffic, EyePacketsShootTheSameRays) {
    SceneData data = every_kind();
    data.camera = data.camera.with_resolution(37, 23); // blocks cut by the image's edges
    const EmbreeScene scene(data, {});
    const RayCounts single = shoot_ray_traffic(scene, data, 5, 2, false).rays;
    const RayCounts packets = shoot_ray_traffic(scene, data, 5, 2, true).rays;
    EXPECT_EQ(packets.eye, 37u * 23u);
    EXPECT_EQ(packets.shadow, single.shadow);
    EXPECT_EQ(packets.reflected, single.reflected);
    EXPECT_EQ(packets.refracted, single.refracted);
}
