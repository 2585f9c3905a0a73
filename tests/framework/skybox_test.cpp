// The cube-map skybox (P3F `env`): which face and texel a direction sees, in
// the course's convention (whitted/skybox.hpp), reading the six faces from a
// folder, and the scene seeing it for rays that escape.
#include "whitted/image.hpp"
#include "whitted/scene_loader.hpp"
#include "whitted/skybox.hpp"

#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace whitted;
namespace fs = std::filesystem;

namespace {

/// A 1x1 face of one colour.
Image plain(const Color& color) { return Image(1, 1, color); }

/// Six 1x1 faces, face f coloured (f + 1) / 8 in red: tells the faces apart.
std::array<Image, 6> numbered_faces() {
    std::array<Image, 6> faces;
    for (int f = 0; f < 6; ++f) faces[f] = plain(Color((f + 1) * 32 / 255.0, 0.0, 0.0));
    return faces;
}

/// The face a numbered skybox shows in `direction`.
int face_seen(const Skybox& sky, const Vec3& direction) {
    return static_cast<int>(std::lround(sky.lookup(direction).r * 255.0 / 32.0)) - 1;
}

/// A fresh folder per test, removed afterwards.
class SkyboxFiles : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / (std::string("whitted_skybox_") +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "sky");
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

} // namespace

TEST(Skybox, EachAxisLooksAtTheCentreOfItsFace) {
    // The course's names are those of a viewer facing +z: +x is on its left.
    const struct {
        Vec3 direction;
        CubeFace face;
    } axes[] = {{{1, 0, 0}, CubeFace::left},  {{-1, 0, 0}, CubeFace::right}, {{0, 1, 0}, CubeFace::top},
                {{0, -1, 0}, CubeFace::bottom}, {{0, 0, 1}, CubeFace::front}, {{0, 0, -1}, CubeFace::back}};
    for (const auto& axis : axes) {
        const CubePoint point = cube_point(axis.direction);
        EXPECT_EQ(point.face, axis.face) << axis.direction.x << " " << axis.direction.y << " " << axis.direction.z;
        EXPECT_DOUBLE_EQ(point.s, 0.5);
        EXPECT_DOUBLE_EQ(point.t, 0.5);
    }
}

TEST(Skybox, AwayFromTheAxisTheOtherComponentsPlaceThePoint) {
    // (s, t) = ((sc / major + 1) / 2, (tc / major + 1) / 2) with (sc, tc) from the table in skybox.hpp;
    // components 0.5 and 0.25 of a major 1 give 0.75 / 0.25 and 0.625 / 0.375.
    const struct {
        Vec3 direction;
        CubeFace face;
        double s, t;
    } cases[] = {
        {{1, 0.5, 0.25}, CubeFace::left, 0.625, 0.75},    // s = +z, t = +y
        {{-1, 0.5, 0.25}, CubeFace::right, 0.375, 0.75},  // s = -z, t = +y
        {{0.5, 1, 0.25}, CubeFace::top, 0.25, 0.375},     // s = -x, t = -z
        {{0.5, -1, 0.25}, CubeFace::bottom, 0.25, 0.625}, // s = -x, t = +z
        {{0.5, 0.25, 1}, CubeFace::front, 0.25, 0.625},   // s = -x, t = +y
        {{0.5, 0.25, -1}, CubeFace::back, 0.75, 0.625},   // s = +x, t = +y
    };
    for (const auto& c : cases) {
        const CubePoint point = cube_point(c.direction * 3.0); // the length does not matter
        EXPECT_EQ(point.face, c.face);
        EXPECT_DOUBLE_EQ(point.s, c.s) << static_cast<int>(c.face);
        EXPECT_DOUBLE_EQ(point.t, c.t) << static_cast<int>(c.face);
    }
}

TEST(Skybox, TiesGoToYThenToXOrY) {
    EXPECT_EQ(cube_point({1, 1, 0}).face, CubeFace::top);
    EXPECT_EQ(cube_point({1, -1, 0}).face, CubeFace::bottom);
    EXPECT_EQ(cube_point({1, 0, 1}).face, CubeFace::left);
    EXPECT_EQ(cube_point({0, 1, -1}).face, CubeFace::top);
    EXPECT_EQ(cube_point({1, 1, 1}).face, CubeFace::top);
}

TEST(Skybox, NeighbouringFacesMeetAlongTheirEdges) {
    // Looking along -z (back) and turning right (towards +x), the view leaves
    // back at its right edge (s = 1) and enters left at its left edge (s = 0),
    // at the same height: the faces meet without a seam.
    const CubePoint before = cube_point({1.0, 0.3, -1.0 - 1e-9});
    const CubePoint after = cube_point({1.0, 0.3, -1.0 + 1e-9});
    EXPECT_EQ(before.face, CubeFace::back);
    EXPECT_EQ(after.face, CubeFace::left);
    EXPECT_NEAR(before.s, 1.0, 1e-8);
    EXPECT_NEAR(after.s, 0.0, 1e-8);
    EXPECT_NEAR(before.t, after.t, 1e-8);
    // Looking up from back: back's top edge (t = 1) meets top's t = 1 edge, s mirrored
    // (the course's top pictures are drawn to match along it).
    const CubePoint below = cube_point({0.2, 1.0 - 1e-9, -1.0});
    const CubePoint above = cube_point({0.2, 1.0 + 1e-9, -1.0});
    EXPECT_EQ(below.face, CubeFace::back);
    EXPECT_EQ(above.face, CubeFace::top);
    EXPECT_NEAR(below.t, 1.0, 1e-8);
    EXPECT_NEAR(above.t, 1.0, 1e-8); // top: t = -z / |y| = 1 at z = -1
    EXPECT_NEAR(below.s, 0.6, 1e-8); // back: s = (x + 1) / 2
    EXPECT_NEAR(above.s, 0.4, 1e-8); // top: s = (-x + 1) / 2
}

TEST(Skybox, LookupReadsTheFaceTheDirectionPointsAt) {
    const Skybox sky(numbered_faces());
    EXPECT_EQ(face_seen(sky, {-1, 0, 0}), 0); // right
    EXPECT_EQ(face_seen(sky, {1, 0, 0}), 1);  // left
    EXPECT_EQ(face_seen(sky, {0, 1, 0}), 2);  // top
    EXPECT_EQ(face_seen(sky, {0, -1, 0}), 3); // bottom
    EXPECT_EQ(face_seen(sky, {0, 0, 1}), 4);  // front
    EXPECT_EQ(face_seen(sky, {0, 0, -1}), 5); // back
}

TEST(Skybox, ThePicturesTopRowIsTheFacesTopAndEachTexelCoversItsSquare) {
    // A 3 x 2 back face: top row 10 20 30, bottom row 40 50 60 (red, /255).
    std::array<Image, 6> faces = numbered_faces();
    Image back(3, 2);
    const int red[2][3] = {{10, 20, 30}, {40, 50, 60}};
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x) back.at(x, y) = Color(red[y][x] / 255.0, 0.0, 0.0);
    faces[static_cast<int>(CubeFace::back)] = back;
    const Skybox sky(faces);
    auto red_at = [&](double s, double t) { // back: s = (x + 1) / 2, t = (y + 1) / 2 for z = -1
        return std::lround(sky.lookup({2.0 * s - 1.0, 2.0 * t - 1.0, -1.0}).r * 255.0);
    };
    // The texel column is int(3 s), the row from the bottom int(2 t).
    EXPECT_EQ(red_at(0.01, 0.01), 40);
    EXPECT_EQ(red_at(0.33, 0.49), 40);
    EXPECT_EQ(red_at(0.34, 0.49), 50);
    EXPECT_EQ(red_at(0.67, 0.2), 60);
    EXPECT_EQ(red_at(0.01, 0.5), 10);
    EXPECT_EQ(red_at(0.5, 0.99), 20);
    EXPECT_EQ(red_at(0.99, 0.99), 30);
}

TEST(Skybox, EightBitColoursComeBackExactly) {
    std::array<Image, 6> faces = numbered_faces();
    faces[0] = plain(Color(0.0, 128 / 255.0, 1.0));
    const Color seen = Skybox(faces).lookup({-1, 0, 0});
    EXPECT_EQ(seen, Color(0.0, 128 / 255.0, 1.0));
}

TEST_F(SkyboxFiles, LoadsTheSixFacesFromJpegOrPng) {
    for (int f = 0; f < 6; ++f) {
        const std::string stem(kCubeFaceNames[f]);
        if (f % 2 == 0) {
            write_image(plain(Color(0.0, 0.0, (f + 1) * 40 / 255.0)), dir_ / "sky" / (stem + ".png"));
        } else { // a flat 8x8 JPEG: flat colours survive JPEG compression to within a step or two
            std::vector<unsigned char> rgb(8 * 8 * 3, 0);
            for (std::size_t i = 2; i < rgb.size(); i += 3) rgb[i] = static_cast<unsigned char>((f + 1) * 40);
            // stb hands the file over through a callback (the framework's copy of stb opens no file).
            std::string jpeg;
            const auto append = [](void* to, void* data, int size) {
                static_cast<std::string*>(to)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
            };
            ASSERT_NE(stbi_write_jpg_to_func(append, &jpeg, 8, 8, 3, rgb.data(), 95), 0);
            std::ofstream(dir_ / "sky" / (stem + ".jpg"), std::ios::binary) << jpeg;
        }
    }
    const Skybox sky = Skybox::load(dir_ / "sky");
    const Vec3 looks[] = {{-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int f = 0; f < 6; ++f) EXPECT_NEAR(sky.lookup(looks[f]).b * 255.0, (f + 1) * 40, 2.0) << kCubeFaceNames[f];
}

// The faces are decoded straight to 8-bit values, six at once (Skybox::load): each must hold the very bytes that
// reading its file as a linear image and storing that gives (the Image constructor: v / 255 back to v).
TEST_F(SkyboxFiles, EachFaceHoldsTheBytesOfItsPictureJpegOrPng) {
    std::array<Image, 6> pictures;
    for (int f = 0; f < 6; ++f) {
        const std::string stem(kCubeFaceNames[f]);
        const int width = 5 + f, height = 3 + 2 * f; // a different size each, so that no row or face is swapped unseen
        std::vector<unsigned char> rgb(static_cast<std::size_t>(width * height * 3));
        for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<unsigned char>((i * 37 + f * 11) % 251);
        const fs::path file = dir_ / "sky" / (stem + (f % 2 == 0 ? ".jpg" : ".png"));
        if (f % 2 == 0) {
            std::string jpeg;
            const auto append = [](void* to, void* data, int size) {
                static_cast<std::string*>(to)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
            };
            ASSERT_NE(stbi_write_jpg_to_func(append, &jpeg, width, height, 3, rgb.data(), 90), 0);
            std::ofstream(file, std::ios::binary) << jpeg;
        } else {
            Image image(width, height);
            for (std::size_t i = 0; i < rgb.size(); ++i) image.pixels[i / 3][static_cast<int>(i % 3)] = rgb[i] / 255.0;
            write_image(image, file);
        }
        pictures[f] = read_image(file);
    }
    const Skybox loaded = Skybox::load(dir_ / "sky");
    const Skybox expected(pictures);
    for (int f = 0; f < 6; ++f) {
        EXPECT_EQ(loaded.faces()[f].width, expected.faces()[f].width) << kCubeFaceNames[f];
        EXPECT_EQ(loaded.faces()[f].height, expected.faces()[f].height) << kCubeFaceNames[f];
        EXPECT_EQ(loaded.faces()[f].rgb, expected.faces()[f].rgb) << kCubeFaceNames[f];
    }
}

// Faces decode at once, in any order: the error told is the first bad face's in the order right, left, top, ...
TEST_F(SkyboxFiles, OfTwoBadFacesTheFirstInOrderIsNamed) {
    for (const std::string_view stem : kCubeFaceNames) {
        const fs::path file = dir_ / "sky" / (std::string(stem) + ".png");
        if (stem == "top" || stem == "back") std::ofstream(file) << "not a picture";
        else write_image(plain(Color(0.5)), file);
    }
    for (int run = 0; run < 20; ++run) {
        try {
            Skybox::load(dir_ / "sky");
            FAIL() << "expected an ImageError";
        } catch (const ImageError& error) {
            EXPECT_EQ(std::string(error.what()).rfind((dir_ / "sky" / "top.png").string() + ": ", 0), 0u) << error.what();
        }
    }
}

TEST_F(SkyboxFiles, AMissingFaceIsNamed) {
    for (const std::string_view stem : {"right", "left", "top", "front", "back"})
        write_image(plain(Color(0.5)), dir_ / "sky" / (std::string(stem) + ".png"));
    try {
        Skybox::load(dir_ / "sky");
        FAIL() << "expected an ImageError";
    } catch (const ImageError& error) {
        EXPECT_EQ(std::string(error.what()), (dir_ / "sky" / "bottom.jpg").string() +
                                                 ": no such file (the skybox face 'bottom' must be bottom.jpg, "
                                                 "bottom.jpeg or bottom.png)");
    }
}

TEST_F(SkyboxFiles, TheSceneFileNamesItsFolderAndEscapingRaysSeeIt) {
    std::array<Image, 6> faces = numbered_faces();
    for (int f = 0; f < 6; ++f) write_image(faces[f], dir_ / "sky" / (std::string(kCubeFaceNames[f]) + ".png"));
    const fs::path scene_file = dir_ / "scene.p3f";
    std::ofstream(scene_file) << "v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 hither 1 resolution 4 4\n"
                                 "bclr 0 1 0\nenv sky # relative to this file\n";
    const LoadedScene loaded = load_scene(scene_file);
    EXPECT_TRUE(loaded.warnings.empty());
    const Scene scene(loaded.data);
    ASSERT_TRUE(scene.has_skybox());
    EXPECT_EQ(face_seen(*loaded.data.skybox, {0, 0, -1}), 5);
    EXPECT_EQ(scene.background(Vec3(0, 0, -1)), Color(6 * 32 / 255.0, 0.0, 0.0)); // the sky, not bclr
}

TEST_F(SkyboxFiles, AMissingFolderIsASceneErrorAtTheEnvLine) {
    const fs::path scene_file = dir_ / "scene.p3f";
    std::ofstream(scene_file) << "v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 hither 1 resolution 4 4\nenv nowhere\n";
    try {
        load_scene(scene_file);
        FAIL() << "expected a SceneError";
    } catch (const SceneError& error) {
        const std::string message = error.what();
        EXPECT_EQ(message.rfind(scene_file.string() + ":2:5: cannot load the skybox: ", 0), 0u) << message;
        EXPECT_NE(message.find("nowhere: no such folder"), std::string::npos) << message;
    }
}

TEST(Skybox, TheLabelledSceneShowsEachFaceWhereTheTableSays) {
    // scenes/skybox_labels/ (instructor/scripts/make-skybox-labels.py): one colour per face.
    // Each direction looks at (s, t) = (0.15, 0.68) of its face, left of the arrow, free of ink.
    const LoadedScene loaded = load_scene(fs::path(WHITTED_SOURCE_DIR) / "scenes" / "skybox_labels.p3f");
    ASSERT_TRUE(loaded.data.skybox);
    const struct {
        Vec3 direction;
        int r, g, b;
    } expected[] = {{{-1, 0.36, 0.7}, 200, 60, 60},   {{1, 0.36, -0.7}, 60, 160, 60},  {{0.7, 1, -0.36}, 70, 110, 210},
                    {{0.7, -1, 0.36}, 200, 170, 40}, {{0.7, 0.36, 1}, 160, 70, 190}, {{-0.7, 0.36, -1}, 40, 170, 180}};
    for (const auto& e : expected) {
        const Color seen = loaded.data.skybox->lookup(e.direction) * 255.0;
        EXPECT_EQ(Vec3(std::lround(seen.r), std::lround(seen.g), std::lround(seen.b)), Vec3(e.r, e.g, e.b))
            << e.direction.x << " " << e.direction.y << " " << e.direction.z;
    }
}
