// The diagnostic passes (whitted render --pass) on scenes whose answer is known.
#include "lab_helpers.hpp"
#include "whitted/passes.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <set>

using namespace whitted;
using namespace whitted::testing_helpers;

namespace {

constexpr int kSize = 21; // odd: the centre pixel's ray goes exactly along the view direction

// The camera at (0, 0, 5) looks at the origin, where `shape` sits.
SceneData looking_at(const Material& material, double radius = 1.0) {
    SceneData data;
    data.camera = Camera::create(Point3(0.0, 0.0, 5.0), Point3(0.0), Vec3(0.0, 1.0, 0.0), 40.0, kSize, kSize);
    data.background = Color(0.3);
    data.materials = {material};
    data.primitives.push_back({Sphere{Point3(0.0), radius}, 0});
    return data;
}

Color centre(const PassResult& result) { return result.render.image.at(kSize / 2, kSize / 2); }
Color corner(const PassResult& result) { return result.render.image.at(0, 0); }

// The camera looks down at the origin of the white floor y = 0, lit by one light at `light`.
SceneData lit_floor(const Point3& light) {
    SceneData data;
    data.camera = Camera::create(Point3(0.0, 6.0, 6.0), Point3(0.0), Vec3(0.0, 1.0, 0.0), 60.0, kSize, kSize);
    data.lights = {PointLight{light, Color(1.0)}};
    data.materials = {diffuse_material(Color(1.0))};
    data.primitives.push_back({Plane{Point3(0.0), Vec3(0.0, 1.0, 0.0)}, 0});
    return data;
}

PassResult run(const SceneData& data, Pass pass, int stage = 6, int threads = 1) {
    const Scene scene{SceneData(data)};
    RenderSettings settings;
    settings.stage = stage;
    return render_pass(scene, settings, pass, threads);
}

} // namespace

TEST(Passes, NamesAreTheOnesTheCommandLineTakes) {
    for (const PassInfo& info : all_passes()) {
        ASSERT_EQ(find_pass(info.name), info.pass);
        EXPECT_EQ(pass_info(info.pass).name, info.name);
    }
    EXPECT_EQ(all_passes().size(), 9u);
    EXPECT_FALSE(find_pass("normals").has_value());
}

TEST(Passes, EveryPassIsBitIdenticalForAnyThreadCount) {
    SceneData data = looking_at(mirror_material(0.5));
    data.lights = {PointLight{Point3(3.0, 3.0, 3.0), Color(1.0)}};
    data.camera = data.camera.with_resolution(37, 29);
    for (const PassInfo& info : all_passes()) {
        const Image one = run(data, info.pass, 6, 1).render.image;
        const Image three = run(data, info.pass, 6, 3).render.image;
        EXPECT_EQ(std::memcmp(one.pixels.data(), three.pixels.data(), one.pixels.size() * sizeof(Color)), 0) << info.name;
    }
}

TEST(Passes, NormalFacingTheCameraIsBlueWhite) {
    // The centre ray hits the sphere head on: normal (0, 0, 1) -> (0.5, 0.5, 1).
    const PassResult result = run(looking_at(diffuse_material(Color(1.0))), Pass::normal);
    EXPECT_NEAR(glm::length(centre(result) - Color(0.5, 0.5, 1.0)), 0.0, 1e-12);
    EXPECT_EQ(corner(result), Color(0.0)); // background
}

TEST(Passes, DepthIsWhiteAtTheNearestPointAndBlackOnTheBackground) {
    const PassResult result = run(looking_at(diffuse_material(Color(1.0))), Pass::depth);
    EXPECT_EQ(centre(result), Color(1.0)); // the centre ray's t = 4 is the smallest
    EXPECT_EQ(corner(result), Color(0.0));
    EXPECT_LT(result.render.image.at(kSize / 2 + 4, kSize / 2).x, 1.0); // farther towards the rim
}

TEST(Passes, AlbedoIsKdTimesTheColour) {
    Material material = diffuse_material(Color(0.8, 0.4, 0.2));
    material.diffuse = 0.5;
    const PassResult result = run(looking_at(material), Pass::albedo);
    EXPECT_EQ(centre(result), Color(0.4, 0.2, 0.1));
}

TEST(Passes, ShadowIsBlackWhereABlockerHidesTheOnlyLight) {
    // The light is straight above the floor's origin at (0, 5, 0) and a ball at
    // (0, 2.5, 0) hides it from the origin. Far from the origin the floor sees the
    // light: white somewhere.
    SceneData data = lit_floor(Point3(0.0, 5.0, 0.0));
    data.primitives.push_back({Sphere{Point3(0.0, 2.5, 0.0), 0.5}, 0});
    const PassResult result = run(data, Pass::shadow, 2);
    EXPECT_EQ(centre(result), Color(0.0));
    int white = 0;
    for (const Color& c : result.render.image.pixels) white += c == Color(1.0);
    EXPECT_GT(white, kSize * kSize / 4);
}

TEST(Passes, ShadowFeelersGetABudgetPerPixelNotPerImage) {
    // A floor lit from straight above, nothing in between: every pixel that sees
    // the floor is white. The budget of rays per pixel (here 3) must start again
    // at each pixel; spent once for the whole image (one thread: 21 x 21 = 441
    // feelers), the pixels after the third would read "blocked", black.
    const Scene scene{lit_floor(Point3(0.0, 50.0, 0.0))};
    RenderSettings settings;
    settings.stage = 2;
    settings.max_rays_per_pixel = 3;
    const PassResult result = render_pass(scene, settings, Pass::shadow, 1);
    int black = 0;
    for (const Color& c : result.render.image.pixels) black += c == Color(0.0);
    EXPECT_EQ(black, 0) << "pixels read as in shadow under an open sky";
    EXPECT_EQ(result.render.stats.pixels_cut_short, 0u);
}

TEST(Passes, ShadowIsGreyWhereOneOfTwoLightsIsHidden) {
    // As above, plus a second light at (5, 5, 0) that the ball does not hide
    // from the origin: one light of two reaches it, grey 0.5.
    SceneData data;
    data.camera = Camera::create(Point3(0.0, 6.0, 6.0), Point3(0.0), Vec3(0.0, 1.0, 0.0), 60.0, kSize, kSize);
    data.lights = {PointLight{Point3(0.0, 5.0, 0.0), Color(1.0)}, PointLight{Point3(5.0, 5.0, 0.0), Color(1.0)}};
    data.materials = {diffuse_material(Color(1.0))};
    data.primitives.push_back({Plane{Point3(0.0), Vec3(0.0, 1.0, 0.0)}, 0});
    data.primitives.push_back({Sphere{Point3(0.0, 2.5, 0.0), 0.5}, 0});
    const PassResult result = run(data, Pass::shadow, 2);
    EXPECT_EQ(centre(result), Color(0.5));
    EXPECT_NE(result.summary.find("no shadow feeler hit the surface it starts from"), std::string::npos) << result.summary;
}

TEST(Passes, FresnelAtNormalIncidenceOnGlassIsFourPercent) {
    // Kr = ((1 - 1.5) / (1 + 1.5))^2 = 0.04 at normal incidence.
    const PassResult glass = run(looking_at(glass_material(1.5)), Pass::fresnel);
    EXPECT_NEAR(centre(glass).x, 0.04, 1e-12);
    // Opaque surfaces have no Fresnel value: the "not applicable" dark blue, not black.
    const PassResult opaque = run(looking_at(diffuse_material(Color(1.0))), Pass::fresnel);
    EXPECT_NE(centre(opaque), Color(0.0));
    EXPECT_GT(centre(opaque).z, centre(opaque).x);
}

TEST(Passes, ReflectanceIsTheMirrorsWeight) {
    const PassResult result = run(looking_at(mirror_material(0.8, Color(1.0, 0.5, 0.25))), Pass::reflectance, 4);
    EXPECT_NEAR(glm::length(centre(result) - Color(0.8, 0.4, 0.2)), 0.0, 1e-12);
    EXPECT_EQ(corner(result), Color(0.0));
}

TEST(Passes, RayDepthReachesTheMaximumBetweenTwoMirrors) {
    // Two parallel mirrors z = -1 and z = 6 facing each other; the camera at z = 5
    // between them: the centre ray bounces until max depth (red), the corner
    // ray too. Without the mirrors, the eye ray alone: the scale's first colour.
    SceneData data = looking_at(mirror_material(0.9), 0.5);
    data.primitives = {{Plane{Point3(0.0, 0.0, -1.0), Vec3(0.0, 0.0, 1.0)}, 0},
                       {Plane{Point3(0.0, 0.0, 6.0), Vec3(0.0, 0.0, -1.0)}, 0}};
    const PassResult bouncing = run(data, Pass::ray_depth, 4);
    EXPECT_EQ(centre(bouncing), Color(1.0, 0.0, 0.0));
    data.primitives.clear();
    const PassResult empty = run(data, Pass::ray_depth, 4);
    EXPECT_EQ(centre(empty), Color(0.05, 0.05, 0.45));
}

TEST(Passes, ObjectIdGivesEachObjectItsOwnColour) {
    SceneData data = looking_at(diffuse_material(Color(1.0)), 0.5);
    data.primitives.push_back({Plane{Point3(0.0, 0.0, -2.0), Vec3(0.0, 0.0, 1.0)}, 0});
    const PassResult result = run(data, Pass::object_id);
    std::set<std::array<double, 3>> colours;
    for (const Color& c : result.render.image.pixels) colours.insert({c.x, c.y, c.z});
    EXPECT_EQ(colours.size(), 2u); // the sphere and the wall behind it
    EXPECT_NE(centre(result), corner(result));
}

TEST(Passes, CostCountsMoreTestsWhereThereIsMoreToTest) {
    // Glass in the middle: the centre pixel's tree has many rays, the corner's
    // one (a single test); the costliest pixel gets the scale's top, red.
    const PassResult result = run(looking_at(glass_material(1.5)), Pass::cost);
    EXPECT_NE(centre(result), corner(result));
    int red = 0;
    for (const Color& c : result.render.image.pixels) red += c == Color(1.0, 0.0, 0.0);
    EXPECT_GT(red, 0);
    EXPECT_NE(result.summary.find("on average"), std::string::npos);
}

TEST(QueryCost, CountsBoxAndShapeTests) {
    // 216 balls in a grid: a ray far off tests only the root's eight boxes; a ray
    // through the grid tests boxes and balls; stopping at the first hit
    // (occlusion) never tests more than finding the closest.
    SceneData data;
    data.materials = {diffuse_material(Color(1.0))};
    for (int i = 0; i < 216; ++i)
        data.primitives.push_back({Sphere{Point3(i % 6 * 3.0, i / 6 % 6 * 3.0, i / 36 * 3.0), 1.0}, 0});
    data.primitives.push_back({Plane{Point3(0.0, -10.0, 0.0), Vec3(0.0, 1.0, 0.0)}, 0});
    const Scene scene(std::move(data));
    const Ray away{Point3(100.0, 100.0, 100.0), Vec3(0.0, 1.0, 0.0)};
    const QueryCost missing = scene.query_cost(away, Interval{}, false);
    EXPECT_EQ(missing.box_tests, 8u);
    EXPECT_EQ(missing.primitive_tests, 1u); // the plane, always tested
    const Ray through{Point3(3.0, 3.0, -20.0), Vec3(0.0, 0.0, 1.0)};
    const QueryCost closest = scene.query_cost(through, Interval{}, false);
    const QueryCost any = scene.query_cost(through, Interval{}, true);
    EXPECT_GT(closest.primitive_tests, 1u);
    EXPECT_GT(closest.box_tests, 8u);
    EXPECT_LE(any.total(), closest.total());
}
