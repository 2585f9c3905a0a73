// The scene: what a file describes, built once into a read-only structure that
// answers the two ray queries of a ray tracer.
//
// Why: loaders fill a plain `SceneData`; `Scene` then builds the acceleration
// structure once (Embree's build-then-query). From then on the scene never
// changes, so any number of threads may query it at the same time.
#pragma once

#include "whitted/bvh_tree.hpp"
#include "whitted/camera.hpp"
#include "whitted/material.hpp"
#include "whitted/primitive.hpp"
#include "whitted/skybox.hpp"

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace whitted {

/// The acceleration structure the scene's queries use (P3F `accel`): none tests
/// every primitive; grid walks a uniform grid; bvh walks a bounding volume hierarchy.
enum class Acceleration { none, grid, bvh };

/// Whose hierarchy a scene walks for Acceleration::bvh: the framework's, or
/// the one lab 10 builds and traverses (from the BVH stage on). The reference
/// renderer's leaf kernels always walk the framework's.
enum class BvhChoice { framework, lab };

/// Everything a scene file says, as plain values.
struct SceneData {
    Camera camera;
    Color background{0.0};
    std::shared_ptr<const Skybox> skybox; // P3F `env`: seen instead of the background colour (shared: never changes)
    Color ambient{0.0};           // ambient light intensity (extension keyword `ambient`)
    std::vector<PointLight> lights;       // point lights (`l`)
    std::vector<AreaLight> area_lights;   // lights with a size (`arealight`)
    std::vector<Material> materials;
    std::vector<Primitive> primitives;
    std::vector<VertexNormals> vertex_normals;
    int max_depth = 5;            // deepest ray in the ray tree; the eye ray is depth 1
    int samples_per_pixel = 0;    // P3F `spp`: 0 = Whitted, one ray through each pixel centre; n > 0 = n samples a pixel
    Acceleration acceleration = Acceleration::bvh; // P3F `accel`
};

/// The intersection tests one ray query makes (the `cost` pass).
struct QueryCost {
    std::uint64_t box_tests = 0;       // ray-box tests in the BVH (eight per node visited)
    std::uint64_t primitive_tests = 0; // ray-primitive tests (occlusion stops at the first hit)

    std::uint64_t total() const { return box_tests + primitive_tests; }
};

// The engine behind the queries (whitted/engine/): the BVH, the reference
// renderer's leaf kernels, the queries of a grading's other process.
class WideBvh;
class UniformGrid;
struct LeafKernels;
struct SceneView;
struct RemoteSceneQueries;

/// No primitive: the last shadow feeler was not blocked (Scene::occluded).
inline constexpr std::uint32_t kNoBlocker = 0xffffffffu;

/// What builds lab 10's tree over the boxes of a scene's bounded primitives.
using BvhBuilder = BvhTree (*)(std::span<const Aabb> boxes);

class Scene {
  public:
    /// Takes the data and builds the acceleration structure over its primitives.
    /// With `kernels` (the reference renderer's), leaves are tested with them
    /// instead of the labs' code (see leaf_kernels.hpp). `lab_builder` builds
    /// lab_bvh() instead of lab 10's build_bvh(): tests of the walk alone give it a known tree.
    explicit Scene(SceneData data, const LeafKernels* kernels = nullptr, BvhChoice bvh = BvhChoice::framework,
                   BvhBuilder lab_builder = nullptr);

    const Camera& camera() const { return data_.camera; }
    const Color& background() const { return data_.background; }
    /// True when rays that escape see a skybox rather than the background colour.
    bool has_skybox() const { return data_.skybox != nullptr; }
    /// What a ray that escapes in `direction` sees: the skybox, else the background colour.
    Color background(const Vec3& direction) const {
        return data_.skybox ? data_.skybox->lookup(direction) : data_.background;
    }
    const Color& ambient() const { return data_.ambient; }
    /// The file's point lights. Shading code asks Tracer::lights() instead: it
    /// adds the area lights, as the points that light the current pixel sample.
    std::span<const PointLight> point_lights() const { return data_.lights; }
    /// The file's area lights.
    std::span<const AreaLight> area_lights() const { return data_.area_lights; }
    std::span<const Primitive> primitives() const { return data_.primitives; }
    /// The primitives with a bounding box (all but infinite planes): the first ones of primitives().
    std::span<const Primitive> bounded_primitives() const { return primitives().first(bounded_count_); }
    /// The acceleration structure the file asks for.
    Acceleration acceleration() const { return data_.acceleration; }
    /// Lab 10's hierarchy over bounded_primitives(), built by its build_bvh() (or
    /// the constructor's `lab_builder`) the first time it is asked for (then
    /// kept) and checked: a tree that is not a hierarchy over those primitives
    /// throws std::runtime_error saying why. In a grading worker, the checker's tree.
    const BvhTree& lab_bvh() const;
    int max_depth() const { return data_.max_depth; }

    /// The number of materials; a hit's material index must be below it.
    std::size_t material_count() const { return data_.materials.size(); }
    /// A number that tells this scene apart from every other scene built by this
    /// process (copies share it: a scene never changes once built).
    std::uint64_t serial() const { return serial_; }
    /// The data this scene was built from, primitives in their original order:
    /// `Scene(source_data())` builds the very same scene, BVH order included.
    SceneData source_data() const;

    /// Bytes held by the acceleration structure.
    std::size_t acceleration_bytes() const;

    /// The material of the surface that was hit.
    const Material& material(const Hit& hit) const { return data_.materials[hit.material]; }

    /// The nearest surface along the ray with t inside t_range, if any: lab 1's
    /// closest_hit() over the whole scene, run on each leaf of the BVH.
    std::optional<Hit> closest_hit(const Ray& ray, Interval t_range = {}) const;

    /// True when any surface lies along the ray with t inside t_range.
    bool occluded(const Ray& ray, Interval t_range) const;
    /// occluded(), the same answer, sooner inside a shadow. `blocker` is a first
    /// guess only (the primitive that blocked the feeler before; kNoBlocker:
    /// none), which cannot change the answer: the reference renderer's kernels
    /// test it first and then set it to this ray's blocker, or kNoBlocker; the
    /// labs' queries leave it alone.
    bool occluded(const Ray& ray, Interval t_range, std::uint32_t& blocker) const;

    /// closest_hit() for each of several rays (hits[i] for rays[i] within
    /// t_ranges[i]): the very same answers, found faster when the rays travel
    /// together, as the eye rays of neighbouring pixels do.
    void closest_hits(std::span<const Ray> rays, std::span<const Interval> t_ranges,
                      std::span<std::optional<Hit>> hits) const;

    /// occluded() for each of several rays (blocked[i] for rays[i] within t_ranges[i]).
    void occluded_rays(std::span<const Ray> rays, std::span<const Interval> t_ranges, std::span<bool> blocked) const;
    /// occluded_rays() with a first guess, as occluded(ray, t_range, blocker) takes it;
    /// the kernels update it as they go (to the last blocker found, or kNoBlocker
    /// after an unblocked ray or packet of rays).
    void occluded_rays(std::span<const Ray> rays, std::span<const Interval> t_ranges, std::span<bool> blocked,
                       std::uint32_t& blocker) const;

    /// True when closest_hits() and occluded_rays() walk the BVH with packets
    /// of rays (the reference renderer's leaf kernels); else they ask one ray at a time.
    bool queries_packets() const;

    /// Runs closest_hit (or, when `any_hit`, occluded) through the labs' code
    /// and counts its intersection tests.
    QueryCost query_cost(const Ray& ray, Interval t_range, bool any_hit) const;

  private:
    SceneView kernel_view() const; // what the leaf kernels see of this scene
    std::optional<Hit> closest_hit_with_kernels(const Ray& ray, Interval t_range) const;
    bool walks_lab_bvh() const { return bvh_choice_ == BvhChoice::lab && data_.acceleration == Acceleration::bvh; }
    bool occluded_with_kernels(const Ray& ray, Interval t_range, std::uint32_t& blocker) const;
    void apply_vertex_normals(Hit& hit, const Ray& ray) const;

    SceneData data_;             // primitives: the BVH's ones first, in BVH order, then infinite planes
    std::size_t bounded_count_ = 0;
    std::shared_ptr<const WideBvh> bvh_; // built once, shared by copies (a scene never changes)
    std::shared_ptr<const UniformGrid> grid_; // accel grid only
    struct LabBvh;
    std::shared_ptr<LabBvh> lab_bvh_;    // lab 10's tree, built on first use, shared by copies
    BvhChoice bvh_choice_ = BvhChoice::framework;
    BvhBuilder lab_builder_ = nullptr;   // null: lab 10's build_bvh()
    const LeafKernels* kernels_ = nullptr;
    const RemoteSceneQueries* remote_ = nullptr; // remote_scene_queries(), looked up once
    std::vector<std::uint32_t> source_index_; // for each primitive, its index in the SceneData given
    std::uint64_t serial_ = 0;
};

} // namespace whitted
