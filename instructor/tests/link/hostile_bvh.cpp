// Lab 10 written by a student who asks the checker for the answers: the walks
// call lab 1's closest_hit() over every primitive, or the scene's own queries,
// and box_entry() hands the box to intersect() as a box primitive, whose slab
// test is the framework's (WHITTED_HOSTILE says which). The grader's link
// refuses the first two before the lab runs (instructor/grader/lab_fences.hpp);
// this worker is linked without that fence, to show the checker refuses the
// calls too: every such test fails and the checker says why.
#include "whitted/labs.hpp"

#include <cstdlib>
#include <string>

namespace whitted {
namespace {

bool mode_is(const char* name) {
    const char* mode = std::getenv("WHITTED_HOSTILE");
    return mode && std::string(mode) == name;
}

bool through_the_scene() { return mode_is("walk_by_scene"); }

} // namespace

std::optional<double> box_entry(const Ray& ray, const Vec3&, const Aabb& box, Interval t_range) {
    if (!mode_is("box_by_intersect")) not_implemented();
    const std::optional<Hit> hit = intersect(ray, Primitive{Box{box.min, box.max}, 0}, t_range);
    if (hit) return hit->t;
    return std::nullopt;
}

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
