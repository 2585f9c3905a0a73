// Scene queries answered by another process: a grading checker or worker
// whose lab 1 lives on the other side of the link (instructor/link/).
//
// Why: the scene's two queries go through lab 1's code in a student build; when
// lab 1 runs in the other process of a grading, the scene must ask it there.
// Only those programs link a definition of `remote_scene_queries()` other than
// the framework's, which returns nullptr.
#pragma once

#include "whitted/bvh_tree.hpp"
#include "whitted/hit.hpp"
#include "whitted/shapes.hpp"
#include "whitted/interval.hpp"

#include <optional>
#include <span>

namespace whitted {

class Scene;
class Tracer;

struct RemoteSceneQueries {
    std::optional<Hit> (*closest_hit)(const Scene& scene, const Ray& ray, Interval t_range);
    bool (*occluded)(const Scene& scene, const Ray& ray, Interval t_range);
    /// Lab 10's tree for the scene, from the process that owns the scene (null: it is built here).
    BvhTree (*lab_bvh)(const Scene& scene);
    /// The framework's own shapes (boxes, cones) tested by the other process, so that
    /// their slab test is never in the graded lab's hands (null: they are tested here).
    std::optional<Hit> (*intersect_shape)(const Ray& ray, const Shape& shape, Interval t_range);
    /// Tracer::trace_pixels() whole, run by the other process where it holds every lab (a grading's
    /// integration tests): one crossing for a block of pixels instead of several a pixel (null: traced here).
    void (*trace_pixels)(const Tracer& tracer, std::span<const Vec2> positions, std::span<Color> colors);
};

/// The queries of the other process, or nullptr in every program but a grading checker or worker.
const RemoteSceneQueries* remote_scene_queries();

} // namespace whitted
