// The BVH must find exactly what testing every primitive finds.
#include "whitted/engine/bvh.hpp"
#include "whitted/labs.hpp"
#include "whitted/scene.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace whitted;

namespace {

// A cloud of random spheres, triangles and boxes, plus one infinite plane.
SceneData random_scene(unsigned seed, int count) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> position(-10.0, 10.0), size(0.05, 1.5);
    SceneData data;
    data.materials.push_back(Material{});
    for (int i = 0; i < count; ++i) {
        const Point3 c(position(rng), position(rng), position(rng));
        switch (i % 3) {
        case 0: data.primitives.push_back({Sphere{c, size(rng)}}); break;
        case 1:
            data.primitives.push_back({Triangle{c, c + Vec3(size(rng), 0.0, size(rng)), c + Vec3(0.0, size(rng), size(rng))}});
            break;
        default: data.primitives.push_back({Box{c, c + Vec3(size(rng), size(rng), size(rng))}}); break;
        }
    }
    data.primitives.push_back({Plane{Point3(0.0, -12.0, 0.0), Vec3(0.0, 1.0, 0.0)}});
    return data;
}

Ray random_ray(std::mt19937& rng) {
    std::uniform_real_distribution<double> position(-15.0, 15.0), unit(-1.0, 1.0);
    Vec3 d;
    do d = Vec3(unit(rng), unit(rng), unit(rng));
    while (glm::length(d) < 0.1);
    return Ray{Point3(position(rng), position(rng), position(rng)), glm::normalize(d)};
}

} // namespace

TEST(Bvh, ClosestHitAgreesWithTestingEveryPrimitive) {
    const Scene scene(random_scene(1, 3000));
    std::mt19937 rng(7);
    int hits = 0;
    for (int i = 0; i < 4000; ++i) {
        const Ray ray = random_ray(rng);
        const auto expected = closest_hit(ray, scene.primitives(), Interval{});
        const auto found = scene.closest_hit(ray);
        ASSERT_EQ(expected.has_value(), found.has_value()) << "ray " << i;
        if (expected) {
            ++hits;
            EXPECT_EQ(expected->t, found->t) << "ray " << i;
            EXPECT_EQ(expected->primitive, found->primitive) << "ray " << i;
        }
    }
    EXPECT_GT(hits, 1000); // the test means something only if many rays hit
}

TEST(Bvh, OcclusionAgreesWithTestingEveryPrimitive) {
    const Scene scene(random_scene(2, 3000));
    std::mt19937 rng(11);
    int blocked = 0;
    for (int i = 0; i < 4000; ++i) {
        const Ray ray = random_ray(rng);
        const Interval range{0.0, 5.0};
        const bool expected = closest_hit(ray, scene.primitives(), range).has_value();
        ASSERT_EQ(expected, scene.occluded(ray, range)) << "ray " << i;
        blocked += expected;
    }
    EXPECT_GT(blocked, 200);
    EXPECT_LT(blocked, 3800);
}

TEST(Bvh, ManyIdenticalPrimitivesStillBuildAndAnswer) {
    // Coincident centroids defeat every spatial split; the build must still terminate.
    SceneData data;
    data.materials.push_back(Material{});
    for (int i = 0; i < 100000; ++i) data.primitives.push_back({Sphere{Point3(0.0), 1.0}});
    const Scene scene(std::move(data));
    const auto hit = scene.closest_hit(Ray{Point3(0.0, 0.0, 5.0), Vec3(0.0, 0.0, -1.0)});
    ASSERT_TRUE(hit.has_value());
    EXPECT_DOUBLE_EQ(hit->t, 4.0);
}

TEST(Bvh, EmptySceneHitsNothing) {
    SceneData data;
    const Scene scene(std::move(data));
    EXPECT_FALSE(scene.closest_hit(Ray{Point3(0.0), Vec3(0.0, 0.0, -1.0)}).has_value());
    EXPECT_FALSE(scene.occluded(Ray{Point3(0.0), Vec3(0.0, 0.0, -1.0)}, Interval{0.0, 10.0}));
}

// Big trees build their two halves on other threads, into nodes of their own
// that are then appended: the tree must be the one a single thread builds,
// node for node, or a picture could depend on the machine.
TEST(Bvh, SeveralThreadsBuildTheTreeOneThreadBuilds) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> position(-100.0, 100.0), size(0.01, 2.0);
    std::vector<Aabb> boxes(300'000); // above the size that builds on several threads, two levels down
    for (Aabb& box : boxes) {
        box.min = Point3(position(rng), position(rng), position(rng));
        box.max = box.min + Vec3(size(rng), size(rng), size(rng));
    }
    const Bvh one(boxes, Bvh::Threads::one), several(boxes, Bvh::Threads::several);
    ASSERT_EQ(one.order().size(), several.order().size());
    EXPECT_TRUE(std::equal(one.order().begin(), one.order().end(), several.order().begin()));
    ASSERT_EQ(one.nodes().size(), several.nodes().size());
    for (std::size_t i = 0; i < one.nodes().size(); ++i) {
        const Bvh::Node &a = one.nodes()[i], &b = several.nodes()[i];
        ASSERT_TRUE(a.first == b.first && a.count == b.count && a.bounds.min == b.bounds.min &&
                    a.bounds.max == b.bounds.max)
            << "node " << i;
    }
    EXPECT_GT(one.nodes().size(), boxes.size() / 4); // a real tree, not one leaf
}
