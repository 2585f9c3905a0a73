// The POV-Ray scene writer: the camera it derives, every kind of primitive and
// material it writes, and (when POV-Ray is installed) that POV-Ray renders the
// result and sees the same picture as whitted.
#include "pov_scene.hpp"
#include "test_helpers.hpp"
#include "whitted/image_compare.hpp"
#include "whitted/lab_status.hpp"
#include "whitted/render.hpp"
#include "whitted/scene_loader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

using namespace whitted;
using whitted::bench::PovOptions;
using whitted::bench::pov_camera;
using whitted::bench::write_pov_scene;
using whitted::testing_helpers::near;

namespace fs = std::filesystem;

namespace {

// POV-Ray's eye ray through the centre of image pixel (col, row), rows counted
// from the top, as its perspective camera computes it (TracePixel::CreateCameraRay).
Vec3 pov_eye_direction(const Camera& camera, int col, int row) {
    const auto c = pov_camera(camera);
    const double x0 = (col + 0.5) / camera.res_x - 0.5;
    const double y0 = 0.5 - (row + 0.5) / camera.res_y;
    return glm::normalize(c.direction + x0 * c.right + y0 * c.up);
}

// Our eye ray through the same pixel, written from the slides' formula.
Vec3 whitted_eye_direction(const Camera& camera, int col, int row) {
    const double x = col + 0.5, y = (camera.res_y - 1 - row) + 0.5;
    return glm::normalize(camera.w * (x / camera.res_x - 0.5) * camera.xe +
                          camera.h * (y / camera.res_y - 0.5) * camera.ye - camera.df * camera.ze);
}

Material plain(Color color, double specular = 0.0) {
    Material m;
    m.color = color;
    m.diffuse = 0.8;
    m.specular = specular;
    m.shininess = 20.0;
    return m;
}

Primitive primitive(Shape shape, std::uint32_t material, std::int32_t normals = -1) {
    Primitive p;
    p.shape = shape;
    p.material = material;
    p.vertex_normals = normals;
    return p;
}

// A scene with one of everything the writer knows.
SceneData every_kind() {
    SceneData data;
    data.camera = Camera::create({0, 1, 6}, {0, 1, 0}, {0, 1, 0}, 50.0, 64, 48);
    data.background = Color(0.1, 0.2, 0.3);
    data.ambient = Color(0.25);
    data.lights.push_back(PointLight{{4, 5, 6}, Color(0.9, 0.8, 0.7)});
    data.materials.push_back(plain(Color(0.8, 0.2, 0.2), 0.5));               // 0: a mirror-like red
    Material glass = plain(Color(1.0));
    glass.transmittance = 0.9;
    glass.ior = 1.5;
    data.materials.push_back(glass);                                          // 1: glass
    Material board = plain(Color(1.0));
    board.checker = Checker{Color(1, 1, 0), Color(0, 0, 1), 0.5};
    data.materials.push_back(board);                                          // 2: checkerboard
    data.primitives.push_back(primitive(Sphere{{-1, 1, 0}, 0.5, false}, 0));
    data.primitives.push_back(primitive(Sphere{{1, 1, 0}, 0.5, false}, 1));   // a hollow glass shell...
    data.primitives.push_back(primitive(Sphere{{1, 1, 0}, 0.45, true}, 1));   // ...with its inner wall
    data.primitives.push_back(primitive(Sphere{{0, 3, 0}, 0.3, true}, 0));    // a lone inward sphere
    data.primitives.push_back(primitive(Plane{{0, 0, 0}, {0, 1, 0}}, 2));
    data.primitives.push_back(primitive(Box{{-2, 0, -2}, {-1.5, 0.5, -1.5}}, 0));
    data.primitives.push_back(primitive(Cone{{2, 0, -2}, 0.5, {2, 1, -2}, 0.0, false}, 0));
    data.primitives.push_back(primitive(Cone{{0, 0, -2}, 0.3, {0, 1, -2}, 0.3, true}, 0));
    data.primitives.push_back(primitive(Triangle{{-1, 0, 1}, {1, 0, 1}, {0, 0.1 + 0.2, 1}}, 0));
    data.vertex_normals.push_back(VertexNormals{Vec3(0, 0, 1), Vec3(0, 0.6, 0.8), Vec3(0.6, 0, 0.8)});
    data.primitives.push_back(primitive(Triangle{{-1, 2, -1}, {1, 2, -1}, {0, 2.5, -1}}, 0, 0));
    return data;
}

std::string exported(const SceneData& data, const PovOptions& options = {}) {
    std::ostringstream out;
    write_pov_scene(data, options, out);
    return out.str();
}

std::size_t count(const std::string& text, const std::string& word) {
    std::size_t n = 0;
    for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
    return n;
}

// The povray program on PATH, if there is one.
std::optional<fs::path> find_povray() {
    const char* path = std::getenv("PATH");
    if (!path) return std::nullopt;
    std::stringstream folders(path);
    for (std::string folder; std::getline(folders, folder, ':');) {
        const fs::path candidate = fs::path(folder.empty() ? "." : folder) / "povray";
        std::error_code error;
        if (fs::is_regular_file(candidate, error)) return candidate;
    }
    return std::nullopt;
}

} // namespace

TEST(PovCamera, LooksFromTheEyeAtTheLookAtPointWithTheViewPlaneSize) {
    const Camera camera = Camera::create({1, 2, 3}, {4, 2, -1}, {0, 1, 0}, 40.0, 200, 100);
    const auto c = pov_camera(camera);
    EXPECT_TRUE(near(c.location, camera.eye));
    EXPECT_TRUE(near(c.direction, camera.at - camera.eye));                  // length df: the view plane holds `at`
    EXPECT_NEAR(glm::length(c.up), 2.0 * camera.df * std::tan(radians(20.0)), 1e-12); // full height h
    EXPECT_NEAR(glm::length(c.right), 2.0 * glm::length(c.up), 1e-12);       // full width w = 200/100 h
    EXPECT_NEAR(glm::dot(c.right, c.up), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(c.right, c.direction), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(c.up, c.direction), 0.0, 1e-12);
}

TEST(PovCamera, HorizontalAngleFollowsTheAspectRatio) {
    // Square image: the horizontal angle equals the vertical field of view.
    EXPECT_NEAR(pov_camera(Camera::create({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60.0, 64, 64)).horizontal_angle, 60.0, 1e-9);
    // Twice as wide: tan(angle/2) = 2 tan(fovy/2).
    const double expected = 2.0 * std::atan(2.0 * std::tan(radians(30.0))) * 180.0 / kPi;
    EXPECT_NEAR(pov_camera(Camera::create({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60.0, 128, 64)).horizontal_angle, expected,
                1e-9);
}

TEST(PovCamera, IsNotMirrored) {
    // Seen from +z with y up in a right-handed world, +x is on the right of the picture.
    const Camera camera = Camera::create({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 45.0, 64, 64);
    const auto c = pov_camera(camera);
    EXPECT_GT(c.right.x, 0.0);
    EXPECT_GT(c.up.y, 0.0);
    EXPECT_GT(pov_eye_direction(camera, 63, 32).x, 0.0); // the rightmost column looks towards +x
    EXPECT_GT(pov_eye_direction(camera, 32, 0).y, 0.0);  // the top row looks up
}

TEST(PovCamera, ShootsOurEyeRaysThroughEveryPixelCentre) {
    const Camera camera = Camera::create({2.1, 1.3, 1.7}, {0, 0, 0}, {0, 0, 1}, 45.079, 40, 30);
    for (int row = 0; row < camera.res_y; row += 7)
        for (int col = 0; col < camera.res_x; col += 9)
            EXPECT_TRUE(near(pov_eye_direction(camera, col, row), whitted_eye_direction(camera, col, row), 1e-14))
                << "pixel " << col << ", " << row;
}

TEST(PovScene, WritesTheSettingsCameraBackgroundAndLights) {
    const std::string text = exported(every_kind(), PovOptions{7, true, "every_kind"});
    EXPECT_EQ(text.find("#version 3.7;"), text.find("#version"));
    EXPECT_NE(text.find("max_trace_level 7"), std::string::npos);
    EXPECT_NE(text.find("adc_bailout 0"), std::string::npos);
    EXPECT_NE(text.find("assumed_gamma 1.0"), std::string::npos);
    EXPECT_NE(text.find("ambient_light rgb <0.25, 0.25, 0.25>"), std::string::npos);
    EXPECT_NE(text.find("location <0, 1, 6>"), std::string::npos);
    EXPECT_NE(text.find("direction <0, 0, -6>"), std::string::npos);
    EXPECT_NE(text.find("background { color rgb <0.1, 0.2, 0.3> }"), std::string::npos);
    EXPECT_NE(text.find("light_source { <4, 5, 6> color rgb <0.9, 0.8, 0.7> }"), std::string::npos);
    EXPECT_EQ(text.find("look_at"), std::string::npos); // no handedness fix-ups
}

TEST(PovScene, WritesEveryKindOfPrimitive) {
    const std::string text = exported(every_kind());
    EXPECT_EQ(count(text, "sphere { <-1, 1, 0>, 0.5 texture { M0 }"), 1u);
    EXPECT_EQ(count(text, "difference { sphere { <1, 1, 0>, 0.5 } sphere { <1, 1, 0>, 0.45 }"), 2u); // shell + shadow
    EXPECT_EQ(count(text, "sphere { <0, 3, 0>, 0.3 inverse"), 1u);
    EXPECT_EQ(count(text, "plane { <0, 1, 0>, 0"), 1u);
    EXPECT_EQ(count(text, "box { <-2, 0, -2>, <-1.5, 0.5, -1.5>"), 1u);
    EXPECT_EQ(count(text, "cone { <2, 0, -2>, 0.5, <2, 1, -2>, 0 open"), 1u);
    EXPECT_EQ(count(text, "cylinder { <0, 0, -2>, <0, 1, -2>, 0.3 open inverse"), 1u);
    EXPECT_EQ(count(text, "mesh {"), 1u);
    EXPECT_EQ(count(text, "  triangle { "), 1u);
    EXPECT_EQ(count(text, "  smooth_triangle { <-1, 2, -1>, <0, 0, 1>, <1, 2, -1>, <0, 0.6, 0.8>"), 1u);
}

TEST(PovScene, WritesNumbersThatReadBackExactly) {
    // 0.1 + 0.2 is not 0.3 in binary; %g would round it and move the vertex.
    const std::string text = exported(every_kind());
    EXPECT_NE(text.find("<0, 0.30000000000000004, 1>"), std::string::npos);
}

TEST(PovScene, WritesEveryMaterialTerm) {
    const std::string text = exported(every_kind());
    // The red mirror: ambient and diffuse Kd, Blinn-Phong highlight Ks with roughness 1/Shine, reflection Ks.
    EXPECT_NE(text.find("#declare M0 = texture {\n  pigment { color rgb <0.8, 0.2, 0.2> }"), std::string::npos);
    EXPECT_NE(text.find("ambient 0.8\n    diffuse 0.8\n    specular 0.5 roughness 0.05\n    reflection { rgb <0.5, 0.5, "
                        "0.5> }"),
              std::string::npos);
    // The glass: transmit T, Fresnel reflection, interior with its ior, diffuse divided by the opacity 1 - T.
    EXPECT_NE(text.find("pigment { color rgbt <1, 1, 1, 0.9> }"), std::string::npos);
    EXPECT_NE(text.find("reflection { 0, 1 fresnel on }\n    conserve_energy"), std::string::npos);
    EXPECT_NE(text.find("#declare I1 = interior { ior 1.5 }"), std::string::npos);
    EXPECT_NE(text.find("diffuse 8.000000000000002"), std::string::npos); // 0.8 / (1 - 0.9)
    // The checkerboard.
    EXPECT_NE(text.find("pigment { checker color rgb <1, 1, 0> color rgb <0, 0, 1> scale 0.5 }"), std::string::npos);
}

TEST(PovScene, TransparentObjectsCastOpaqueShadowsThroughAnInvisibleCopy) {
    const SceneData data = every_kind();
    const std::string opaque = exported(data);
    EXPECT_EQ(count(opaque, "no_shadow"), 1u);
    EXPECT_EQ(count(opaque, "no_image no_reflection"), 1u);
    PovOptions filtered;
    filtered.opaque_shadows = false;
    const std::string light_through = exported(data, filtered);
    EXPECT_EQ(count(light_through, "no_shadow"), 0u);
    EXPECT_EQ(count(light_through, "no_image"), 0u);
}

TEST(PovScene, GroupsTrianglesIntoOneMeshPerMaterial) {
    SceneData data = every_kind();
    data.primitives.clear();
    for (int i = 0; i < 10; ++i)
        data.primitives.push_back(primitive(Triangle{{i, 0, 0}, {i + 1.0, 0, 0}, {i, 1, 0}}, static_cast<std::uint32_t>(i % 3 == 0 ? 0 : 2)));
    const std::string text = exported(data);
    EXPECT_EQ(count(text, "mesh {"), 2u);
    EXPECT_EQ(count(text, "  triangle {"), 10u);
}

// POV-Ray renders an exported scene, and its picture passes the image gate
// against whitted's (with POV-Ray writing linear values, as whitted does).
TEST(PovRay, RendersTheExportedClassicSceneAsWhittedDoes) {
    const std::optional<fs::path> povray = find_povray();
    if (!povray) GTEST_SKIP() << "povray is not on PATH";
    LoadedScene loaded = load_scene(fs::path(WHITTED_SOURCE_DIR) / "scenes" / "whitted_1980.p3f");
    loaded.data.camera = loaded.data.camera.with_resolution(32, 32);
    loaded.data.max_depth = 5;
    const fs::path folder = fs::path(WHITTED_BINARY_DIR) / "test-output" / "pov_scene_test";
    fs::create_directories(folder);
    const fs::path pov = folder / "whitted_1980.pov", png = folder / "whitted_1980_povray.png";
    fs::remove(png);
    {
        std::ofstream out(pov);
        write_pov_scene(loaded.data, PovOptions{5, true, "whitted_1980.p3f"}, out);
    }
    std::ostringstream command_text;
    command_text << povray.value() << " +I" << pov << " +O" << png << " +W32 +H32 -A +WT1 -D +FN File_Gamma=1.0 -GA > "
                 << (folder / "povray.log") << " 2>&1";
    const std::string command = command_text.str();
    ASSERT_EQ(std::system(command.c_str()), 0) << command << "\nsee " << (folder / "povray.log");
    ASSERT_TRUE(fs::exists(png));

    if (highest_complete_stage(probe_labs()) < kLabCount) GTEST_SKIP() << "POV-Ray ran; comparing needs every lab";
    RenderSettings settings;
    settings.max_depth = 5;
    const Scene scene(loaded.data);
    const RenderResult ours = render(scene, settings, 1);
    const ImageDifference difference = compare_images(ours.image, read_image(png));
    EXPECT_TRUE(difference.passed) << difference.summary();
}
