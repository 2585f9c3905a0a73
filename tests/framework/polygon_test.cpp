// Polygon triangulation: the triangles must cover the polygon exactly (their
// areas sum to its area, none lies outside) and keep its winding.
#include "polygon.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace whitted::detail;

namespace {

/// The polygon's vertices in the plane z = 0, counter-clockwise seen from +z.
std::vector<Point3> in_xy_plane(const std::vector<Vec2>& points) {
    std::vector<Point3> vertices;
    for (const Vec2& p : points) vertices.emplace_back(p.x, p.y, 0.0);
    return vertices;
}

/// The same polygon moved into a tilted plane far from the origin (rotations keep areas and windings).
std::vector<Point3> tilted(std::vector<Point3> vertices) {
    const double a = 0.7, b = 1.1;
    for (Point3& p : vertices) {
        const Point3 q{p.x, std::cos(a) * p.y - std::sin(a) * p.z, std::sin(a) * p.y + std::cos(a) * p.z};
        p = Point3{std::cos(b) * q.x + std::sin(b) * q.z, q.y, -std::sin(b) * q.x + std::cos(b) * q.z} +
            Point3(100.0, -40.0, 25.0);
    }
    return vertices;
}

/// A star (or gear) with `points` tips: radii alternate between `outer` and `inner`.
std::vector<Vec2> star(int points, double outer, double inner) {
    std::vector<Vec2> result;
    for (int i = 0; i < 2 * points; ++i) {
        const double angle = kPi * i / points;
        const double r = i % 2 == 0 ? outer : inner;
        result.emplace_back(r * std::cos(angle), r * std::sin(angle));
    }
    return result;
}

/// True when p lies strictly inside the xy polygon (even-odd crossing rule).
bool inside_xy(const Vec2& p, const std::vector<Vec2>& polygon) {
    bool inside = false;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Vec2 &a = polygon[i], &b = polygon[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
    }
    return inside;
}

/// Checks that the triangles' areas sum to the polygon's and every triangle faces like the polygon.
void expect_exact_cover(const std::vector<Point3>& vertices, const std::vector<TriangleIndices>& triangles) {
    ASSERT_FALSE(triangles.empty());
    const Vec3 newell = newell_normal(vertices);
    const double polygon_area = glm::length(newell) / 2.0;
    double sum = 0.0;
    for (const auto& [i, j, k] : triangles) {
        const Vec3 twice_area = glm::cross(vertices[j] - vertices[i], vertices[k] - vertices[i]);
        sum += glm::length(twice_area) / 2.0;
        EXPECT_GT(glm::dot(glm::normalize(twice_area), glm::normalize(newell)), 0.999999);
    }
    EXPECT_NEAR(sum, polygon_area, 1e-9 * polygon_area);
}

/// Checks that each triangle's centroid lies inside the (xy) polygon: no triangle bridges a notch.
void expect_centroids_inside(const std::vector<Vec2>& polygon, const std::vector<TriangleIndices>& triangles) {
    for (const auto& [i, j, k] : triangles)
        EXPECT_TRUE(inside_xy((polygon[i] + polygon[j] + polygon[k]) / 3.0, polygon)) << i << " " << j << " " << k;
}

} // namespace

TEST(Polygon, NewellNormalIsTwiceTheAreaAlongTheFrontNormal) {
    const auto square = in_xy_plane({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
    const Vec3 normal = newell_normal(square);
    EXPECT_DOUBLE_EQ(normal.x, 0.0);
    EXPECT_DOUBLE_EQ(normal.y, 0.0);
    EXPECT_DOUBLE_EQ(normal.z, 8.0);
}

TEST(Polygon, ConvexQuadBecomesTwoTrianglesWithItsWinding) {
    const auto quad = in_xy_plane({{0, 0}, {3, 0}, {3, 1}, {0, 1}});
    const auto triangles = triangulate_polygon(quad);
    EXPECT_EQ(triangles.size(), 2u);
    expect_exact_cover(quad, triangles);
}

TEST(Polygon, ClockwisePolygonKeepsItsBackwardsWinding) {
    const auto quad = in_xy_plane({{0, 1}, {3, 1}, {3, 0}, {0, 0}});
    const auto triangles = triangulate_polygon(quad);
    EXPECT_LT(newell_normal(quad).z, 0.0);
    expect_exact_cover(quad, triangles);
}

TEST(Polygon, ConcaveLShapeIsCoveredWithoutLeavingIt) {
    const std::vector<Vec2> l_shape{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
    const auto triangles = triangulate_polygon(in_xy_plane(l_shape));
    EXPECT_EQ(triangles.size(), 4u);
    expect_exact_cover(in_xy_plane(l_shape), triangles);
    expect_centroids_inside(l_shape, triangles);
}

TEST(Polygon, ConcaveLShapeWhoseFirstVertexCannotSeeTheOthersIsCovered) {
    // From vertex 0, (2, 1), the top of the L is hidden: a fan from it would leave the polygon.
    const std::vector<Vec2> l_shape{{2, 1}, {1, 1}, {1, 3}, {0, 3}, {0, 0}, {2, 0}};
    const auto triangles = triangulate_polygon(in_xy_plane(l_shape));
    expect_exact_cover(in_xy_plane(l_shape), triangles);
    expect_centroids_inside(l_shape, triangles);
}

TEST(Polygon, FivePointedStarIsCoveredWithoutLeavingIt) {
    const auto outline = star(5, 2.0, 0.7);
    const auto triangles = triangulate_polygon(in_xy_plane(outline));
    EXPECT_EQ(triangles.size(), 8u);
    expect_exact_cover(in_xy_plane(outline), triangles);
    expect_centroids_inside(outline, triangles);
}

TEST(Polygon, StarInATiltedPlaneFarFromTheOriginIsCovered) {
    const auto vertices = tilted(in_xy_plane(star(7, 3.0, 1.0)));
    expect_exact_cover(vertices, triangulate_polygon(vertices));
}

TEST(Polygon, ConcaveGearWith144VerticesIsCoveredWithoutLeavingIt) {
    const auto gear = star(72, 5.0, 4.2);
    ASSERT_EQ(gear.size(), 144u);
    const auto triangles = triangulate_polygon(in_xy_plane(gear));
    EXPECT_EQ(triangles.size(), 142u);
    expect_exact_cover(in_xy_plane(gear), triangles);
    expect_centroids_inside(gear, triangles);
    expect_exact_cover(tilted(in_xy_plane(gear)), triangulate_polygon(tilted(in_xy_plane(gear))));
}

TEST(Polygon, CollinearAndRepeatedPointsAddNoSliverTriangles) {
    // A 2 x 2 square with extra points along its edges and one vertex written twice.
    const auto vertices = in_xy_plane({{0, 0}, {1, 0}, {2, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}});
    const auto triangles = triangulate_polygon(vertices);
    expect_exact_cover(vertices, triangles);
    for (const auto& [i, j, k] : triangles)
        EXPECT_GT(glm::length(glm::cross(vertices[j] - vertices[i], vertices[k] - vertices[i])), 0.0);
}

TEST(Polygon, LargeConvexPolygonIsTriangulatedQuickly) {
    std::vector<Point3> circle;
    const int n = 100'000;
    for (int i = 0; i < n; ++i) circle.emplace_back(std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n), 0.0);
    const auto triangles = triangulate_polygon(circle);
    EXPECT_EQ(triangles.size(), static_cast<std::size_t>(n - 2));
}

TEST(Polygon, PointsOnOneLineGiveNoTriangles) {
    EXPECT_TRUE(triangulate_polygon(in_xy_plane({{0, 0}, {1, 1}, {2, 2}, {3, 3}})).empty());
}

TEST(Polygon, FewerThanThreeDistinctPointsGiveNoTriangles) {
    EXPECT_TRUE(triangulate_polygon(in_xy_plane({{0, 0}, {1, 1}})).empty());
    EXPECT_TRUE(triangulate_polygon(in_xy_plane({{1, 1}, {1, 1}, {1, 1}})).empty());
}

TEST(Polygon, CombWithAThousandTeethIsCoveredWithoutLeavingIt) {
    // A spine 0 <= y <= 1 under teeth x in [2t + 1, 2t + 2], y up to 10, outlined counter-clockwise.
    std::vector<Vec2> comb{{0, 0}, {2000, 0}};
    for (int t = 999; t >= 0; --t) comb.insert(comb.end(), {{2 * t + 2, 10}, {2 * t + 1, 10}, {2 * t + 1, 1}, {2 * t, 1}});
    const auto vertices = in_xy_plane(comb);
    const auto triangles = triangulate_polygon(vertices);
    expect_exact_cover(vertices, triangles);
    expect_centroids_inside(comb, triangles);
}

TEST(Polygon, RandomStarShapedPolygonWithTwoThousandVerticesIsCovered) {
    std::vector<Vec2> outline;
    unsigned state = 12345;
    for (int i = 0; i < 2000; ++i) {
        state = state * 1103515245u + 12345u;
        const double angle = 2.0 * kPi * i / 2000.0;
        const double radius = 1.0 + (state >> 16) % 1000 / 400.0;
        outline.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
    }
    const auto triangles = triangulate_polygon(in_xy_plane(outline));
    expect_exact_cover(in_xy_plane(outline), triangles);
    expect_centroids_inside(outline, triangles);
}

TEST(Polygon, SelfIntersectingPolygonEndsWithTrianglesFacingOneWay) {
    // Not a valid polygon (it winds twice around the centre), but a hostile file must
    // not hang the loader or give triangles facing backwards.
    std::vector<Point3> twice_around;
    for (int i = 0; i < 999; ++i) {
        const double angle = 4.0 * kPi * i / 999.0;
        const double radius = 1.0 + i / 500.0;
        twice_around.emplace_back(radius * std::cos(angle), radius * std::sin(angle), 0.0);
    }
    const auto triangles = triangulate_polygon(twice_around);
    EXPECT_FALSE(triangles.empty());
    for (const auto& [i, j, k] : triangles)
        EXPECT_GT(glm::cross(twice_around[j] - twice_around[i], twice_around[k] - twice_around[i]).z, 0.0);
}
