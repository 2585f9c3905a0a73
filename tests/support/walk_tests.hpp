// Lab 10's walks measured: the primitives your bvh_closest_hit() and
// bvh_occluded() test, against the framework's walk of the very same tree.
//
// Why: a walk that finds the right hit by testing every primitive is right and
// useless. The count is kept below your code (whitted/primitive_test_count.hpp),
// and the tree is the framework's (scene_with_known_tree), so that neither your
// tree nor your counting decides what your walk is measured against.
#pragma once

#include "whitted/labs.hpp"
#include "whitted/primitive_test_count.hpp"
#include "tree_yardsticks.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>

namespace whitted::testing_helpers {

/// The scene with the framework's tree as scene.lab_bvh(), whatever your build_bvh() makes.
inline Scene scene_with_known_tree(SceneData data) {
    return Scene(std::move(data), nullptr, BvhChoice::lab, framework_bvh_tree);
}

/// The primitive tests of your walks and of the framework's walks of the same tree, for the same rays.
struct WalkTests {
    std::uint64_t yours = 0;
    std::uint64_t framework = 0;
};

/// bvh_closest_hit(), adding its tests and the framework's walk's to `tests`.
inline std::optional<Hit> counted_closest_hit(const Scene& scene, const Ray& ray, Interval range, WalkTests& tests) {
    std::optional<Hit> hit;
    {
        const PrimitiveTestCount count;
        hit = bvh_closest_hit(scene, ray, range);
        tests.yours += count.tests();
    }
    tests.framework += closest_hit_cost(scene.lab_bvh(), scene.bounded_primitives(), ray, range).primitive_tests;
    return hit;
}

/// bvh_occluded(), adding its tests and the framework's walk's to `tests`.
inline bool counted_occluded(const Scene& scene, const Ray& ray, Interval range, WalkTests& tests) {
    bool blocked = false;
    {
        const PrimitiveTestCount count;
        blocked = bvh_occluded(scene, ray, range);
        tests.yours += count.tests();
    }
    tests.framework += occluded_cost(scene.lab_bvh(), scene.bounded_primitives(), ray, range).primitive_tests;
    return blocked;
}

/// Your walks may test at most 1.5 times the primitives the framework's walk
/// tests. The framework skips a node whose box the ray misses within the range,
/// visits the nearer child first and shrinks the range to each hit, so that the
/// farther child's box often starts beyond it. A walk that tests every leaf
/// tests every primitive (in these tests 40 to 180 times more).
inline void expect_about_as_few_tests(const WalkTests& tests, const char* walk) {
    if (static_cast<double>(tests.yours) > 1.5 * static_cast<double>(tests.framework))
        ADD_FAILURE() << "your " << walk << " tested " << tests.yours << " primitives for these rays, where the framework's walk of "
        << "the same tree tests " << tests.framework << ": skip a node whose box the ray misses within t_range, "
        << "visit the nearer child first and shrink t_range.max to each hit";
}

} // namespace whitted::testing_helpers
