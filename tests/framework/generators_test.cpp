// The scene generators: sizes per level, the sphereflake's geometry (children
// touch their parent, siblings stay apart, the flake is SPD's), the tetrahedron's
// outward faces, output the loader accepts, and bad levels refused.
#include "whitted/generators.hpp"
#include "whitted/scene_loader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <vector>

using namespace whitted;

namespace {

std::vector<FlakeSphere> flake(int level) {
    std::vector<FlakeSphere> spheres;
    for_each_flake_sphere(level, [&](const FlakeSphere& s) { spheres.push_back(s); });
    return spheres;
}

// Writes `text` to a fresh temporary file with the given extension and loads it
// (a random number in its name: two test runs at once use different files).
LoadedScene load_text(const std::string& text, const std::string& name) {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("whitted_gen_" + std::to_string(std::random_device{}()) + "_" + name);
    std::ofstream(path) << text;
    LoadedScene scene = load_scene(path);
    std::filesystem::remove(path);
    return scene;
}

std::string message_of(const std::function<void()>& action) {
    try {
        action();
    } catch (const std::invalid_argument& error) {
        return error.what();
    }
    return "no error";
}

} // namespace

TEST(Sphereflake, HasOnePlusNinePlusEtcSpheresPerLevel) {
    const std::size_t expected[] = {1, 10, 91, 820, 7381, 66430, 597871, 5380840};
    for (int level = 0; level <= kMaxSphereflakeLevel; ++level) EXPECT_EQ(sphereflake_sphere_count(level), expected[level]);
    for (int level = 0; level <= 4; ++level) EXPECT_EQ(flake(level).size(), expected[level]) << "level " << level;
}

TEST(Sphereflake, EveryChildTouchesItsParentAndIsAThirdOfItsSize) {
    const std::vector<FlakeSphere> spheres = flake(4);
    EXPECT_DOUBLE_EQ(spheres[0].radius, 0.5);
    for (std::size_t i = 1; i < spheres.size(); ++i) {
        const FlakeSphere& child = spheres[i];
        const FlakeSphere& parent = spheres[child.parent];
        ASSERT_EQ(child.index, i);
        ASSERT_LT(child.parent, i);
        EXPECT_NEAR(glm::length(child.centre - parent.centre), parent.radius + child.radius, 1e-9) << "sphere " << i;
        EXPECT_NEAR(child.radius, parent.radius / 3.0, 1e-15);
        EXPECT_NEAR(glm::length(child.axis), 1.0, 1e-12);
    }
}

TEST(Sphereflake, SiblingsDoNotOverlap) {
    const std::vector<FlakeSphere> spheres = flake(3);
    std::map<std::size_t, std::vector<FlakeSphere>> families;
    for (std::size_t i = 1; i < spheres.size(); ++i) families[spheres[i].parent].push_back(spheres[i]);
    EXPECT_EQ(families.size(), 91u);
    for (const auto& [parent, children] : families) {
        ASSERT_EQ(children.size(), 9u);
        for (std::size_t a = 0; a < children.size(); ++a)
            for (std::size_t b = a + 1; b < children.size(); ++b)
                EXPECT_GT(glm::length(children[a].centre - children[b].centre),
                          children[a].radius + children[b].radius + 1e-9)
                    << "children " << a << " and " << b << " of sphere " << parent;
    }
}

// The classic flake has a child along (1,1,2)/sqrt(6), as in SPD's balls files.
TEST(Sphereflake, AChildSitsWhereSpdPutsItsFirst) {
    const Vec3 expected = Vec3(1, 1, 2) / std::sqrt(6.0) * (0.5 + 0.5 / 3.0);
    double nearest = 1.0;
    for (const FlakeSphere& s : flake(1))
        if (s.index > 0) nearest = std::min(nearest, glm::length(s.centre - expected));
    EXPECT_LT(nearest, 1e-12);
}

// Every sphere of balls4.nff (SPD's size 4, printed with 6 digits) is in the level-4 flake.
TEST(Sphereflake, LevelFourIsSpdBalls4) {
    const std::filesystem::path balls4 = WHITTED_SOURCE_DIR "/../shared/scenes/spd/balls4.nff";
    if (!std::filesystem::exists(balls4)) GTEST_SKIP() << "no " << balls4;
    const LoadedScene spd = load_scene(balls4);
    std::multimap<long, Point3> ours; // keyed by x on a 1e-3 grid
    for (const FlakeSphere& s : flake(4)) ours.emplace(std::lround(s.centre.x * 1e3), s.centre);
    std::size_t spheres = 0;
    for (const Primitive& primitive : spd.data.primitives) {
        const Sphere* sphere = std::get_if<Sphere>(&primitive.shape);
        if (!sphere) continue;
        ++spheres;
        double nearest = 1.0;
        const long key = std::lround(sphere->center.x * 1e3);
        for (auto it = ours.lower_bound(key - 1); it != ours.upper_bound(key + 1); ++it)
            nearest = std::min(nearest, glm::length(it->second - sphere->center));
        EXPECT_LT(nearest, 2e-6) << "balls4 sphere at " << sphere->center.x << " " << sphere->center.y << " "
                                 << sphere->center.z;
    }
    EXPECT_EQ(spheres, 7381u);
}

TEST(Sphereflake, OutputLoadsWithGroundLightsAndCamera) {
    std::ostringstream text;
    write_sphereflake_nff(2, text);
    const LoadedScene scene = load_text(text.str(), "flake2.nff");
    EXPECT_TRUE(scene.warnings.empty());
    std::size_t spheres = 0, triangles = 0;
    for (const Primitive& primitive : scene.data.primitives) {
        spheres += std::holds_alternative<Sphere>(primitive.shape);
        triangles += std::holds_alternative<Triangle>(primitive.shape);
    }
    EXPECT_EQ(spheres, 91u);
    EXPECT_EQ(triangles, 2u); // the ground square
    EXPECT_EQ(scene.data.lights.size(), 3u);
    EXPECT_EQ(scene.data.camera.eye, Point3(2.1, 1.3, 1.7));
    EXPECT_EQ(scene.data.camera.res_x, 512);
}

TEST(Sphereflake, RejectsLevelsOutsideZeroToSeven) {
    EXPECT_EQ(message_of([] { flake(8); }), "sphereflake level must be 0 to 7, found 8");
    EXPECT_EQ(message_of([] { flake(-1); }), "sphereflake level must be 0 to 7, found -1");
    std::ostringstream out;
    EXPECT_EQ(message_of([&] { write_sphereflake_nff(9, out); }), "sphereflake level must be 0 to 7, found 9");
    EXPECT_TRUE(out.str().empty());
}

TEST(Tetra, HasFourToTheLevelTrianglesFacingOutwards) {
    // The outward normals of the level-1 tetrahedron; every small copy has the same four.
    const Vec3 outward[] = {-Vec3(1, 1, 1), -Vec3(-1, -1, 1), -Vec3(-1, 1, -1), -Vec3(1, -1, -1)};
    for (int level = 1; level <= 6; ++level) {
        std::size_t count = 0;
        for_each_tetra_triangle(level, [&](const std::array<Point3, 3>& t) {
            ++count;
            const Vec3 normal = glm::normalize(glm::cross(t[1] - t[0], t[2] - t[0]));
            double best = 0.0;
            for (const Vec3& n : outward) best = std::max(best, glm::dot(normal, glm::normalize(n)));
            EXPECT_NEAR(best, 1.0, 1e-12);
        });
        EXPECT_EQ(count, tetra_triangle_count(level));
    }
    EXPECT_EQ(tetra_triangle_count(6), 4096u);
}

// What a generator writes, read back by the scene loader.
LoadedScene load_generated(void (*write)(int level, std::ostream& out), int level, const std::string& name) {
    std::ostringstream text;
    write(level, text);
    return load_text(text.str(), name);
}

TEST(Tetra, OutputLoadsAndBadLevelsAreRefused) {
    const LoadedScene scene = load_generated(write_tetra_nff, 3, "tetra3.nff");
    EXPECT_EQ(scene.data.primitives.size(), 64u);
    EXPECT_EQ(scene.data.lights.size(), 1u);
    EXPECT_EQ(message_of([] { for_each_tetra_triangle(0, [](const auto&) {}); }), "tetra level must be 1 to 9, found 0");
    EXPECT_EQ(message_of([] { for_each_tetra_triangle(10, [](const auto&) {}); }), "tetra level must be 1 to 9, found 10");
}

// The soup is random but fixed: the same triangles on every machine, in clusters,
// with real area (the loader refuses flat polygons), and as many as the level says.
TEST(Soup, HasTheLevelsCountOfTrianglesWithAreaInsideItsBox) {
    std::size_t count = 0, slivers = 0;
    std::array<Point3, 3> first{};
    for_each_soup_triangle(2, [&](const std::array<Point3, 3>& t) {
        if (count++ == 0) first = t;
        const double area = 0.5 * glm::length(glm::cross(t[1] - t[0], t[2] - t[0]));
        const double longest = std::max({glm::length(t[1] - t[0]), glm::length(t[2] - t[1]), glm::length(t[0] - t[2])});
        EXPECT_GT(area, 1e-9 * longest * longest);
        if (area < 0.05 * longest * longest) ++slivers;
        for (const Point3& p : t) EXPECT_LT(max_abs_component(p), 20.0);
    });
    EXPECT_EQ(count, 4000u);
    EXPECT_EQ(soup_triangle_count(2), 4000u);
    EXPECT_GT(slivers, 400u); // about a fifth are slivers by construction
    // Written again: the very same first triangle (a fixed seed, no library's distributions).
    std::array<Point3, 3> again{};
    bool taken = false;
    for_each_soup_triangle(2, [&](const std::array<Point3, 3>& t) {
        if (!taken) again = t, taken = true;
    });
    EXPECT_EQ(first, again);
}

TEST(Soup, OutputLoadsAndBadLevelsAreRefused) {
    const LoadedScene scene = load_generated(write_soup_nff, 1, "soup1.nff");
    EXPECT_EQ(scene.data.primitives.size(), 1000u);
    EXPECT_EQ(scene.data.lights.size(), 2u);
    EXPECT_EQ(message_of([] { for_each_soup_triangle(7, [](const auto&) {}); }), "soup level must be 1 to 6, found 7");
}

TEST(Generators, AreFoundByName) {
    ASSERT_NE(find_generator("sphereflake"), nullptr);
    EXPECT_EQ(find_generator("sphereflake")->primitive_count(4), 7381u);
    EXPECT_EQ(find_generator("tetra")->default_level, 6);
    EXPECT_EQ(find_generator("teapot"), nullptr);
}
