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

const char* const kAxisName[] = {"x", "y", "z"};

/// The unit vector along `axis` (0 x, 1 y, 2 z) times `sign`: its other two components are exactly 0.
Vec3 along(int axis, double sign) {
    Vec3 v(0.0);
    v[axis] = sign;
    return v;
}

/// The cube squashed flat in `axis` onto its face at 1: min = max = 1 there, -1..1 across the other two
/// (the box of a triangle that lies in the plane axis = 1).
Aabb flat_box(int axis) {
    Aabb box = kCube;
    box.min[axis] = 1.0;
    return box;
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
    // The same ray started 2 lower, from (-3, -2, 0), is inside the y slab from t = sqrt 2 to 3 sqrt 2 and
    // enters the x slab at 2 sqrt 2, in between: it meets the box. A miss must come from the slabs, not always.
    const std::optional<double> lower = entry(Point3(-3.0, -2.0, 0.0), Vec3(1.0, 1.0, 0.0));
    ASSERT_TRUE(lower.has_value()) << "from (-3, -2, 0) along (1, 1, 0) the ray crosses the cube";
    EXPECT_NEAR(*lower, 2.0 * std::sqrt(2.0), 1e-12);
    EXPECT_FALSE(entry(Point3(0.0, 2.0, -5.0), Vec3(0.0, 0.0, 1.0)).has_value()) << "above the cube, parallel to z";
    // Parallel to z at height 0.5 instead of 2: inside the y slab all along, entering the z slab at t = 4.
    const std::optional<double> level = entry(Point3(0.0, 0.5, -5.0), Vec3(0.0, 0.0, 1.0));
    ASSERT_TRUE(level.has_value()) << "at height 0.5 the ray parallel to z runs through the cube";
    EXPECT_DOUBLE_EQ(*level, 4.0);
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
    // From the centre along +x the ray is inside until the face x = 1 at t = 1: a range that starts at
    // t = 0.5 enters at 0.5, one that starts at t = 2 begins after the ray has left (a miss).
    const std::optional<double> half = entry(Point3(0.0), Vec3(1.0, 0.0, 0.0), kCube, Interval{0.5, kInfinity});
    ASSERT_TRUE(half.has_value()) << "at t = 0.5 the ray is still inside the cube";
    EXPECT_EQ(*half, 0.5);
    EXPECT_FALSE(entry(Point3(0.0), Vec3(1.0, 0.0, 0.0), kCube, Interval{2.0, kInfinity}).has_value())
        << "the ray leaves the cube at t = 1, before the range starts at t = 2";
}

TEST(BoxEntry, AnOriginOnAFaceIsInTheBox) {
    // The origin (1, 0.3, -0.2) lies on the face x = 1. Going in (-x), the x slab is crossed from
    // t = 0 to t = 2: entered at t = 0, or where the range starts if later.
    const Point3 on_face(1.0, 0.3, -0.2);
    const std::optional<double> in = entry(on_face, Vec3(-1.0, 0.0, 0.0));
    ASSERT_TRUE(in.has_value()) << "a ray from a point of the face into the box is in the box from t = 0";
    EXPECT_EQ(*in, 0.0);
    const std::optional<double> in_later = entry(on_face, Vec3(-1.0, 0.0, 0.0), kCube, Interval{1e-9, kInfinity});
    ASSERT_TRUE(in_later.has_value());
    EXPECT_EQ(*in_later, 1e-9);
    // Going out (+x), the x slab is behind the ray but for its last point: t from -2 to 0. The ray
    // touches the box at t = 0 only: entry 0 = exit 0 with a range from 0, a miss with a range from 1e-9.
    const std::optional<double> out = entry(on_face, Vec3(1.0, 0.0, 0.0));
    ASSERT_TRUE(out.has_value()) << "entry 0 is not after exit 0: the ray touches the box at its origin";
    EXPECT_EQ(*out, 0.0);
    EXPECT_FALSE(entry(on_face, Vec3(1.0, 0.0, 0.0), kCube, Interval{1e-9, kInfinity}).has_value())
        << "going out of the face, the ray is outside the box for every t > 0";
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

TEST(BoxEntry, RaysParallelToEachAxisOnAFaceBesideItOrInside) {
    // A ray parallel to one axis (direction 1 or -1 there, exactly 0 on the other two) from 5 before the
    // cube: on the two axes it does not move along, inv_direction is infinite. Its origin there is on
    // the face at -1 or at 1 (where (face - origin) x infinity is 0 x infinity = NaN), inside at 0.5, or
    // beside the cube at 1.5. On a face or inside, the ray runs through the cube and enters it at t = 4;
    // beside it, it misses. Every axis plays every part: a NaN handled by the last axis is not hidden by
    // a later one.
    for (int axis = 0; axis < 3; ++axis) {
        for (const double sign : {1.0, -1.0}) {
            for (int across = 0; across < 3; ++across) {
                if (across == axis) continue;
                for (const double place : {-1.0, 1.0, 0.5, 1.5}) {
                    SCOPED_TRACE(::testing::Message() << "a ray along " << (sign > 0 ? "+" : "-") << kAxisName[axis]
                                                      << " with " << kAxisName[across] << " = " << place);
                    Point3 origin(0.0);
                    origin[axis] = -5.0 * sign;
                    origin[across] = place;
                    const std::optional<double> t = entry(origin, along(axis, sign));
                    if (place > 1.0) {
                        EXPECT_FALSE(t.has_value()) << "the ray runs beside the cube";
                        continue;
                    }
                    ASSERT_TRUE(t.has_value()) << "the ray runs through the cube (on a face counts)";
                    EXPECT_EQ(*t, 4.0);
                }
            }
        }
    }
}

TEST(BoxEntry, FlatBoxesAreHitOnEveryAxis) {
    // A box flat in one axis (min = max = 1 there: the box of a triangle in the plane axis = 1).
    // A ray along another axis with its origin in that plane runs along the flat box: 0 x infinity = NaN
    // on the flat axis, which must change nothing; it enters where the other slab starts, t = 4. Half a
    // unit beside the plane it misses. Straight through the flat box (along the flat axis from -5) it is
    // inside for one t only, 6, entry = exit: still a hit.
    for (int flat = 0; flat < 3; ++flat) {
        const Aabb box = flat_box(flat);
        for (int axis = 0; axis < 3; ++axis) {
            if (axis == flat) continue;
            SCOPED_TRACE(::testing::Message() << "the box flat in " << kAxisName[flat] << ", a ray along +"
                                              << kAxisName[axis]);
            Point3 origin(0.0);
            origin[axis] = -5.0;
            origin[flat] = 1.0;
            const std::optional<double> t = entry(origin, along(axis, 1.0), box);
            ASSERT_TRUE(t.has_value()) << "the ray runs along the flat box, in its plane";
            EXPECT_EQ(*t, 4.0);
            origin[flat] = 1.5;
            EXPECT_FALSE(entry(origin, along(axis, 1.0), box).has_value()) << "half a unit beside the flat box";
        }
        SCOPED_TRACE(::testing::Message() << "the box flat in " << kAxisName[flat] << ", a ray across it");
        Point3 before(0.3, -0.4, 0.2);
        before[flat] = -5.0;
        const std::optional<double> through = entry(before, along(flat, 1.0), box);
        ASSERT_TRUE(through.has_value()) << "straight at the flat box: entry and exit are both t = 6, which counts";
        EXPECT_EQ(*through, 6.0);
    }
}
