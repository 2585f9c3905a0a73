// The uniform grid (accel 1): the same nearest hits and the same shadow
// answers as testing every primitive, for rays from outside and inside, along
// the axes, in flat scenes and in scenes of one primitive or none.
#include "whitted/engine/uniform_grid.hpp"
#include "whitted/bvh_tree.hpp"
#include "whitted/labs.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;

namespace {

double number(int i, double scale) { return std::sin(i * 12.9898 + scale * 78.233) * 0.5; } // in [-0.5, 0.5]

std::vector<Primitive> scattered(int count, double size, bool flat) {
    std::vector<Primitive> primitives;
    for (int i = 0; i < count; ++i) {
        const Point3 p(size * number(i, 1.0), flat ? 0.0 : size * number(i, 2.0), size * number(i, 3.0));
        if (i % 3 == 0 && !flat) primitives.push_back({Sphere{p, 0.05 * size * (0.2 + number(i, 4.0) + 0.5)}, 0});
        else primitives.push_back({Triangle{p, p + Vec3(0.1 * size, 0.0, 0.02 * size), p + Vec3(0.0, 0.0, 0.1 * size)}, 0});
    }
    return primitives;
}

std::vector<Ray> rays(double size) {
    std::vector<Ray> all;
    for (int i = 0; i < 400; ++i) {
        const Point3 origin = i % 2 == 0 ? Point3(size * number(i, 5.0), size * number(i, 6.0), size * number(i, 7.0)) // inside
                                         : Point3(0.0, 0.3 * size, 2.0 * size);                                        // outside
        Vec3 d(number(i, 8.0), number(i, 9.0), number(i, 10.0) - (i % 2 == 0 ? 0.0 : 1.0));
        if (i % 7 == 0) d = Vec3(0.0, 0.0, -1.0); // along an axis: two infinite slopes
        if (i % 11 == 0) d = Vec3(1.0, 0.0, 0.0);
        all.push_back(Ray{origin, glm::normalize(d)});
    }
    return all;
}

void expect_grid_matches_testing_everything(const std::vector<Primitive>& primitives, double size, const std::string& what) {
    const UniformGrid grid(primitive_boxes(primitives));
    int hits = 0;
    for (const Ray& ray : rays(size)) {
        const std::optional<Hit> expected = closest_hit(ray, primitives, Interval{});
        const std::optional<Hit> got = grid.closest_hit(ray, primitives, Interval{});
        ASSERT_EQ(got.has_value(), expected.has_value()) << what;
        if (expected) {
            ++hits;
            EXPECT_EQ(got->t, expected->t) << what;
        }
        const Interval feeler{0.0, 0.4 * size};
        EXPECT_EQ(grid.occluded(ray, primitives, feeler), closest_hit(ray, primitives, feeler).has_value()) << what;
    }
    if (primitives.size() > 10) { EXPECT_GT(hits, 20) << what << ": the test's rays should hit"; }
}

} // namespace

TEST(UniformGrid, FindsWhatTestingEveryPrimitiveFinds) {
    expect_grid_matches_testing_everything(scattered(800, 10.0, false), 10.0, "800 triangles and spheres");
}

TEST(UniformGrid, AFlatSceneHasCellsToo) {
    expect_grid_matches_testing_everything(scattered(300, 10.0, true), 10.0, "300 triangles in the plane y = 0");
}

TEST(UniformGrid, OnePrimitiveAndNone) {
    expect_grid_matches_testing_everything(scattered(1, 10.0, false), 10.0, "one primitive");
    const UniformGrid empty({});
    EXPECT_FALSE(empty.closest_hit(Ray{Point3(0.0), Vec3(0.0, 0.0, 1.0)}, {}, Interval{}).has_value());
}

TEST(UniformGrid, AboutTwoCellsPerPrimitive) {
    const std::vector<Primitive> primitives = scattered(1000, 10.0, false);
    const UniformGrid grid(primitive_boxes(primitives));
    const auto [x, y, z] = grid.resolution();
    EXPECT_GE(x * y * z, 1000);
    EXPECT_LE(x * y * z, 4000);
}
