// The scene loader on bad input: every error is one line "file:line:col: expected ..., found ...".
// Bodies follow the one-line viewpoint of scene_test::kView, so they start on line 2.
#include "scene_test_support.hpp"

#include <gtest/gtest.h>

using namespace whitted;
using namespace scene_test;

namespace {

/// Checks that the message starts with the location and contains the fragment.
void expect_error(const std::string& message, std::string_view location, std::string_view fragment) {
    EXPECT_EQ(message.rfind(location, 0), 0u) << message;
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

std::string view_error(std::string_view text, Dialect dialect = Dialect::nff) { return error_of(text, dialect); }

} // namespace

// ---- tokens and numbers ----

TEST(SceneErrors, UnknownKeywordIsNamedWithItsPosition) {
    EXPECT_EQ(nff_error("s 0 0 0 1\n  foo 1 2"), "scene.nff:3:3: unknown keyword 'foo'");
}

TEST(SceneErrors, KeywordOfTheOtherDialectGetsAHint) {
    expect_error(nff_error("box 0 0 0 1 1 1"), "scene.nff:2:1: unknown keyword 'box'", "P3F keyword");
    expect_error(p3f_error("b 0 0 0"), "scene.p3f:2:1: unknown keyword 'b'", "NFF keyword");
}

TEST(SceneErrors, TruncatedFileSaysHowManyNumbersAreMissing) {
    EXPECT_EQ(nff_error("s 1 2"), "scene.nff:2:6: expected 2 more numbers for 's', found end of file");
    EXPECT_EQ(nff_error("p 4\n0 0 0\n1 0 0\n1 1"),
              "scene.nff:5:4: expected 4 more numbers for 'p', found end of file");
}

TEST(SceneErrors, WordWhereANumberBelongsIsNamed) {
    EXPECT_EQ(nff_error("s 0 0 0 abc"), "scene.nff:2:9: expected a number for the sphere radius, found 'abc'");
    expect_error(nff_error("s 0 0 0\ns 1 1 1 1"), "scene.nff:3:1: expected a number for the sphere radius", "'s'");
    expect_error(nff_error("s 0 0 0 1.2.3"), "scene.nff:2:9: expected a number", "'1.2.3'");
}

TEST(SceneErrors, ExtraNumberWhereAKeywordBelongsIsAnError) {
    expect_error(nff_error("s 0 0 0 1 2"), "scene.nff:2:11: expected a keyword, found the number '2'", "too many");
}

TEST(SceneErrors, NumberAtTheStartOfTheFileAsksForAKeyword) {
    EXPECT_EQ(error_of("  0 0 5", Dialect::p3f),
              "scene.p3f:1:3: expected a keyword, found the number '0' (every entity starts with a keyword such as "
              "'v' or 's')");
}

TEST(SceneErrors, BinaryAndUtf16FilesAreNamedAsNotText) {
    expect_error(error_of("\x89PNG\r\n", Dialect::nff), "scene.nff:1:1: unknown keyword '\\x89PNG'",
                 "not plain text");
    EXPECT_EQ(error_of("\xFF\xFEv\0", Dialect::nff),
              "scene.nff:1:1: expected a text file in ASCII or UTF-8, found UTF-16 (save the file as UTF-8)");
    // A UTF-8 word is text, so it gets no such hint.
    EXPECT_EQ(nff_error("k\xC3\xBCgel 1"), "scene.nff:2:1: unknown keyword 'k\\xc3\\xbcgel'");
}

TEST(SceneErrors, NanInfinityAndOverflowAreNotFiniteNumbers) {
    EXPECT_EQ(nff_error("s 0 0 0 nan"), "scene.nff:2:9: expected a finite number for the sphere radius, found 'nan'");
    expect_error(nff_error("s 0 0 -inf 1"), "scene.nff:2:7: expected a finite number", "'-inf'");
    expect_error(nff_error("s 0 1e999 0 1"), "scene.nff:2:5: expected a finite number", "'1e999'");
}

TEST(SceneErrors, TinyNumbersUnderflowToZeroWithoutAnError) {
    EXPECT_EQ(nff_error("s 0 1e-400 0 1"), "no error");
}

// ---- values out of range ----

TEST(SceneErrors, ZeroSphereRadiusIsAnError) {
    EXPECT_EQ(nff_error("s 0 0 0 0"), "scene.nff:2:9: expected a non-zero sphere radius, found '0'");
    expect_error(p3f_error("s 0 0 0 0.0"), "scene.p3f:2:9: expected a non-zero sphere radius", "'0.0'");
}

TEST(SceneErrors, ConeWithBothRadiiZeroIsAnError) {
    expect_error(nff_error("c 0 0 0 0 0 1 0 0"), "scene.nff:2:17: expected a cone with a non-zero radius", "0");
}

TEST(SceneErrors, ConeWithRadiiOfBothSignsIsAnError) {
    expect_error(nff_error("c 0 0 0 -1\n0 1 0 1"), "scene.nff:3:7: expected cone radii of one sign", "'1'");
}

TEST(SceneErrors, ConeWithApexAtItsBaseIsAnError) {
    expect_error(nff_error("c 0 0 0 1 0 0 0 1"), "scene.nff:2:1: expected a cone whose apex differs", "one point");
}

TEST(SceneErrors, NonPositiveIorOfATransmittingMaterialIsAnError) {
    expect_error(nff_error("f 1 1 1 0 0 1 0.5 0"), "scene.nff:2:19: expected a positive index of refraction",
                 "found '0'");
    expect_error(nff_error("f 1 1 1 0 0 1 0 -1.5"), "scene.nff:2:17: expected a positive index of refraction",
                 "'-1.5'");
}

TEST(SceneErrors, NegativeMaterialWeightsColoursAndExponentAreErrors) {
    expect_error(nff_error("f 1 -1 1 1 0 1 0 1"), "scene.nff:2:5: expected a non-negative number for the material colour", "'-1'");
    expect_error(nff_error("f 1 1 1 -1 0 1 0 1"), "scene.nff:2:9: expected a non-negative number for the diffuse weight Kd", "'-1'");
    expect_error(nff_error("f 1 1 1 1 -1 1 0 1"), "scene.nff:2:11: expected a non-negative number for the specular weight Ks", "'-1'");
    expect_error(nff_error("f 1 1 1 1 0 -1 0 1"), "scene.nff:2:13: expected a non-negative number for the highlight exponent", "'-1'");
    expect_error(nff_error("f 1 1 1 1 0 1 -1 1"), "scene.nff:2:15: expected a non-negative number for the transmittance", "'-1'");
    expect_error(p3f_error("f 1 1 1 1 1 -1 1 1 1 0 1"), "scene.p3f:2:13: expected a non-negative number for the specular colour", "'-1'");
    expect_error(nff_error("b 0 -0.5 0"), "scene.nff:2:5: expected a non-negative number for the background colour", "'-0.5'");
    expect_error(nff_error("l 0 0 0 1 -1 1"), "scene.nff:2:11: expected a non-negative number for the light colour", "'-1'");
    expect_error(nff_error("ambient 0 0 -1"), "scene.nff:2:13: expected a non-negative number for the ambient", "'-1'");
}

TEST(SceneErrors, NffLightWithAPartialColourIsAnError) {
    EXPECT_EQ(nff_error("l 0 0 0 1 1"), "scene.nff:2:12: expected 1 more number for 'l', found end of file");
}

// ---- the viewpoint ----

TEST(SceneErrors, MissingViewpointIsReportedAtTheEndOfTheFile) {
    EXPECT_EQ(view_error("s 0 0 0 1\n"), "scene.nff:1:10: expected a viewpoint 'v' in the file, found end of file");
    EXPECT_EQ(view_error(""), "scene.nff:1:1: expected a viewpoint 'v' in the file, found end of file");
}

TEST(SceneErrors, ViewpointWordsOutOfOrderAreNamed) {
    EXPECT_EQ(view_error("v at 0 0 0 from 0 0 1"), "scene.nff:1:3: expected 'from' in the viewpoint 'v', found 'at'");
}

TEST(SceneErrors, UpParallelToTheViewDirectionIsAnError) {
    expect_error(view_error("v from 0 0 5 at 0 0 0 up 0 0 -2 angle 45 hither 1 resolution 8 8"),
                 "scene.nff:1:23: expected an up direction not parallel", "parallel");
}

TEST(SceneErrors, ZeroUpIsAnError) {
    expect_error(view_error("v from 0 0 5 at 0 0 0 up 0 0 0 angle 45 hither 1 resolution 8 8"),
                 "scene.nff:1:23: expected a non-zero up direction", "0 0 0");
}

TEST(SceneErrors, EyeAtTheLookAtPointIsAnError) {
    expect_error(view_error("v from 1 2 3 at 1 2 3 up 0 1 0 angle 45 hither 1 resolution 8 8"),
                 "scene.nff:1:14: expected a look-at point 'at' away from the eye", "same point");
}

TEST(SceneErrors, AngleOutsideZeroTo180IsAnError) {
    for (const char* angle : {"0", "180", "-5", "200"})
        expect_error(view_error(std::string("v from 0 0 5 at 0 0 0 up 0 1 0 angle ") + angle +
                                " hither 1 resolution 8 8"),
                     "scene.nff:1:38: expected an angle between 0 and 180 degrees", angle);
}

TEST(SceneErrors, ResolutionMustBeAPositiveWholeNumberWithinTheLimit) {
    const std::string start = "v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 hither 1 resolution ";
    expect_error(view_error(start + "0 8"), "scene.nff:1:61: expected a whole number from 1 to 16384", "'0'");
    expect_error(view_error(start + "-4 8"), "scene.nff:1:61: expected a whole number from 1 to 16384", "'-4'");
    expect_error(view_error(start + "8 20000"), "scene.nff:1:63: expected a whole number from 1 to 16384", "'20000'");
    expect_error(view_error(start + "512.5 8"), "scene.nff:1:61: expected a whole number for the image width",
                 "'512.5'");
    expect_error(view_error(start + "99999999999999999999 8"), "scene.nff:1:61: expected a whole number from 1", "");
}

TEST(SceneErrors, NffResolutionNeedsTwoRowsForItsAngle) {
    expect_error(view_error("v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 hither 1 resolution 8 1"),
                 "scene.nff:1:63: expected at least 2 pixel rows", "'1'");
    EXPECT_EQ(view_error("v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 hither 1 resolution 8 1", Dialect::p3f), "no error");
}

// ---- polygons, meshes and limits ----

TEST(SceneErrors, PolygonOnOneLineIsAnErrorAtItsKeyword) {
    expect_error(nff_error("s 0 0 0 1\n p 3 0 0 0 1 1 1 2 2 2"), "scene.nff:3:2: expected a polygon with an area",
                 "one line");
}

TEST(SceneErrors, PolygonWithFewerThanThreeVerticesIsAnError) {
    expect_error(nff_error("p 2 0 0 0 1 1 1"), "scene.nff:2:3: expected a whole number from 3 to 10000", "'2'");
    expect_error(nff_error("p 3.5"), "scene.nff:2:3: expected a whole number for the number of polygon vertices",
                 "'3.5'");
}

TEST(SceneErrors, PolygonWithMoreVerticesThanTheLimitIsAnError) {
    SceneLimits limits;
    limits.max_polygon_vertices = 4;
    expect_error(nff_error("p 5", limits), "scene.nff:2:3: expected a whole number from 3 to 4", "'5'");
}

TEST(SceneErrors, MorePrimitivesThanTheLimitIsAnError) {
    SceneLimits limits;
    limits.max_primitives = 2;
    EXPECT_EQ(nff_error("s 0 0 0 1\ns 0 0 0 1\ns 0 0 0 1", limits),
              "scene.nff:4:1: expected at most 2 primitives in the scene, found more");
    expect_error(nff_error("p 4 0 0 0 1 0 0 1 1 0 0 1 0\np 3 0 0 0 1 0 0 1 1 0", limits), "scene.nff:3:1:", "at most");
}

TEST(SceneErrors, ZeroLengthVertexNormalIsAnError) {
    expect_error(nff_error("pp 3\n0 0 0 0 0 1\n1 0 0 0 0 0\n0 1 0 0 0 1"),
                 "scene.nff:4:7: expected a non-zero vertex normal", "0 0 0");
}

TEST(SceneErrors, BoxWithMinNotBelowMaxIsAnError) {
    EXPECT_EQ(p3f_error("box 0 0 0 1 0 1"),
              "scene.p3f:2:1: expected a box with min < max on every axis, found y min 0 >= max 0");
    expect_error(p3f_error("box 2 0 0 1 1 1"), "scene.p3f:2:1: expected a box", "x min 2 >= max 1");
}

TEST(SceneErrors, PlaneThroughThreePointsOnOneLineIsAnError) {
    expect_error(p3f_error("pl 0 0 0 1 1 1 2 2 2"), "scene.p3f:2:1: expected three points of a plane", "one line");
}

TEST(SceneErrors, MeshIndexZeroOrOutOfRangeIsAnErrorAtTheIndex) {
    const std::string vertices = "mesh 3 1\n0 0 0\n1 0 0\n0 1 0\n";
    expect_error(p3f_error(vertices + "1 0 2"), "scene.p3f:6:3: expected a vertex index from 1 to 3", "'0'");
    expect_error(p3f_error(vertices + "1 2 4"), "scene.p3f:6:5: expected a vertex index from 1 to 3", "'4'");
    expect_error(p3f_error(vertices + "-4 1 2"), "scene.p3f:6:1: expected a vertex index from 1 to 3", "'-4'");
    expect_error(p3f_error(vertices + "1 2.5 3"), "scene.p3f:6:3: expected a whole number", "'2.5'");
    expect_error(p3f_error(vertices + "1 2 -99999999999999999999"), "scene.p3f:6:5: expected a vertex index from 1 to 3",
                 "'-99999999999999999999'");
    EXPECT_EQ(p3f_error(vertices + "1 2"), "scene.p3f:6:4: expected 1 more number for 'mesh', found end of file");
}

// ---- dialect details and extensions ----

TEST(SceneErrors, P3fLightWithoutAColourIsAnError) {
    expect_error(p3f_error("l 0 0 0\ns 0 0 0 1"), "scene.p3f:3:1: expected a number for the light colour", "'s'");
}

TEST(SceneErrors, P3fMaterialWithNffsEightNumbersIsAnError) {
    expect_error(p3f_error("f 1 1 1 1 0 1 0 1\ns 0 0 0 1"), "scene.p3f:3:1: expected a number", "'s'");
}

TEST(SceneErrors, P3fNegativeSamplesPerPixelIsAnError) {
    expect_error(p3f_error("spp -1"), "scene.p3f:2:5: expected a whole number from 0", "'-1'");
}

TEST(SceneErrors, P3fNegativeApertureIsAnError) {
    expect_error(view_error("v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 hither 1 resolution 8 8 aperture -1",
                            Dialect::p3f),
                 "scene.p3f:1:74: expected a non-negative number for the lens aperture", "'-1'");
}

TEST(SceneErrors, P3fAccelWithoutAName) {
    EXPECT_EQ(p3f_error("accel"),
              "scene.p3f:2:6: expected an acceleration structure (0 none, 1 grid, 2 bvh) after 'accel', found end of file");
}

TEST(SceneErrors, P3fUnknownAccelIsAnError) {
    EXPECT_EQ(p3f_error("accel 3"), "scene.p3f:2:7: expected 0 (none), 1 (grid) or 2 (bvh) after 'accel', found '3'");
}

TEST(SceneErrors, P3fShutterClosingBeforeItOpensIsAnError) {
    expect_error(view_error("v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 hither 1 resolution 8 8 time0 1 time1 0",
                            Dialect::p3f),
                 "scene.p3f:1:65: expected time0 <= time1", "1 > 0");
}

TEST(SceneErrors, AnAreaLightNeedsTwoEdgesThatSpanAnArea) {
    EXPECT_EQ(p3f_error("arealight 0 5 0 1 1 1 1 0 0 2 0 0 4"),
              "scene.p3f:2:1: expected two edges that span a parallelogram after 'arealight', found edges along one line "
              "(a light without area is a point light: 'l')");
    EXPECT_EQ(p3f_error("arealight 0 5 0 1 1 1 0 0 0 0 0 1 4"),
              "scene.p3f:2:1: expected two edges that span a parallelogram after 'arealight', found edges along one line "
              "(a light without area is a point light: 'l')");
}

TEST(SceneErrors, AnAreaLightsSampleCountIsAWholeNumberFromOne) {
    expect_error(p3f_error("arealight 0 5 0 1 1 1 1 0 0 0 0 1 0"),
                 "scene.p3f:2:35: expected a whole number from 1 to 4096 for the area light's sample count", "'0'");
    expect_error(p3f_error("arealight 0 5 0 1 1 1 1 0 0 0 0 1 5000"),
                 "scene.p3f:2:35: expected a whole number from 1 to 4096 for the area light's sample count", "'5000'");
    expect_error(p3f_error("arealight 0 5 0 1 1 1 1 0 0 0 0 1"),
                 "scene.p3f:2:34: expected 1 more number for 'arealight'", "end of file");
}

TEST(SceneErrors, CheckerBeforeAnyMaterialIsAnError) {
    expect_error(nff_error("checker 1 0 0 0 1 1 1"), "scene.nff:2:1: expected a material 'f' before 'checker'", "none");
}

TEST(SceneErrors, CheckerSizeMustBePositive) {
    expect_error(nff_error("f 1 1 1 1 0 1 0 1\nchecker 0 0 0 0 1 1 1"),
                 "scene.nff:3:9: expected a positive number for the checker square size", "'0'");
}

TEST(SceneErrors, MaxDepthMustBeAWholeNumberOfAtLeastOne) {
    expect_error(nff_error("maxdepth 0"), "scene.nff:2:10: expected a whole number from 1", "'0'");
    expect_error(nff_error("maxdepth 2.5"), "scene.nff:2:10: expected a whole number", "'2.5'");
}

TEST(SceneErrors, NumbersBeyondOneE15AreAnError) {
    // Their squares would overflow lengths and areas, which would silently drop shapes.
    expect_error(nff_error("s 0 0 0 1e300"), "scene.nff:2:9: expected a number between -1e15 and 1e15 for the sphere radius",
                 "'1e300'");
}

TEST(SceneErrors, ControlBytesInAWordAreShownEscaped) {
    expect_error(nff_error("s 0 0 0 1\x01"), "scene.nff:2:9: expected a number for the sphere radius", "'1\\x01'");
}
