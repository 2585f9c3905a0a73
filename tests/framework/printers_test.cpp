// The values the tests compare print readably when an assertion fails
// (tests/support/printers.hpp), never as GoogleTest's "24-byte object <...>".
#include "whitted/labs.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <vector>

using namespace whitted;
using ::testing::PrintToString;

TEST(Printers, VectorsPrintTheirCoordinatesInFull) {
    EXPECT_EQ(PrintToString(Vec2(0.5, -2.0)), "(0.5, -2)");
    EXPECT_EQ(PrintToString(Vec3(1.0, 0.1, -0.0)), "(1, 0.1, -0)");
    // Full precision: two doubles that differ in the last bit print differently.
    EXPECT_EQ(PrintToString(Point3(0.1 + 0.2, 1e-300, kInfinity)), "(0.30000000000000004, 1e-300, inf)");
    EXPECT_EQ(PrintToString(Color(0.25)), "(0.25, 0.25, 0.25)");
}

TEST(Printers, RaysHitsAndRangesPrintTheirFields) {
    EXPECT_EQ(PrintToString(Ray{Point3(0.0, 0.0, 5.0), Vec3(0.0, 0.0, -1.0)}), "Ray{origin (0, 0, 5), direction (0, 0, -1)}");
    Hit hit;
    hit.t = 2.5;
    hit.point = Point3(0.0, 0.0, 2.5);
    hit.normal = hit.geometric_normal = Vec3(0.0, 0.0, 1.0);
    hit.front_face = false;
    hit.uv = Vec2(0.25, 0.5);
    hit.primitive = 3;
    hit.material = 1;
    EXPECT_EQ(PrintToString(hit), "Hit{t 2.5, point (0, 0, 2.5), normal (0, 0, 1), geometric_normal (0, 0, 1), back face, "
                                  "uv (0.25, 0.5), primitive 3, material 1}");
    EXPECT_EQ(PrintToString(Interval{}), "Interval{min 0, max inf}");
    EXPECT_EQ(PrintToString(Aabb{Point3(-1.0), Point3(1.0, 2.0, 3.0)}), "Aabb{min (-1, -1, -1), max (1, 2, 3)}");
}

TEST(Printers, OptionalsPrintTheirValueOrNullopt) {
    EXPECT_EQ(PrintToString(std::optional<double>(0.5)), "(0.5)");
    EXPECT_EQ(PrintToString(std::optional<double>()), "(nullopt)");
    EXPECT_EQ(PrintToString(std::optional<Vec3>(Vec3(1.0, 2.0, 3.0))), "((1, 2, 3))");
    EXPECT_EQ(PrintToString(std::optional<Hit>(Hit{})), "(Hit{t 0, point (0, 0, 0), normal (0, 0, 0), geometric_normal (0, 0, 0), "
                                                         "front face, uv (0, 0), primitive 0, material 0})");
    EXPECT_EQ(PrintToString(std::optional<Hit>()), "(nullopt)");
}

TEST(Printers, LightsCamerasAndSamplesPrintTheirFields) {
    EXPECT_EQ(PrintToString(PointLight{Point3(1.0, 2.0, 3.0), Color(0.5)}),
              "PointLight{position (1, 2, 3), color (0.5, 0.5, 0.5)}");
    EXPECT_EQ(PrintToString(std::vector<PointLight>{PointLight{Point3(0.0), Color(1.0)}}),
              "{ PointLight{position (0, 0, 0), color (1, 1, 1)} }");
    AreaLight area;
    area.center = Point3(0.0);
    area.samples = 4;
    EXPECT_EQ(PrintToString(area), "AreaLight{center (0, 0, 0), color (1, 1, 1), edge_u (1, 0, 0), edge_v (0, 0, 1), "
                                   "samples 4, first_number 0}");
    const Camera camera = Camera::create(Point3(0.0, 0.0, 1.0), Point3(0.0), Vec3(0.0, 1.0, 0.0), 90.0, 4, 2);
    EXPECT_EQ(PrintToString(camera), "Camera{eye (0, 0, 1), at (0, 0, 0), up (0, 1, 0), fovy 90, res 4 x 2, aperture 0, "
                                     "focal_ratio 1; df 1, w 3.9999999999999996, h 1.9999999999999998, xe (1, 0, 0), "
                                     "ye (0, 1, 0), ze (0, 0, 1)}");
    EXPECT_EQ(PrintToString(PixelSample{3, 5, 2}), "PixelSample{x 3, y 5, index 2}");
}

TEST(Printers, TreesAndShapesPrintTheirFields) {
    const BvhNode leaf{Aabb{Point3(0.0), Point3(1.0)}, 0, 2};
    EXPECT_EQ(PrintToString(leaf), "BvhNode{bounds Aabb{min (0, 0, 0), max (1, 1, 1)}, first 0, count 2 (a leaf)}");
    const BvhTree tree{{leaf}, {0, 1}};
    EXPECT_EQ(PrintToString(tree), "BvhTree{1 nodes, 2 indices in order, root BvhNode{bounds Aabb{min (0, 0, 0), "
                                   "max (1, 1, 1)}, first 0, count 2 (a leaf)}}");
    EXPECT_EQ(PrintToString(Sphere{Point3(0.0), 2.0, true}), "Sphere{center (0, 0, 0), radius 2, inward}");
    EXPECT_EQ(PrintToString(Plane{Point3(0.0), Vec3(0.0, 1.0, 0.0)}), "Plane{point (0, 0, 0), normal (0, 1, 0)}");
    EXPECT_EQ(PrintToString(Triangle{Point3(0.0), Point3(1.0, 0.0, 0.0), Point3(0.0, 1.0, 0.0)}),
              "Triangle{p0 (0, 0, 0), p1 (1, 0, 0), p2 (0, 1, 0)}");
    EXPECT_EQ(PrintToString(Primitive{Box{Point3(0.0), Point3(1.0)}, 2}), "Primitive{Box{min (0, 0, 0), max (1, 1, 1)}, material 2, index 0}");
    EXPECT_EQ(PrintToString(Cone{Point3(0.0), 1.0, Point3(0.0, 1.0, 0.0), 0.5}),
              "Cone{base (0, 0, 0), base_radius 1, apex (0, 1, 0), apex_radius 0.5}");
}
