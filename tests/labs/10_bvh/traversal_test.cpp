// Lab 10, bvh_closest_hit() and bvh_occluded(): the same answers as testing
// every primitive, for rays from outside and from inside a cloud of triangles
// and spheres, found with about as few primitive tests as the framework's walk
// of the same tree makes, and a render through your BVH equal to one through
// the framework's.
#include "whitted/labs.hpp"
#include "whitted/render.hpp"

#include "lab_helpers.hpp"
#include "walk_tests.hpp"

#include <gtest/gtest.h>

#include <cstring>

using namespace whitted;
using namespace whitted::testing_helpers;

namespace {

/// Triangles and spheres mixed, with a floor plane (planes are never in the BVH).
SceneData mixed_scene() {
    std::vector<Primitive> primitives = triangle_soup(600, 12.0, 5);
    TestNumbers numbers{9};
    for (int i = 0; i < 150; ++i) primitives.push_back({Sphere{numbers.point(12.0), 0.1 + 0.4 * numbers.next()}, 0});
    primitives.push_back({Plane{Point3(0.0, -7.0, 0.0), Vec3(0.0, 1.0, 0.0)}, 0});
    SceneData data = bvh_test_scene(std::move(primitives), 12.0);
    data.lights = {PointLight{Point3(5.0, 20.0, 10.0), Color(1.0)}};
    return data;
}

} // namespace

TEST(BvhClosestHit, FindsWhatTestingEveryPrimitiveFinds) {
    const Scene scene = scene_with_known_tree(mixed_scene());
    const std::span<const Primitive> bounded = scene.bounded_primitives();
    int hits = 0;
    WalkTests tests;
    for (const Ray& ray : bvh_test_rays(scene.camera(), 12.0, 21)) {
        const std::optional<Hit> yours = counted_closest_hit(scene, ray, Interval{}, tests);
        const std::optional<Hit> every = closest_hit(ray, bounded, Interval{});
        ASSERT_EQ(yours.has_value(), every.has_value()) << "a ray from " << ray.origin.x << ", " << ray.origin.y << ", "
                                                        << ray.origin.z << (every ? " hits" : " misses") << " a primitive";
        if (!every) continue;
        ++hits;
        EXPECT_EQ(yours->t, every->t) << "not the nearest hit";
        EXPECT_EQ(yours->primitive, every->primitive);
    }
    EXPECT_GT(hits, 200) << "the test's rays should mostly hit";
    expect_about_as_few_tests(tests, "bvh_closest_hit()");
}

TEST(BvhClosestHit, StaysInsideTheRange) {
    const Scene scene = scene_with_known_tree(mixed_scene());
    const std::span<const Primitive> bounded = scene.bounded_primitives();
    WalkTests tests;
    for (const Ray& ray : bvh_test_rays(scene.camera(), 12.0, 4)) {
        const std::optional<Hit> first = closest_hit(ray, bounded, Interval{});
        if (!first) continue;
        // Beyond the nearest hit: the next one, if any, never the nearest again.
        const Interval beyond{first->t, kInfinity};
        const std::optional<Hit> yours = counted_closest_hit(scene, ray, beyond, tests);
        const std::optional<Hit> every = closest_hit(ray, bounded, beyond);
        ASSERT_EQ(yours.has_value(), every.has_value());
        if (every) { EXPECT_EQ(yours->t, every->t); }
        // And a range that ends before it: nothing.
        EXPECT_FALSE(counted_closest_hit(scene, ray, Interval{0.0, first->t * 0.999}, tests).has_value());
    }
    expect_about_as_few_tests(tests, "bvh_closest_hit()");
}

TEST(BvhOccluded, AnswersWhatTestingEveryPrimitiveAnswers) {
    const Scene scene = scene_with_known_tree(mixed_scene());
    TestNumbers numbers{17};
    WalkTests tests;
    int blocked = 0, clear = 0;
    for (int i = 0; i < 600; ++i) {
        // A feeler between two points of the cloud.
        const Point3 from = numbers.point(14.0), to = numbers.point(14.0);
        const double distance = glm::length(to - from);
        const Ray ray{from, (to - from) / distance};
        const Interval range{0.0, distance};
        bool every = false;
        for (const Primitive& primitive : scene.bounded_primitives()) every = every || intersect(ray, primitive, range).has_value();
        EXPECT_EQ(counted_occluded(scene, ray, range, tests), every) << "feeler " << i;
        (every ? blocked : clear) += 1;
    }
    EXPECT_GT(blocked, 50);
    EXPECT_GT(clear, 50);
    expect_about_as_few_tests(tests, "bvh_occluded()");
}

TEST(BvhPicture, YourTreeAndWalkDrawTheFrameworksPicture) {
    // Stage 10 walks your tree; stage 9 the framework's: the same picture, bit for bit.
    SceneData data = mixed_scene();
    data.camera = data.camera.with_resolution(48, 36);
    RenderSettings settings;
    settings.stage = stage_number(Stage::bvh);
    const Image yours = render(Scene(data, nullptr, BvhChoice::lab), settings, 2).image;
    const Image framework = render(Scene(data), settings, 2).image;
    ASSERT_EQ(yours.pixels.size(), framework.pixels.size());
    EXPECT_EQ(0, std::memcmp(yours.pixels.data(), framework.pixels.data(), yours.pixels.size() * sizeof(Color)));
}
