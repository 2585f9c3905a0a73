// Lab 10's quality bar on the SPD scenes (../shared/scenes/spd, skipped where
// they are not): the reference lab 10's tree, walked by the framework's
// counting walk, costs a ray at most 1.5 times the box and primitive tests of
// the framework's own SAH tree, the bar the lab's tests set on generated scenes.
// The figures are printed for the instructors' notes.
#include "whitted/bvh_tree.hpp"
#include "whitted/labs.hpp"
#include "whitted/scene_loader.hpp"
#include "tree_yardsticks.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>

using namespace whitted;

namespace {

struct Tally {
    TreeQueryCost cost;
    std::uint64_t rays = 0;
    double per_ray() const { return static_cast<double>(cost.nodes_visited + cost.primitive_tests) / static_cast<double>(rays); }
};

} // namespace

TEST(Lab10Spd, TheReferenceTreeIsWithinTheLabsBarOnEverySpdScene) {
    const std::filesystem::path folder = std::filesystem::path(WHITTED_SOURCE_DIR) / ".." / "shared" / "scenes" / "spd";
    if (!std::filesystem::is_directory(folder)) GTEST_SKIP() << "no SPD scenes at " << folder;
    for (const char* name : {"balls4.nff", "mount6.nff", "teapot6.nff", "tetra6.nff"}) {
        const std::filesystem::path file = folder / name;
        if (!std::filesystem::exists(file)) continue;
        LoadedScene loaded = load_scene(file);
        loaded.data.camera = loaded.data.camera.with_resolution(96, 72);
        const Scene scene(loaded.data);
        const std::span<const Primitive> primitives = scene.bounded_primitives();
        const std::vector<Aabb> boxes = primitive_boxes(primitives);
        const auto start = std::chrono::steady_clock::now();
        const BvhTree lab = build_bvh(boxes);
        const double build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        ASSERT_EQ(bvh_tree_error(lab, boxes), "") << name;
        const BvhTree framework = framework_bvh_tree(boxes);
        Tally yours, reference;
        const Camera& camera = scene.camera();
        for (int y = 0; y < camera.res_y; ++y)
            for (int x = 0; x < camera.res_x; ++x) {
                const Ray eye = primary_ray(camera, x + 0.5, y + 0.5);
                std::vector<std::pair<Ray, Interval>> queries{{eye, Interval{}}};
                if (const std::optional<Hit> hit = scene.closest_hit(eye))
                    for (const PointLight& light : scene.point_lights()) { // the shadow feelers, as closest-hit walks
                        const Vec3 to_light = light.position - hit->point;
                        const double distance = glm::length(to_light);
                        queries.push_back({spawn_ray(*hit, to_light / distance), Interval{0.0, distance}});
                    }
                for (const auto& [ray, range] : queries) {
                    yours.cost += closest_hit_cost(lab, primitives, ray, range), ++yours.rays;
                    reference.cost += closest_hit_cost(framework, primitives, ray, range), ++reference.rays;
                }
            }
        std::printf("%-12s %7zu primitives: reference lab 10 %.1f tests a ray (%.1f nodes, %.1f primitives), framework SAH "
                    "%.1f, ratio %.2f; built in %.1f ms\n",
                    name, primitives.size(), yours.per_ray(), double(yours.cost.nodes_visited) / yours.rays,
                    double(yours.cost.primitive_tests) / yours.rays, reference.per_ray(), yours.per_ray() / reference.per_ray(),
                    build_ms);
        EXPECT_LE(yours.per_ray(), 1.5 * reference.per_ray()) << name;
    }
}
