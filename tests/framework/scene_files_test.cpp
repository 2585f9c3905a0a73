// Loading scene files from disk: dialect by extension, file-system errors, and the real SPD scenes.
#include "whitted/generators.hpp"
#include "whitted/render.hpp"
#include "whitted/scene_loader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

using namespace whitted;
namespace fs = std::filesystem;

namespace {

constexpr std::string_view kTinyScene = "v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 hither 1 resolution 8 8\ns 0 0 0 1\n";

/// A fresh directory for this test's files.
fs::path scratch_directory() {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path directory = fs::path(::testing::TempDir()) / (std::string("whitted_") + test->name());
    fs::remove_all(directory);
    fs::create_directories(directory);
    return directory;
}

fs::path write_file(const fs::path& path, std::string_view text) {
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

std::string load_error(const fs::path& path) {
    try {
        load_scene(path);
    } catch (const SceneError& error) {
        return error.what();
    }
    return "no error";
}

template <class T> std::size_t count_shapes(const SceneData& data) {
    return static_cast<std::size_t>(std::count_if(data.primitives.begin(), data.primitives.end(),
                                                  [](const Primitive& p) { return std::holds_alternative<T>(p.shape); }));
}

} // namespace

TEST(SceneFiles, NffAndP3fExtensionsPickTheDialectInAnyCase) {
    const fs::path directory = scratch_directory();
    EXPECT_EQ(load_scene(write_file(directory / "a.nff", kTinyScene)).data.primitives.size(), 1u);
    EXPECT_EQ(load_scene(write_file(directory / "b.NFF", kTinyScene)).data.primitives.size(), 1u);
    EXPECT_EQ(load_scene(write_file(directory / "c.P3f", kTinyScene)).data.primitives.size(), 1u);
    // `b` is NFF only, so the dialect really follows the extension.
    EXPECT_NE(load_error(write_file(directory / "d.p3f", "b 0 0 0")).find("unknown keyword 'b'"), std::string::npos);
}

TEST(SceneFiles, ErrorsNameTheFileAsGiven) {
    const fs::path path = write_file(scratch_directory() / "bad.nff", "v from 0 0 1");
    EXPECT_EQ(load_error(path), path.string() + ":1:13: expected 'at' in the viewpoint 'v', found end of file");
}

TEST(SceneFiles, UnknownExtensionIsAnError) {
    EXPECT_EQ(load_error("scene.xyz"), "scene.xyz: unknown scene format '.xyz' (expected .nff or .p3f)");
}

TEST(SceneFiles, MissingFileIsAnError) {
    const fs::path path = scratch_directory() / "missing.nff";
    EXPECT_EQ(load_error(path).rfind(path.string() + ": cannot open", 0), 0u) << load_error(path);
}

TEST(SceneFiles, DirectoryIsAnError) {
    const fs::path path = scratch_directory() / "folder.nff";
    fs::create_directory(path);
    EXPECT_EQ(load_error(path), path.string() + ": cannot open a directory as a scene file");
}

TEST(SceneFiles, TheCourseFeaturesSceneReadsEveryKeywordAsTheCourseMeansIt) {
    // scenes/course_features.p3f: accel, spp, env, bclr, the thin lens and shutter, a
    // twelfth material number, a mesh with negative indices, comments after numbers.
    const LoadedScene scene = load_scene(fs::path(WHITTED_SOURCE_DIR) / "scenes" / "course_features.p3f");
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
    EXPECT_EQ(scene.data.acceleration, Acceleration::bvh);
    EXPECT_EQ(scene.data.samples_per_pixel, 9);
    EXPECT_TRUE(scene.data.skybox);
    EXPECT_EQ(scene.data.camera.aperture, 0.0);
    EXPECT_EQ(scene.data.camera.focal_ratio, 1.0);
    EXPECT_EQ(scene.data.lights.size(), 2u);
    EXPECT_EQ(scene.data.materials.size(), 4u);
    // a plane, a sphere, a box and the four triangles of the mesh
    EXPECT_EQ(scene.data.primitives.size(), 7u);
}

TEST(SceneFiles, TheCourseDepthOfFieldSceneRendersWithSamplesSkyAndLens) {
    // scenes/course_depth_of_field.p3f: spp 9, the labelled skybox, a lens 10 pixels across.
    LoadedScene loaded = load_scene(fs::path(WHITTED_SOURCE_DIR) / "scenes" / "course_depth_of_field.p3f");
    EXPECT_TRUE(loaded.warnings.empty()) << loaded.warnings.front();
    EXPECT_EQ(loaded.data.samples_per_pixel, 9);
    ASSERT_TRUE(loaded.data.skybox);
    EXPECT_NEAR(loaded.data.camera.aperture, 10.0 * loaded.data.camera.w / 320.0, 1e-12);
    EXPECT_EQ(loaded.data.camera.focal_ratio, 0.9);
    loaded.data.camera = loaded.data.camera.with_resolution(80, 60);
    // Each feature changes the picture: the lens (against a pinhole), the samples
    // (against one ray a pixel); the sky is seen where nothing is hit (not black).
    const auto picture = [&](double aperture, int samples) {
        SceneData data = loaded.data;
        data.camera.aperture = aperture;
        RenderSettings settings;
        settings.stage = stage_number(Stage::depth_of_field);
        settings.samples_per_pixel = samples;
        return render(Scene(std::move(data)), settings, 2).image;
    };
    const Image full = picture(loaded.data.camera.aperture, 9);
    const auto pixels_apart = [&](const Image& other) {
        int count = 0;
        for (std::size_t i = 0; i < full.pixels.size(); ++i)
            if (glm::length(full.pixels[i] - other.pixels[i]) > 0.02) ++count;
        return count;
    };
    EXPECT_GT(pixels_apart(picture(0.0, 9)), 80 * 60 / 20) << "the lens blurs at least 5 % of the pixels";
    EXPECT_GT(pixels_apart(picture(loaded.data.camera.aperture, 0)), 80 * 60 / 20) << "9 samples a pixel smooth the picture";
    const Color sky = full.pixels[0]; // the top-left corner looks into the sky, over the floor's horizon
    EXPECT_GT(sky.r + sky.g + sky.b, 0.1);
}

TEST(SceneFiles, AHundredThousandTriangleMeshWithAccel2RendersThroughEveryStructure) {
    // The course's big-model scene: `whitted generate torus --level 5` writes one P3F mesh of
    // 100,352 triangles with `accel 2`. Its picture through lab 10's BVH (stage 10), the
    // framework's BVH (stage 9) and the uniform grid is the same, bit for bit.
    std::ostringstream text;
    write_torus_p3f(5, text);
    const std::filesystem::path file = std::filesystem::path(WHITTED_BINARY_DIR) / "torus5_test.p3f";
    std::ofstream(file) << text.str();
    LoadedScene loaded = load_scene(file);
    EXPECT_TRUE(loaded.warnings.empty());
    EXPECT_EQ(loaded.data.acceleration, Acceleration::bvh);
    EXPECT_EQ(loaded.data.primitives.size(), 100352u + 1u) << "the mesh's triangles and the floor";
    loaded.data.camera = loaded.data.camera.with_resolution(64, 48);
    const auto picture = [&](Acceleration acceleration, BvhChoice bvh, int stage) {
        SceneData data = loaded.data;
        data.acceleration = acceleration;
        RenderSettings settings;
        settings.stage = stage;
        return render(Scene(std::move(data), nullptr, bvh), settings, 2).image;
    };
    const Image lab = picture(Acceleration::bvh, BvhChoice::lab, stage_number(Stage::bvh));
    const Image framework = picture(Acceleration::bvh, BvhChoice::framework, stage_number(Stage::depth_of_field));
    const Image grid = picture(Acceleration::grid, BvhChoice::framework, stage_number(Stage::depth_of_field));
    ASSERT_EQ(lab.pixels.size(), framework.pixels.size());
    EXPECT_EQ(0, std::memcmp(lab.pixels.data(), framework.pixels.data(), lab.pixels.size() * sizeof(Color)));
    EXPECT_EQ(0, std::memcmp(grid.pixels.data(), framework.pixels.data(), grid.pixels.size() * sizeof(Color)));
    std::filesystem::remove(file);
}

TEST(SceneFiles, EverySpdSceneLoadsWithTheExpectedContent) {
    const fs::path directory = fs::path(WHITTED_SOURCE_DIR) / ".." / "shared" / "scenes" / "spd";
    if (!fs::is_directory(directory)) GTEST_SKIP() << "no SPD scenes at " << directory;
    std::map<std::string, LoadedScene> scenes;
    for (const auto& entry : fs::directory_iterator(directory))
        if (entry.path().extension() == ".nff") scenes.emplace(entry.path().stem().string(), load_scene(entry.path()));
    ASSERT_FALSE(scenes.empty());
    for (const auto& [name, scene] : scenes) {
        EXPECT_GT(scene.data.camera.fovy, 45.0) << name; // the row-centre angle 45 widens slightly
        EXPECT_FALSE(scene.data.lights.empty()) << name;
    }
    if (scenes.count("balls4")) {
        const SceneData& balls = scenes["balls4"].data;
        EXPECT_EQ(count_shapes<Sphere>(balls), 7381u);
        EXPECT_EQ(count_shapes<Triangle>(balls), 2u); // the ground quad
        EXPECT_EQ(balls.lights.size(), 3u);
        EXPECT_NEAR(balls.lights[0].color.x, std::sqrt(3.0) / 6.0, 1e-12); // SPD rule sqrt(N) / (2 N)
    }
    if (scenes.count("tetra6")) {
        EXPECT_EQ(count_shapes<Triangle>(scenes["tetra6"].data), 4096u);
    }
    if (scenes.count("teapot6")) {
        const SceneData& teapot = scenes["teapot6"].data;
        EXPECT_EQ(teapot.vertex_normals.size(), 2256u);
        const auto with_normals = std::count_if(teapot.primitives.begin(), teapot.primitives.end(),
                                                [](const Primitive& p) { return p.vertex_normals >= 0; });
        EXPECT_EQ(with_normals, 2256);
    }
    if (scenes.count("mount6")) {
        const SceneData& mount = scenes["mount6"].data;
        const bool has_glass_sphere = std::any_of(mount.primitives.begin(), mount.primitives.end(), [&](const Primitive& p) {
            return std::holds_alternative<Sphere>(p.shape) && mount.materials[p.material].transmittance > 0.0;
        });
        EXPECT_TRUE(has_glass_sphere);
    }
}
