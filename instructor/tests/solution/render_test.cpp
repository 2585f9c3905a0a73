// Whole-image properties of the renderer: determinism, stages, failures.
#include "whitted/image_compare.hpp"
#include "whitted/render.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>

using namespace whitted;

namespace {

// A small scene with every effect: a mirror sphere, a glass sphere, a floor, two lights.
SceneData effects_scene(int size) {
    SceneData data;
    data.camera = Camera::create(Point3(0.0, 1.5, 6.0), Point3(0.0, 1.0, 0.0), Vec3(0.0, 1.0, 0.0), 45.0, size, size);
    data.background = Color(0.2, 0.3, 0.5);
    data.ambient = Color(0.1);
    data.lights = {PointLight{Point3(5.0, 8.0, 5.0), Color(0.8)}, PointLight{Point3(-6.0, 4.0, 2.0), Color(0.3, 0.3, 0.6)}};
    Material floor;
    floor.checker = Checker{Color(0.9), Color(0.2), 1.0};
    Material mirror;
    mirror.color = Color(0.8, 0.3, 0.2);
    mirror.diffuse = 0.5;
    mirror.specular = 0.5;
    mirror.shininess = 50.0;
    Material glass;
    glass.diffuse = 0.0;
    glass.specular = 0.1;
    glass.shininess = 200.0;
    glass.transmittance = 0.9;
    glass.ior = 1.5;
    data.materials = {floor, mirror, glass};
    data.primitives.push_back({Plane{Point3(0.0), Vec3(0.0, 1.0, 0.0)}, 0});
    data.primitives.push_back({Sphere{Point3(-1.1, 1.0, 0.0), 1.0}, 1});
    data.primitives.push_back({Sphere{Point3(1.1, 1.0, 0.5), 0.9}, 2});
    return data;
}

// Adds a hollow glass shell (the classic scene's) in front of the spheres:
// every hit on it spawns a reflected and a refracted ray.
SceneData with_hollow_shell(SceneData data) {
    data.primitives.push_back({Sphere{Point3(0.0, 1.0, 2.0), 0.7}, 2});
    data.primitives.push_back({Sphere{Point3(0.0, 1.0, 2.0), 0.65, true}, 2});
    return data;
}

bool bit_identical(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Color)) == 0;
}

} // namespace

TEST(Render, ImageIsBitIdenticalForAnyThreadCount) {
    const Scene scene(effects_scene(61)); // not a multiple of the tile size
    const RenderSettings settings;
    const Image one = render(scene, settings, 1).image;
    for (int threads : {2, 3, 8}) EXPECT_TRUE(bit_identical(one, render(scene, settings, threads).image)) << threads;
}

TEST(Render, EveryStageProducesFiniteColoursAndStagesDiffer) {
    const Scene scene(effects_scene(32));
    Image previous;
    for (int stage = 1; stage <= 6; ++stage) {
        RenderSettings settings;
        settings.stage = stage;
        const Image image = render(scene, settings, 2).image;
        EXPECT_EQ(count_non_finite(image), 0u) << "stage " << stage;
        if (stage > 1) {
            EXPECT_FALSE(bit_identical(previous, image)) << "stage " << stage << " adds nothing";
        }
        previous = image;
    }
}

TEST(Render, CountsRaysOfEveryKind) {
    const Scene scene(effects_scene(32));
    const RenderResult result = render(scene, RenderSettings{}, 2);
    EXPECT_EQ(result.stats.eye, 32u * 32u);
    EXPECT_GT(result.stats.shadow, 0u);
    EXPECT_GT(result.stats.reflected, 0u);
    EXPECT_GT(result.stats.refracted, 0u);
}

TEST(Render, StageOneShowsTheFlatDiffuseColour) {
    // The centre pixel looks straight at `at`; put a red sphere there.
    SceneData data;
    data.camera = Camera::create(Point3(0.0, 0.0, 5.0), Point3(0.0), Vec3(0.0, 1.0, 0.0), 30.0, 9, 9);
    Material red;
    red.color = Color(1.0, 0.0, 0.0);
    data.materials = {red};
    data.primitives.push_back({Sphere{Point3(0.0), 0.5}, 0});
    data.background = Color(0.0, 0.0, 1.0);
    RenderSettings settings;
    settings.stage = 1;
    const Image image = render(Scene(std::move(data)), settings, 1).image;
    EXPECT_EQ(image.at(4, 4), Color(1.0, 0.0, 0.0));
    EXPECT_EQ(image.at(0, 0), Color(0.0, 0.0, 1.0));
}

TEST(Render, AnExceptionInAnyThreadReachesTheCaller) {
    // A callback that throws stands for an unfinished lab throwing inside a worker thread.
    const Scene scene(effects_scene(64));
    EXPECT_THROW(render(scene, RenderSettings{}, 2, [](double) { throw std::runtime_error("stop"); }),
                 std::runtime_error);
}

TEST(Render, AdaptiveDepthControlSavesRaysWithoutChangingThePicture) {
    // A hollow glass shell at depth 12 spawns two rays at every hit; pruning rays whose
    // accumulated weight is below 1/1024 must cut the ray count and stay within the image gate.
    const Scene scene(with_hollow_shell(effects_scene(48)));
    RenderSettings every_ray;
    every_ray.max_depth = 12;
    every_ray.min_weight = 0.0;
    RenderSettings pruned = every_ray;
    pruned.min_weight = 1.0 / 1024.0;
    const RenderResult full = render(scene, every_ray, 2);
    const RenderResult fast = render(scene, pruned, 2);
    EXPECT_LT(fast.stats.total() * 2, full.stats.total());
    const ImageDifference difference = compare_images(full.image, fast.image);
    EXPECT_TRUE(difference.passed) << difference.summary();
}

TEST(Render, TheRayBudgetStopsRayTreesThatWouldGrowWithoutBound) {
    // A hollow glass shell at depth 100 with adaptive depth control off doubles its
    // ray tree at every hit: about 2^100 rays. The per-pixel budget must end it.
    const Scene scene(with_hollow_shell(effects_scene(16)));
    RenderSettings settings;
    settings.max_depth = 100;
    settings.min_weight = 0.0;
    const RenderResult result = render(scene, settings, 2);
    EXPECT_GT(result.stats.pixels_cut_short, 0u);
    EXPECT_LE(result.stats.total(), 16u * 16u * (settings.max_rays_per_pixel + 1));
    EXPECT_EQ(count_non_finite(result.image), 0u);
}
