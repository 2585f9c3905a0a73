// Lab 10 written by a student who asks the checker for the walk's answer: the
// walks call lab 1's closest_hit() over every primitive, or the scene's own
// queries (WHITTED_HOSTILE says which). The grader's link refuses such a lab
// before it runs (instructor/grader/lab_fences.hpp); this worker is linked
// without that fence, to show the checker refuses the calls too: every walk
// test fails and the checker says why.
#include "whitted/labs.hpp"

#include <cstdlib>
#include <string>

namespace whitted {
namespace {

bool through_the_scene() {
    const char* mode = std::getenv("WHITTED_HOSTILE");
    return mode && std::string(mode) == "walk_by_scene";
}

} // namespace

std::optional<double> box_entry(const Ray&, const Vec3&, const Aabb&, Interval) { not_implemented(); }

BvhTree build_bvh(std::span<const Aabb>) { not_implemented(); }

std::optional<Hit> bvh_closest_hit(const Scene& scene, const Ray& ray, Interval t_range) {
    if (through_the_scene()) return scene.closest_hit(ray, t_range);
    return closest_hit(ray, scene.bounded_primitives(), t_range);
}

bool bvh_occluded(const Scene& scene, const Ray& ray, Interval t_range) {
    if (through_the_scene()) return scene.occluded(ray, t_range);
    return closest_hit(ray, scene.bounded_primitives(), t_range).has_value();
}

} // namespace whitted
