// Lab 10, box_entry(): the slab test. The ray is inside the box where it is
// inside all three slabs min[axis] <= p[axis] <= max[axis] and inside t_range:
// from the largest entry to the smallest exit.
#include "whitted/labs.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;

namespace {

const Aabb kCube{Point3(-1.0), Point3(1.0)};

std::optional<double> entry(const Point3& origin, const Vec3& direction, const Aabb& box = kCube, Interval range = {}) {
    const Ray ray{origin, glm::normalize(direction)};
    return box_entry(ray, 1.0 / ray.direction, box, range);
}

} // namespace

TEST(BoxEntry, ARayStraightAtTheCubeEntersAtItsNearFace) {
    // From z = -5 towards +z: the slab -1 <= z <= 1 is entered at t = 4; x and y are inside all along.
    const std::optional<double> t = entry(Point3(0.0, 0.0, -5.0), Vec3(0.0, 0.0, 1.0));
    ASSERT_TRUE(t.has_value()) << "the ray runs through the cube";
    EXPECT_DOUBLE_EQ(*t, 4.0);
    // Towards -x from x = 3: the entry is the face x = 1, at t = 2 (the slab's ends swap for a negative direction).
    const std::optional<double> back = entry(Point3(3.0, 0.5, -0.5), Vec3(-1.0, 0.0, 0.0));
    ASSERT_TRUE(back.has_value());
    EXPECT_DOUBLE_EQ(*back, 2.0);
}

TEST(BoxEntry, TheEntryIsTheLastOfTheThreeSlabs) {
    // Along (1, 1, 0)/sqrt 2 from (-3, -2, 0): the x slab is entered at x = -1, t = 2 sqrt 2;
    // the y slab at y = -1, t = sqrt 2 (earlier): the box is entered at the later one.
    const std::optional<double> t = entry(Point3(-3.0, -2.0, 0.0), Vec3(1.0, 1.0, 0.0));
    ASSERT_TRUE(t.has_value());
    EXPECT_NEAR(*t, 2.0 * std::sqrt(2.0), 1e-12);
}

TEST(BoxEntry, ARayPassingBesideTheBoxMissesIt) {
    // Along (1, 1, 0) from (-3, 0, 0): it leaves the y slab (y = 1, t = sqrt 2) before it enters the x slab (t = 2 sqrt 2).
    EXPECT_FALSE(entry(Point3(-3.0, 0.0, 0.0), Vec3(1.0, 1.0, 0.0)).has_value());
    EXPECT_FALSE(entry(Point3(0.0, 2.0, -5.0), Vec3(0.0, 0.0, 1.0)).has_value()) << "above the cube, parallel to z";
}

TEST(BoxEntry, TheRangeCutsTheRayShort) {
    const Point3 origin(0.0, 0.0, -5.0);
    const Vec3 ahead(0.0, 0.0, 1.0);
    EXPECT_FALSE(entry(origin, ahead, kCube, Interval{0.0, 3.5}).has_value()) << "the range ends before the cube starts (t = 4)";
    EXPECT_FALSE(entry(origin, -ahead).has_value()) << "the cube is behind the ray";
    const std::optional<double> inside = entry(origin, ahead, kCube, Interval{4.5, 100.0});
    ASSERT_TRUE(inside.has_value()) << "the range starts inside the cube";
    EXPECT_DOUBLE_EQ(*inside, 4.5) << "the ray is in the box from the start of the range";
}

TEST(BoxEntry, AnOriginInsideTheBoxEntersAtTheStartOfTheRange) {
    const std::optional<double> t = entry(Point3(0.2, -0.3, 0.1), Vec3(0.3, 1.0, -0.2), kCube, Interval{0.0, kInfinity});
    ASSERT_TRUE(t.has_value());
    EXPECT_EQ(*t, 0.0);
}

TEST(BoxEntry, ARayAlongAFaceOfTheBoxStillCounts) {
    // Direction (0, 0, 1): 1 / 0 = infinity for x and y. With the origin exactly on the face
    // x = 1, (1 - 1) x infinity is NaN: the test must not lose the box to it (a flat box,
    // a triangle in the plane x = 1, has exactly that face).
    const Aabb flat{Point3(1.0, -1.0, -1.0), Point3(1.0, 1.0, 1.0)};
    const std::optional<double> t = entry(Point3(1.0, 0.0, -5.0), Vec3(0.0, 0.0, 1.0), flat);
    ASSERT_TRUE(t.has_value()) << "the ray runs along the flat box x = 1";
    EXPECT_DOUBLE_EQ(*t, 4.0);
    EXPECT_FALSE(entry(Point3(1.5, 0.0, -5.0), Vec3(0.0, 0.0, 1.0), flat).has_value()) << "beside it: a miss";
}
