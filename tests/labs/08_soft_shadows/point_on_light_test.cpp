// Lab 8, point_on_light(): (u, v) in [0, 1)^2 to a point of the parallelogram
// center + s edge_u + t edge_v, s and t from -1/2 to 1/2, with s = u - 1/2 and t = v - 1/2.
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace whitted;
using namespace whitted::testing_helpers;

TEST(PointOnLight, TheCornersAndTheCentreOfASquareLight) {
    // A 2 x 2 square at height 10 in the xz-plane: edge_u along +x, edge_v along +z.
    const AreaLight light = square_light(Point3(1.0, 10.0, -3.0), 2.0, 4);
    expect_point(point_on_light(light, Vec2(0.0, 0.0)), Point3(0.0, 10.0, -4.0), "(0, 0): centre - edge_u/2 - edge_v/2");
    expect_point(point_on_light(light, Vec2(0.5, 0.5)), Point3(1.0, 10.0, -3.0), "(1/2, 1/2): the centre");
    expect_point(point_on_light(light, Vec2(0.5, 0.0)), Point3(1.0, 10.0, -4.0), "(1/2, 0): middle of the first edge");
    expect_point(point_on_light(light, Vec2(0.0, 0.5)), Point3(0.0, 10.0, -3.0), "(0, 1/2)");
    // u runs along edge_u (+x), v along edge_v (+z).
    expect_point(point_on_light(light, Vec2(0.25, 0.75)), Point3(0.5, 10.0, -2.5), "(1/4, 3/4)");
}

TEST(PointOnLight, ALeaningParallelogramFollowsItsEdges) {
    // Edges that are neither unit length nor at right angles: the point is
    // center + (u - 1/2) edge_u + (v - 1/2) edge_v.
    AreaLight light;
    light.center = Point3(-2.0, 5.0, 1.0);
    light.edge_u = Vec3(3.0, 0.0, 1.0);
    light.edge_v = Vec3(1.0, 1.0, 0.0);
    // (0.1, 0.9): -0.4 edge_u + 0.4 edge_v = (-1.2 + 0.4, 0.4, -0.4).
    expect_point(point_on_light(light, Vec2(0.1, 0.9)), Point3(-2.8, 5.4, 0.6), "(0.1, 0.9)");
    // (1, 1) (the limit of the range) is the far corner, centre + (edge_u + edge_v) / 2.
    expect_point(point_on_light(light, Vec2(1.0, 1.0)), Point3(0.0, 5.5, 1.5), "(1, 1)");
}

TEST(PointOnLight, EveryPointLiesOnTheLightsPlaneAndInsideIt) {
    AreaLight light;
    light.center = Point3(4.0, 7.0, -1.0);
    light.edge_u = Vec3(0.0, 2.0, 2.0);
    light.edge_v = Vec3(1.5, 0.0, 0.0);
    const Vec3 normal = glm::normalize(glm::cross(light.edge_u, light.edge_v));
    for (double u : {0.0, 0.13, 0.5, 0.77, 0.999}) {
        for (double v : {0.0, 0.31, 0.62, 0.999}) {
            const Vec3 offset = point_on_light(light, Vec2(u, v)) - light.center;
            std::string where = "(";
            where.append(std::to_string(u)).append(", ").append(std::to_string(v)).append(")");
            EXPECT_NEAR(glm::dot(offset, normal), 0.0, 1e-12) << where << " is off the light's plane";
            // edge_u and edge_v are at right angles here: the coordinates are projections.
            EXPECT_NEAR(glm::dot(offset, light.edge_u) / glm::dot(light.edge_u, light.edge_u), u - 0.5, 1e-12) << where;
            EXPECT_NEAR(glm::dot(offset, light.edge_v) / glm::dot(light.edge_v, light.edge_v), v - 0.5, 1e-12) << where;
            if (enough_failures()) return;
        }
    }
}
