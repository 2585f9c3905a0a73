// Hidden tests of lab 4: other directions, other mirrors, other depths than the public tests.
#include "whitted/labs.hpp"

#include "image_check.hpp"
#include "lab_helpers.hpp"
#include "test_helpers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace whitted;
using namespace whitted::testing_helpers;

TEST(HiddenMirrorDirection, ReflectsOffAFloorFacingUpAlongY) {
    // n = (0, 1, 0), wo = (0.6, 0.8, 0): wo . n = 0.8, r = 1.6 (0, 1, 0) - wo = (-0.6, 0.8, 0).
    EXPECT_TRUE(near(mirror_direction(Vec3(0.6, 0.8, 0.0), Vec3(0.0, 1.0, 0.0)), Vec3(-0.6, 0.8, 0.0), 1e-15));
}

TEST(HiddenMirrorDirection, ReflectsOffACeilingFacingDown) {
    // n = (0, 0, -1), wo = (0, 0.6, -0.8): wo . n = 0.8, r = 1.6 (0, 0, -1) - wo = (0, -0.6, -0.8).
    EXPECT_TRUE(near(mirror_direction(Vec3(0.0, 0.6, -0.8), -kUp), Vec3(0.0, -0.6, -0.8), 1e-15));
}

TEST(HiddenMirrorDirection, At70DegreesAndAzimuth200KeepsTheHeightAndTurnsTheTangentAround) {
    // r = (-wo.x, -wo.y, wo.z) for n = +z, whatever the azimuth.
    const Vec3 wo = direction_at(70.0, 200.0);
    EXPECT_TRUE(near(mirror_direction(wo, kUp), Vec3(-wo.x, -wo.y, wo.z), 1e-15));
}

TEST(HiddenMirrorDirection, DoesNotDependOnWhichWayTheNormalPoints) {
    // 2 (wo . n) n is even in n: reflecting about -n gives the same r.
    const Vec3 n = glm::normalize(Vec3(2.0, -1.0, 2.0));
    const Vec3 wo = glm::normalize(Vec3(1.0, 0.5, 0.3));
    EXPECT_TRUE(near(mirror_direction(wo, n), mirror_direction(wo, -n), 1e-15));
    EXPECT_TRUE(near(mirror_direction(wo, n), 2.0 * glm::dot(wo, n) * n - wo, 1e-15));
}

TEST(HiddenReflection, ColouredMirrorFiltersEachChannel) {
    // Ks = 0.3, specular colour (0.2, 0.9, 0.5), green background: 0.3 x 0.9 = 0.27 green only.
    SceneData data;
    data.background = Color(0.0, 1.0, 0.0);
    data.materials = {mirror_material(0.3, Color(0.2, 0.9, 0.5))};
    data.primitives.push_back({Plane{Point3(0.0, -2.0, 0.0), Vec3(0.0, 1.0, 0.0)}, 0});
    const TracerRig rig(std::move(data), 4, 5);
    const Vec3 wo = glm::normalize(Vec3(0.3, 0.9, -0.2));
    const Color c = reflection(rig.tracer, hit_seen_from(Point3(1.0, -2.0, 3.0), Vec3(0.0, 1.0, 0.0), wo), wo, 2);
    EXPECT_TRUE(near(c, Color(0.0, 0.27, 0.0), 1e-12));
}

TEST(HiddenReflection, AMirrorBallShowsWhatIsBehindTheViewer) {
    // A mirror ball (r = 1, Ks = 0.7) at the origin, eye at z = 5, a yellow lamp wall at z = 10.
    // Through the centre the ray comes straight back: 0.7 yellow. At impact parameter 0.5
    // it hits (0.5, 0, sqrt(0.75)) at 30 degrees and leaves deflected by 60 degrees,
    // along (sin 60, 0, cos 60), towards a red ball 4 units from the hit point.
    SceneData data;
    data.ambient = Color(1.0);
    data.materials = {mirror_material(0.7), diffuse_material(Color(1.0, 1.0, 0.0)), diffuse_material(Color(1.0, 0.0, 0.0))};
    data.primitives.push_back({Sphere{Point3(0.0), 1.0}, 0});
    data.primitives.push_back({Plane{Point3(0.0, 0.0, 10.0), -kUp}, 1});
    data.primitives.push_back({Sphere{Point3(0.5, 0.0, std::sqrt(0.75)) + 4.0 * direction_at(60.0), 0.5}, 2});
    const Scene scene(std::move(data));
    EXPECT_TRUE(near(trace_one(scene, Ray{Point3(0.0, 0.0, 5.0), -kUp}, 4), Color(0.7, 0.7, 0.0), 1e-12));
    EXPECT_TRUE(near(trace_one(scene, Ray{Point3(0.5, 0.0, 5.0), -kUp}, 4), Color(0.7, 0.0, 0.0), 1e-12));
}

TEST(HiddenReflection, ACornerMirrorSendsTheRayBackAfterTwoReflections) {
    // Mirrors x = 0 and y = 0 (Ks = 0.5, Kd = 0) form a corner. The eye ray from (3, 2, 0)
    // along (-1, -0.5, 0) reflects at (0, 0.5, 0) to (1, -0.5, 0), then at (1, 0, 0) to
    // (1, 0.5, 0) and leaves: two reflected rays, 0.5^2 of the white background.
    // With max_depth 2 the second mirror is the last level: one reflected ray, black.
    for (int max_depth : {2, 3, 7}) {
        SCOPED_TRACE(::testing::Message() << "max_depth " << max_depth);
        SceneData data;
        data.background = Color(1.0);
        data.materials = {mirror_material(0.5)};
        data.primitives.push_back({Plane{Point3(0.0), Vec3(1.0, 0.0, 0.0)}, 0});
        data.primitives.push_back({Plane{Point3(0.0), Vec3(0.0, 1.0, 0.0)}, 0});
        TracerRig rig(std::move(data), 4, max_depth);
        const Color c = rig.trace(make_ray(Point3(3.0, 2.0, 0.0), Vec3(-1.0, -0.5, 0.0)));
        EXPECT_EQ(rig.stats.reflected, max_depth == 2 ? 1u : 2u);
        EXPECT_TRUE(near(c, Color(max_depth == 2 ? 0.0 : 0.25), 1e-12));
    }
}

TEST(HiddenReflection, ALightGuideOfTwoMirrorStripsStopsAtMaxDepth) {
    // Mirror strips y = 0 and y = 1 for 0 < x < 10 (Ks = 0.9, Kd = 0, min_weight 0). The
    // eye ray from (0.5, 0.5, 0) along (1, -2, 0) hits them at x = 0.75, 1.25, ..., 9.75:
    // 19 hits, then it leaves at the end (white background). max_depth D allows
    // min(D - 1, 19) reflected rays; the background is reached only for D >= 20, at 0.9^19.
    for (int max_depth : {5, 19, 20, 30}) {
        SCOPED_TRACE(::testing::Message() << "max_depth " << max_depth);
        SceneData data;
        data.background = Color(1.0);
        data.materials = {mirror_material(0.9)};
        data.primitives.push_back({Box{Point3(0.0, -1.0, -1.0), Point3(10.0, 0.0, 1.0)}, 0});
        data.primitives.push_back({Box{Point3(0.0, 1.0, -1.0), Point3(10.0, 2.0, 1.0)}, 0});
        TracerRig rig(std::move(data), 4, max_depth, 0.0);
        const Color c = rig.trace(make_ray(Point3(0.5, 0.5, 0.0), Vec3(1.0, -2.0, 0.0)));
        EXPECT_EQ(rig.stats.reflected, static_cast<std::uint64_t>(std::min(max_depth - 1, 19)));
        EXPECT_TRUE(near(c, Color(max_depth >= 20 ? std::pow(0.9, 19) : 0.0), 1e-12));
    }
}

TEST(HiddenLab4Image, HiddenSceneMatchesTheReference) {
    expect_matches_reference(ImageCheck{"instructor/tests/hidden/scenes/04_reflection_hidden.p3f",
                                        "instructor/tests/hidden/04_reflection/04_reflection_hidden.png", 4});
}
