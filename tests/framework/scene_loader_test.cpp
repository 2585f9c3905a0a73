// The scene loader on good input: one tiny file per keyword and dialect, checking the parsed values.
#include "scene_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using namespace scene_test;

namespace {

template <class T> T shape_of(const LoadedScene& scene, std::size_t i) {
    return std::get<T>(scene.data.primitives.at(i).shape);
}

void expect_vec(const Vec3& actual, const Vec3& expected, double tolerance = 1e-12) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

} // namespace

// ---- NFF ----

TEST(NffLoader, ViewpointGivesTheCameraEyeLookAtUpAndResolution) {
    const auto scene = nff("v\nfrom 1 2 3\nat 0 0 0\nup 0 0 1\nangle 45\nhither 0.01\nresolution 320 200\n");
    const Camera& camera = scene.data.camera;
    expect_vec(camera.eye, {1, 2, 3});
    expect_vec(camera.at, {0, 0, 0});
    expect_vec(camera.up, {0, 0, 1});
    EXPECT_EQ(camera.res_x, 320);
    EXPECT_EQ(camera.res_y, 200);
    EXPECT_DOUBLE_EQ(camera.df, std::sqrt(14.0));
    EXPECT_EQ(scene.data.max_depth, 5);
    EXPECT_TRUE(scene.warnings.empty());
}

// The NFF angle a spans the centres of the top and bottom pixel rows. With H rows
// those centres are (H - 1) / H of the view-plane height h apart, so at view
// distance d: h (H - 1) / H = 2 d tan(a / 2), that is h = 2 d tan(a / 2) H / (H - 1),
// and the slides' full-height angle is fovy = 2 atan(tan(a / 2) H / (H - 1)).
TEST(NffLoader, AngleBetweenRowCentresBecomesTheFullHeightFieldOfView) {
    const auto scene = nff("v from 0 0 10 at 0 0 0 up 0 1 0 angle 45 hither 1 resolution 40 10");
    const Camera& camera = scene.data.camera;
    const double rows = 10.0;
    EXPECT_NEAR(camera.fovy, 2.0 * std::atan(std::tan(radians(22.5)) * rows / (rows - 1.0)) * 180.0 / kPi, 1e-12);
    // The top row's centre is at viewport y = H - 0.5, h ((H - 0.5) / H - 0.5) above the view-plane centre:
    // the ray through it makes half the NFF angle with the view direction.
    const double offset = camera.h * ((rows - 0.5) / rows - 0.5);
    EXPECT_NEAR(std::atan(offset / camera.df), radians(45.0) / 2.0, 1e-12);
}

TEST(NffLoader, OptionalYonAfterHitherIsAccepted) {
    const auto scene = nff("v from 0 0 5 at 0 0 0 up 0 1 0 angle 30 hither 1 yon 1000 resolution 8 8");
    EXPECT_EQ(scene.data.camera.res_x, 8);
}

TEST(NffLoader, BackgroundSetsTheBackgroundColour) {
    expect_vec(nff_body("b 0.1 0.2 0.3").data.background, {0.1, 0.2, 0.3});
}

TEST(NffLoader, LightWithAColourKeepsIt) {
    const auto scene = nff_body("l 1 2 3 0.5 0.25 1");
    ASSERT_EQ(scene.data.lights.size(), 1u);
    expect_vec(scene.data.lights[0].position, {1, 2, 3});
    expect_vec(scene.data.lights[0].color, {0.5, 0.25, 1});
}

TEST(NffLoader, LightsWithoutAColourAndTheAmbientGetTheSpdIntensity) {
    // Haines' SPD rule: sqrt(N) / (2 N) for N = 4 lights is 2 / 8 = 0.25.
    const auto scene = nff_body("l 1 2 3\nl 4 5 6\nl 0 0 9 1 1 1\nl 7 8 9");
    ASSERT_EQ(scene.data.lights.size(), 4u);
    expect_vec(scene.data.lights[0].color, Color(0.25));
    expect_vec(scene.data.lights[1].position, {4, 5, 6});
    expect_vec(scene.data.lights[2].color, Color(1.0));
    expect_vec(scene.data.lights[3].color, Color(0.25));
    expect_vec(scene.data.ambient, Color(0.25));
}

TEST(NffLoader, AnExplicitAmbientWinsOverTheSpdIntensity) {
    const auto scene = nff_body("ambient 0.1 0.2 0.3\nl 1 2 3");
    expect_vec(scene.data.lights[0].color, Color(0.5));
    expect_vec(scene.data.ambient, {0.1, 0.2, 0.3});
}

TEST(NffLoader, ColouredLightsLeaveTheAmbientDark) {
    expect_vec(nff_body("l 1 2 3 1 1 1").data.ambient, Color(0.0));
}

TEST(NffLoader, MaterialGivesColourWeightsExponentTransmittanceAndIor) {
    const auto scene = nff_body("f 1 0.5 0.25 0.7 0.3 20 0.4 1.5\ns 0 0 0 1");
    ASSERT_EQ(scene.data.materials.size(), 1u);
    const Material& m = scene.data.materials[0];
    expect_vec(m.color, {1, 0.5, 0.25});
    EXPECT_DOUBLE_EQ(m.diffuse, 0.7);
    expect_vec(m.specular_color, Color(1.0));
    EXPECT_DOUBLE_EQ(m.specular, 0.3);
    EXPECT_DOUBLE_EQ(m.shininess, 20);
    EXPECT_DOUBLE_EQ(m.transmittance, 0.4);
    EXPECT_DOUBLE_EQ(m.ior, 1.5);
    EXPECT_EQ(scene.data.primitives[0].material, 0u);
}

TEST(NffLoader, OpaqueMaterialWithIorZeroAsInSpdFilesGetsIorOne) {
    EXPECT_DOUBLE_EQ(nff_body("f 1 1 1 1 0 100000 0 0").data.materials[0].ior, 1.0);
}

TEST(NffLoader, ShapesBeforeAnyMaterialAreWhiteAndDiffuse) {
    const auto scene = nff_body("s 0 0 0 1\nf 1 0 0 1 0 1 0 1\ns 3 0 0 1");
    ASSERT_EQ(scene.data.materials.size(), 2u);
    expect_vec(scene.data.materials[0].color, Color(1.0));
    EXPECT_DOUBLE_EQ(scene.data.materials[0].diffuse, 1.0);
    EXPECT_EQ(scene.data.primitives[0].material, 0u);
    EXPECT_EQ(scene.data.primitives[1].material, 1u);
}

TEST(NffLoader, SphereGivesCentreAndRadius) {
    const auto sphere = shape_of<Sphere>(nff_body("s 1 2 3 0.5"), 0);
    expect_vec(sphere.center, {1, 2, 3});
    EXPECT_DOUBLE_EQ(sphere.radius, 0.5);
    EXPECT_FALSE(sphere.inward);
}

TEST(NffLoader, NegativeSphereRadiusMakesAnInwardSphere) {
    const auto sphere = shape_of<Sphere>(nff_body("s 0 0 0 -0.96"), 0);
    EXPECT_DOUBLE_EQ(sphere.radius, 0.96);
    EXPECT_TRUE(sphere.inward);
}

TEST(NffLoader, ConeOnTwoLinesGivesBaseAndApex) {
    const auto cone = shape_of<Cone>(nff_body("c\n0 0 0 1\n0 2 0 0.5\n"), 0);
    expect_vec(cone.base, {0, 0, 0});
    expect_vec(cone.apex, {0, 2, 0});
    EXPECT_DOUBLE_EQ(cone.base_radius, 1.0);
    EXPECT_DOUBLE_EQ(cone.apex_radius, 0.5);
    EXPECT_FALSE(cone.inward);
}

TEST(NffLoader, ConeOnOneLineAsGeneratorsWriteItGivesTheSameCone) {
    const auto cone = shape_of<Cone>(nff_body("c 0 0 0 1 0 2 0 0.5"), 0);
    expect_vec(cone.apex, {0, 2, 0});
    EXPECT_DOUBLE_EQ(cone.apex_radius, 0.5);
}

TEST(NffLoader, ConeWithNegativeRadiiIsInward) {
    const auto cone = shape_of<Cone>(nff_body("c 0 0 0 -1 0 2 0 -1"), 0);
    EXPECT_TRUE(cone.inward);
    EXPECT_DOUBLE_EQ(cone.base_radius, 1.0);
}

TEST(NffLoader, PolygonBecomesTrianglesFacingLikeThePolygon) {
    const auto scene = nff_body("p 4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n");
    ASSERT_EQ(scene.data.primitives.size(), 2u);
    for (const Primitive& primitive : scene.data.primitives) {
        const auto& t = std::get<Triangle>(primitive.shape);
        EXPECT_GT(glm::cross(t.p1 - t.p0, t.p2 - t.p0).z, 0.0);
        EXPECT_EQ(primitive.vertex_normals, -1);
    }
}

TEST(NffLoader, PolygonWithNormalsGivesTrianglesWithUnitVertexNormals) {
    const auto scene = nff_body("pp 3\n0 0 0 0 0 2\n1 0 0 0 0.5 0.5\n0 1 0 0 0 1\n");
    ASSERT_EQ(scene.data.primitives.size(), 1u);
    ASSERT_EQ(scene.data.vertex_normals.size(), 1u);
    EXPECT_EQ(scene.data.primitives[0].vertex_normals, 0);
    const VertexNormals& normals = scene.data.vertex_normals[0];
    expect_vec(normals[0], {0, 0, 1});
    expect_vec(normals[1], {0, std::sqrt(0.5), std::sqrt(0.5)});
    expect_vec(normals[2], {0, 0, 1});
}

TEST(NffLoader, HugeAndTinyVertexNormalsStillBecomeUnitLength) {
    const auto scene = nff_body("pp 3\n0 0 0 0 0 1e15\n1 0 0 0 1e15 1e15\n0 1 0 0 0 1e-300\n");
    const VertexNormals& normals = scene.data.vertex_normals.at(0);
    expect_vec(normals[0], {0, 0, 1});
    expect_vec(normals[1], {0, std::sqrt(0.5), std::sqrt(0.5)});
    expect_vec(normals[2], {0, 0, 1});
}

TEST(NffLoader, FlatPpTriangleFromATessellatorIsSkippedWithAWarning) {
    const auto scene = nff_body("pp 3\n0 0 0 0 0 1\n1 0 0 0 0 1\n2 0 0 0 0 1\n");
    EXPECT_TRUE(scene.data.primitives.empty());
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_EQ(scene.warnings[0].rfind("scene.nff:2:1: warning: ", 0), 0u) << scene.warnings[0];
}

TEST(NffLoader, LineBreaksAndCommentsDoNotMatter) {
    const auto scene = nff("# a comment line\nv from 0 0 5 at 0 0 0 up 0 1 0 # trailing comment\n"
                           "angle\n45 hither 1 resolution 8\n8 s 0 0 0\n1#touching comment\n");
    EXPECT_EQ(scene.data.primitives.size(), 1u);
}

TEST(NffLoader, ShapesBeforeTheViewpointAreFine) {
    const auto scene = nff(std::string("s 0 0 0 1\n") + std::string(kView));
    EXPECT_EQ(scene.data.primitives.size(), 1u);
}

TEST(NffLoader, NumbersMayBeWrittenInAnyUsualForm) {
    const auto sphere = shape_of<Sphere>(nff_body("s 1 -2.5 1e-3 .5\ns +3 0 0 1"), 0);
    expect_vec(sphere.center, {1, -2.5, 1e-3});
    EXPECT_DOUBLE_EQ(sphere.radius, 0.5);
    EXPECT_DOUBLE_EQ(shape_of<Sphere>(nff_body("s +3 0 0 1"), 0).center.x, 3.0);
}

TEST(NffLoader, ExtensionsSetAmbientCheckerAndMaxDepth) {
    const auto scene = nff_body("ambient 0.4 0.4 0.4\nmaxdepth 10\nf 1 1 1 1 0 1 0 1\ns 0 0 0 1\n"
                                "checker 0.5 0.8 0.3 0.15 0.9 0.85 0.05\ns 0 -100 0 99");
    expect_vec(scene.data.ambient, Color(0.4));
    EXPECT_EQ(scene.data.max_depth, 10);
    ASSERT_EQ(scene.data.materials.size(), 2u);
    EXPECT_FALSE(scene.data.materials[0].checker.has_value()); // the shape before `checker` stays plain
    const auto& checker = scene.data.materials[1].checker;
    ASSERT_TRUE(checker.has_value());
    EXPECT_DOUBLE_EQ(checker->size, 0.5);
    expect_vec(checker->color_a, {0.8, 0.3, 0.15});
    expect_vec(checker->color_b, {0.9, 0.85, 0.05});
    EXPECT_EQ(scene.data.primitives[1].material, 1u);
}

// ---- P3F ----

TEST(P3fLoader, ViewpointAngleIsTheFullViewPlaneHeight) {
    const auto scene = p3f("v from 0 0 10 at 0 0 0 up 0 1 0 angle 60 hither 1 resolution 40 10");
    EXPECT_DOUBLE_EQ(scene.data.camera.fovy, 60.0);
    EXPECT_NEAR(scene.data.camera.h, 2.0 * 10.0 * std::tan(radians(30.0)), 1e-12);
    EXPECT_TRUE(scene.warnings.empty());
}

TEST(P3fLoader, ApertureAndFocalMakeAThinLens) {
    // resolution 40 x 10, angle 60, view distance 10: h = 2 * 10 * tan(30 deg) = 11.547, w = 4 h = 46.188.
    // aperture 3 pixel widths: a lens 3 w / 40 across; focal 0.5: in focus at half the view distance.
    const auto scene = p3f("v from 0 0 10 at 0 0 0 up 0 1 0 angle 60 hither 1 resolution 40 10 aperture 3 focal 0.5");
    const Camera& camera = scene.data.camera;
    EXPECT_NEAR(camera.aperture, 3.0 * (4.0 * 2.0 * 10.0 * std::tan(radians(30.0))) / 40.0, 1e-12);
    EXPECT_DOUBLE_EQ(camera.focal_ratio, 0.5);
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front(); // lab 9 renders it (`whitted render` notes it before)
    const auto pinhole = p3f("v from 0 0 1 at 0 0 0 up 0 1 0 angle 60 hither 1 resolution 4 4 aperture 0 focal 2");
    EXPECT_TRUE(pinhole.warnings.empty());
    EXPECT_EQ(pinhole.data.camera.aperture, 0.0);
    EXPECT_EQ(p3f("v from 0 0 1 at 0 0 0 up 0 1 0 angle 60 hither 1 resolution 4 4").data.camera.focal_ratio, 1.0);
}

TEST(P3fLoader, AShutterIsReadAndMotionBlurWarnedAbout) {
    const auto still = p3f("v from 0 0 1 at 0 0 0 up 0 1 0 angle 60 hither 1 resolution 4 4 aperture 0 focal 1 time0 0 time1 0");
    EXPECT_TRUE(still.warnings.empty());
    const auto moving = p3f("v from 0 0 1 at 0 0 0 up 0 1 0 angle 60 hither 1 resolution 4 4 time0 0 time1 1");
    ASSERT_EQ(moving.warnings.size(), 1u);
    EXPECT_NE(moving.warnings[0].find("motion blur is not rendered"), std::string::npos);
}

TEST(P3fLoader, AccelNamesTheStructureByNumberOrName) {
    EXPECT_EQ(p3f_body("accel 0").data.acceleration, Acceleration::none);
    EXPECT_EQ(p3f_body("accel 1").data.acceleration, Acceleration::grid);
    EXPECT_EQ(p3f_body("accel 2").data.acceleration, Acceleration::bvh);
    EXPECT_EQ(p3f_body("accel grid").data.acceleration, Acceleration::grid);
    EXPECT_EQ(p3f_body("s 0 0 0 1").data.acceleration, Acceleration::bvh); // without `accel`
    EXPECT_TRUE(p3f_body("accel 2").warnings.empty());
}

TEST(P3fLoader, ATwelfthMaterialNumberIsTheCoursesRoughness) {
    const auto mirror = p3f_body("f 1 1 1 1 1 1 1 1 10 0 1 0\ns 0 0 0 1");
    EXPECT_TRUE(mirror.warnings.empty());
    EXPECT_EQ(mirror.data.primitives.size(), 1u);
    const auto rough = p3f_body("f 1 1 1 1 1 1 1 1 10 0 1 0.3\ns 0 0 0 1");
    ASSERT_EQ(rough.warnings.size(), 1u);
    EXPECT_EQ(rough.warnings[0], "scene.p3f:2:26: warning: glossy (rough) reflection is not rendered: the reflection is a perfect mirror");
}

TEST(P3fLoader, SppZeroIsWhittedRayTracing) {
    const auto whitted = p3f_body("spp 0");
    EXPECT_EQ(whitted.data.samples_per_pixel, 0);
    EXPECT_TRUE(whitted.warnings.empty());
    EXPECT_EQ(p3f_body("s 0 0 0 1").data.samples_per_pixel, 0); // without `spp`
    const auto scene = p3f_body("spp 4");
    EXPECT_EQ(scene.data.samples_per_pixel, 4);
    EXPECT_TRUE(scene.warnings.empty());
    EXPECT_EQ(p3f_body("spp 65536").data.samples_per_pixel, 65536);
}

TEST(P3fLoader, AnAreaLightIsAParallelogramWithASampleCount) {
    // The extension `arealight centre colour edge_u edge_v samples`, in both dialects.
    const auto scene = p3f_body("arealight 0 7 0  1 0.9 0.8  3 0 0  0 0 2  16");
    ASSERT_EQ(scene.data.area_lights.size(), 1u);
    const AreaLight& light = scene.data.area_lights[0];
    expect_vec(light.center, {0, 7, 0});
    expect_vec(light.color, {1, 0.9, 0.8});
    expect_vec(light.edge_u, {3, 0, 0});
    expect_vec(light.edge_v, {0, 0, 2});
    EXPECT_EQ(light.samples, 16);
    EXPECT_TRUE(scene.data.lights.empty()) << "an area light is not one of the point lights";
    EXPECT_EQ(nff_body("arealight 1 2 3 1 1 1 1 0 0 0 1 0 4").data.area_lights.size(), 1u);
}

TEST(P3fLoader, TheSceneNumbersTheAreaLightsPoints) {
    // Each light's points draw their own sample numbers: the second light's start after the first's.
    const Scene scene(p3f_body("arealight 0 7 0 1 1 1 1 0 0 0 0 1 16\narealight 3 7 0 1 1 1 1 0 0 0 0 1 9\n"
                               "arealight 6 7 0 1 1 1 1 0 0 0 0 1 1").data);
    ASSERT_EQ(scene.area_lights().size(), 3u);
    EXPECT_EQ(scene.area_lights()[0].first_number, 0u);
    EXPECT_EQ(scene.area_lights()[1].first_number, 16u);
    EXPECT_EQ(scene.area_lights()[2].first_number, 25u);
}

TEST(NffLoader, AreaLightsCountForTheDefaultIntensityOfUncolouredLights) {
    // Haines' rule over every light: 2 lights give sqrt(2) / 4 to the uncoloured one.
    const auto scene = nff_body("l 1 2 3\narealight 0 5 0 1 1 1 1 0 0 0 0 1 4");
    EXPECT_NEAR(scene.data.lights.at(0).color.r, std::sqrt(2.0) / 4.0, 1e-15);
}

TEST(P3fLoader, BclrSetsTheBackgroundColour) {
    expect_vec(p3f_body("bclr 0.34 0.55 0.85").data.background, {0.34, 0.55, 0.85});
}

TEST(P3fLoader, LightGivesPositionAndColour) {
    const auto scene = p3f_body("l 60 40 0 1 0.5 1");
    expect_vec(scene.data.lights.at(0).position, {60, 40, 0});
    expect_vec(scene.data.lights.at(0).color, {1, 0.5, 1});
}

TEST(P3fLoader, MaterialGivesDiffuseAndSpecularColoursWithTheirWeights) {
    const Material m = p3f_body("f 0.2 0.7 0.8 0.6 1 0.9 0.8 0.5 64 0.1 1.4").data.materials.at(0);
    expect_vec(m.color, {0.2, 0.7, 0.8});
    EXPECT_DOUBLE_EQ(m.diffuse, 0.6);
    expect_vec(m.specular_color, {1, 0.9, 0.8});
    EXPECT_DOUBLE_EQ(m.specular, 0.5);
    EXPECT_DOUBLE_EQ(m.shininess, 64);
    EXPECT_DOUBLE_EQ(m.transmittance, 0.1);
    EXPECT_DOUBLE_EQ(m.ior, 1.4);
}

TEST(P3fLoader, SphereAndInwardSphereMakeAHollowShell) {
    const auto scene = p3f_body("s 4 2.3 -4 1\ns 4 2.3 -4 -0.96");
    EXPECT_FALSE(shape_of<Sphere>(scene, 0).inward);
    EXPECT_TRUE(shape_of<Sphere>(scene, 1).inward);
    EXPECT_DOUBLE_EQ(shape_of<Sphere>(scene, 1).radius, 0.96);
}

TEST(P3fLoader, PlaneThroughThreePointsFacesWhereTheyRunCounterClockwise) {
    const auto plane = shape_of<Plane>(p3f_body("pl 0 0 0  0 0 1  1 0 0"), 0);
    expect_vec(plane.point, {0, 0, 0});
    expect_vec(plane.normal, {0, 1, 0});
}

TEST(P3fLoader, PolygonBecomesTriangles) {
    EXPECT_EQ(p3f_body("p 3 0 0 0 1 0 0 0 1 0").data.primitives.size(), 1u);
}

TEST(P3fLoader, BoxGivesItsCorners) {
    const auto box = shape_of<Box>(p3f_body("box -1 -2 -3 1 2 3"), 0);
    expect_vec(box.min, {-1, -2, -3});
    expect_vec(box.max, {1, 2, 3});
}

TEST(P3fLoader, MeshIndicesCountFromOneOrBackwardsFromTheLastVertex) {
    const auto scene = p3f_body("mesh 4 2\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n1 2 3\n-4 -2 -1\n");
    ASSERT_EQ(scene.data.primitives.size(), 2u);
    const auto& first = shape_of<Triangle>(scene, 0);
    const auto& second = shape_of<Triangle>(scene, 1);
    expect_vec(first.p2, {1, 1, 0});
    expect_vec(second.p0, {0, 0, 0});
    expect_vec(second.p1, {1, 1, 0});
    expect_vec(second.p2, {0, 1, 0});
}

TEST(P3fLoader, ExtensionsWorkInP3fToo) {
    const auto scene = p3f_body("ambient 0.4 0.4 0.4 maxdepth 10 f 1 1 1 1 0 0 0 0 1 0 1 checker 1 1 0 0 0 0 1");
    expect_vec(scene.data.ambient, Color(0.4));
    EXPECT_EQ(scene.data.max_depth, 10);
    EXPECT_TRUE(scene.data.materials.back().checker.has_value());
}

TEST(NffLoader, AByteOrderMarkAtTheStartIsSkipped) {
    const LoadedScene scene = parse_scene("\xEF\xBB\xBFv from 0 0 5 at 0 0 0 up 0 1 0 angle 45 hither 1 resolution 8 8\n",
                                          Dialect::nff, "bom.nff");
    EXPECT_EQ(scene.data.camera.res_x, 8);
}
