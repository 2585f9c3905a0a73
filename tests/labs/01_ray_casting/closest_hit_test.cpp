// closest_hit over a span of primitives, and the dispatcher intersect() it calls.
#include "test_helpers.hpp"
#include "whitted/labs.hpp"
#include "whitted/primitive.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

using namespace whitted;
using whitted::testing_helpers::make_ray;
using whitted::testing_helpers::near;

TEST(Intersect, DispatchesEveryShapeAndFillsMaterialAndPrimitive) {
    // Every shape is placed so that the ray from (0, 0, -10) along +z first meets it at z = -1 (t = 9).
    const Ray ray = make_ray({0, 0, -10}, {0, 0, 1});
    const std::vector<Shape> shapes = {
        Sphere{{0, 0, 0}, 1.0},
        Plane{{0, 0, -1}, {0, 0, -1}},
        Triangle{{-1, -1, -1}, {-1, 1, -1}, {1, 0, -1}},
        Box{{-1, -1, -1}, {1, 1, 1}},
        Cone{{0, -1, 0}, 1.0, {0, 1, 0}, 1.0}, // cylinder along y, met from the side
    };
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const Primitive primitive{shapes[i], static_cast<std::uint32_t>(7 + i), -1, static_cast<std::uint32_t>(i)};
        const auto hit = intersect(ray, primitive, {});
        ASSERT_TRUE(hit) << "shape " << i;
        EXPECT_NEAR(hit->t, 9.0, 1e-12) << "shape " << i;
        EXPECT_TRUE(near(hit->point, {0, 0, -1}, 1e-12)) << "shape " << i;
        EXPECT_EQ(hit->material, 7 + i);
        EXPECT_EQ(hit->primitive, i);
    }
}

TEST(ClosestHit, PicksTheNearestWhateverTheOrder) {
    // Unit spheres on the x axis at 4, 7 and 10; from the origin along +x their near sides are
    // t = 3, 6 and 9. Whatever order they are listed in, the sphere at 4 (id 1) is the nearest.
    std::array<Primitive, 3> primitives = {{
        {Sphere{{10, 0, 0}, 1.0}, 0, -1, 0},
        {Sphere{{4, 0, 0}, 1.0}, 0, -1, 1},
        {Sphere{{7, 0, 0}, 1.0}, 0, -1, 2},
    }};
    std::sort(primitives.begin(), primitives.end(), [](const Primitive& a, const Primitive& b) { return a.index < b.index; });
    const Ray ray = make_ray({0, 0, 0}, {1, 0, 0});
    do {
        const auto nearest = closest_hit(ray, primitives, {});
        ASSERT_TRUE(nearest);
        EXPECT_EQ(nearest->primitive, 1u) << "order " << primitives[0].index << primitives[1].index << primitives[2].index
                                          << ": keep the hit with the smallest t, not the first or last one found";
        EXPECT_NEAR(nearest->t, 3.0, 1e-12);
    } while (std::next_permutation(primitives.begin(), primitives.end(),
                                   [](const Primitive& a, const Primitive& b) { return a.index < b.index; }));
}

TEST(ClosestHit, ANearTriangleHidesAFarPlaneAndSphere) {
    // From (0, 0, 10) along -z: the triangle at z = 2 (t = 8), the sphere (0, 0, 0) r 1 at t = 9,
    // the plane z = -3 at t = 13. The triangle comes last in the list but is the nearest.
    const std::vector<Primitive> primitives = {
        {Plane{{0, 0, -3}, {0, 0, 1}}, 0, -1, 0},
        {Sphere{{0, 0, 0}, 1.0}, 0, -1, 1},
        {Triangle{{-1, -1, 2}, {1, -1, 2}, {0, 1, 2}}, 0, -1, 2},
    };
    const auto nearest = closest_hit(make_ray({0, 0, 10}, {0, 0, -1}), primitives, {});
    ASSERT_TRUE(nearest);
    EXPECT_EQ(nearest->primitive, 2u);
    EXPECT_NEAR(nearest->t, 8.0, 1e-12);
    EXPECT_TRUE(near(nearest->normal, {0, 0, 1}));
}

TEST(ClosestHit, EmptySceneAndMissesGiveNothing) {
    const Ray ray = make_ray({0, 0, 0}, {1, 0, 0});
    EXPECT_FALSE(closest_hit(ray, std::span<const Primitive>{}, {})) << "no primitives, no hit";
    const std::vector<Primitive> behind = {{Sphere{{-5, 0, 0}, 1.0}, 0, -1, 0}, {Sphere{{0, 5, 0}, 1.0}, 0, -1, 1}};
    EXPECT_FALSE(closest_hit(ray, behind, {})) << "one sphere is behind the ray, the other beside it";
    // Turned around (along -x), the ray meets the sphere around (-5, 0, 0) at x = -4: t = 4.
    const auto back = closest_hit(make_ray({0, 0, 0}, {-1, 0, 0}), behind, {});
    ASSERT_TRUE(back) << "along -x the ray runs into the sphere around (-5, 0, 0)";
    EXPECT_EQ(back->primitive, 0u);
    EXPECT_NEAR(back->t, 4.0, 1e-12);
}

TEST(ClosestHit, RespectsTheRangeItIsGiven) {
    // Unit spheres at x = 4 (t = 3 and 5) and x = 7 (t = 6 and 8).
    const std::vector<Primitive> primitives = {{Sphere{{7, 0, 0}, 1.0}, 0, -1, 0}, {Sphere{{4, 0, 0}, 1.0}, 0, -1, 1}};
    const Ray ray = make_ray({0, 0, 0}, {1, 0, 0});
    // Starting past the near side of the first sphere: its far side t = 5 is nearer than t = 6.
    const auto beyond = closest_hit(ray, primitives, {3.5, kInfinity});
    ASSERT_TRUE(beyond) << "pass t_range on to intersect()";
    EXPECT_EQ(beyond->primitive, 1u);
    EXPECT_NEAR(beyond->t, 5.0, 1e-12);
    EXPECT_FALSE(beyond->front_face);
    // Starting past both spheres of the first: only the second remains.
    const auto second = closest_hit(ray, primitives, {5.5, kInfinity});
    ASSERT_TRUE(second);
    EXPECT_EQ(second->primitive, 0u);
    EXPECT_NEAR(second->t, 6.0, 1e-12);
    // Stopping before the first hit: nothing.
    EXPECT_FALSE(closest_hit(ray, primitives, {0.0, 2.5})) << "no hit has t < 2.5";
    EXPECT_FALSE(closest_hit(ray, primitives, {0.0, 3.0})) << "t = 3 equals max: outside the open range";
}
