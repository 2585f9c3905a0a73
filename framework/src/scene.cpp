#include "whitted/scene.hpp"

#include "whitted/engine/leaf_kernels.hpp"
#include "whitted/engine/remote_queries.hpp"
#include "whitted/engine/uniform_grid.hpp"
#include "whitted/engine/vertex_normals.hpp"
#include "whitted/engine/wide_bvh.hpp"
#include "whitted/labs.hpp"

#include "lab_call.hpp"
#include "permute.hpp"
#include "prefault.hpp"

#include <atomic>
#include <cmath>
#include <future>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace whitted {
namespace {

// Scenes with at least this many bounded primitives set up on two threads.
constexpr std::size_t kParallelSetupCount = 1u << 16;

std::uint64_t next_serial() {
    // Only an identity for scenes: the one counter the framework shares between threads.
    static std::atomic<std::uint64_t> counter{0};
    return ++counter;
}

// What testing a ray against the shape costs the reference renderer, in node tests
// (measured leads of issue 17): the SAH weighs leaves with it, so cheap spheres
// share leaves and costly cones get boxes of their own.
float test_cost(const Shape& shape) {
    if (std::holds_alternative<Sphere>(shape)) return 1.0f;
    if (std::holds_alternative<Triangle>(shape)) return 1.5f;
    if (std::holds_alternative<Box>(shape)) return 2.0f;
    return 3.0f; // a cone (planes have no box)
}

} // namespace

// See whitted/engine/vertex_normals.hpp for what is kept and why.
void apply_vertex_normals(Hit& hit, const Ray& ray, const VertexNormals& normals) {
    const double b1 = hit.uv.x, b2 = hit.uv.y, b0 = 1.0 - b1 - b2;
    Vec3 n = b0 * normals[0] + b1 * normals[1] + b2 * normals[2];
    const double length = glm::length(n);
    if (!(length > 0.0)) return; // opposite normals cancel: keep the geometric one
    n /= length;
    // The shading normal faces the same side as the geometric one.
    if (glm::dot(n, hit.geometric_normal) < 0.0) n = -n;
    const Vec3 wo = -ray.direction;
    const double cos_theta = glm::dot(wo, n);
    const Vec3 mirrored = 2.0 * cos_theta * n - wo;
    if (cos_theta <= 0.0 || glm::dot(mirrored, hit.geometric_normal) <= 0.0) return;
    hit.normal = n;
}

[[gnu::weak]] const RemoteSceneQueries* remote_scene_queries() { return nullptr; }

// Lab 10's tree: built once, by whichever thread asks first.
struct Scene::LabBvh {
    std::once_flag built;
    BvhTree tree;
};

Scene::Scene(SceneData data, const LeafKernels* kernels, BvhChoice bvh, BvhBuilder lab_builder)
    : data_(std::move(data)), lab_bvh_(std::make_shared<LabBvh>()), bvh_choice_(bvh), lab_builder_(lab_builder),
      kernels_(kernels),
      remote_(remote_scene_queries()), serial_(next_serial()) {
    // Bounded primitives go into the BVH, in its order; infinite planes follow.
    const std::size_t count = data_.primitives.size();
    std::vector<Aabb> boxes;
    std::vector<float> test_costs;
    std::vector<std::uint32_t> bounded_index, unbounded_index;
    boxes.reserve(count);
    std::future<void> prefaulted = detail::prefault_behind(boxes.data(), count * sizeof(Aabb));
    test_costs.reserve(count);
    bounded_index.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        if (auto box = bounds(data_.primitives[i].shape)) {
            boxes.push_back(*box);
            test_costs.push_back(test_cost(data_.primitives[i].shape));
            bounded_index.push_back(static_cast<std::uint32_t>(i));
        } else {
            unbounded_index.push_back(static_cast<std::uint32_t>(i));
        }
    }
    bounded_count_ = boxes.size();
    if (prefaulted.valid()) prefaulted.get(); // before the boxes move on (and are freed with the builder)
    const Bvh binary(std::move(boxes), std::move(test_costs));
    // The eight-wide tree is collapsed while the primitives move into the binary tree's
    // order: neither reads what the other writes, and a big scene has two halves of its
    // set-up time. (A small one does both on this thread: a thread costs more.)
    auto collapse = [&binary] { return std::make_shared<const WideBvh>(binary); };
    std::future<std::shared_ptr<const WideBvh>> collapsed;
    // A grading worker asks the checker every query (remote_queries.hpp): it keeps no
    // structure of its own, so the graded lab's code finds no framework walk to borrow.
    const bool queries_here = !(remote_ && remote_->lab_bvh);
    if (queries_here && bounded_count_ >= kParallelSetupCount) {
        try {
            collapsed = std::async(std::launch::async, collapse);
        } catch (const std::system_error&) {
            // no thread to be had (a process limit): collapse below, after the move
        }
    }
    source_index_.reserve(count);
    for (std::uint32_t index : binary.order()) source_index_.push_back(bounded_index[index]);
    source_index_.insert(source_index_.end(), unbounded_index.begin(), unbounded_index.end());
    // Moved into that order where they are: a big scene's primitives are not copied.
    detail::permute_in_place(std::span<Primitive>(data_.primitives), source_index_);
    for (std::size_t i = 0; i < count; ++i) data_.primitives[i].index = static_cast<std::uint32_t>(i);
    if (queries_here) bvh_ = collapsed.valid() ? collapsed.get() : collapse();
    if (queries_here && data_.acceleration == Acceleration::grid)
        grid_ = std::make_shared<const UniformGrid>(primitive_boxes(bounded_primitives()));
    // Each area light's points draw numbers of their own: no two lights share them.
    std::uint32_t next_number = 0;
    for (AreaLight& light : data_.area_lights) {
        light.first_number = next_number;
        next_number += static_cast<std::uint32_t>(light.samples);
    }
}

namespace {

// Lab 1's closest_hit(), marked as running for the crash report.
std::optional<Hit> labs_closest_hit(const Ray& ray, std::span<const Primitive> primitives, Interval t_range) {
    return detail::call_lab("closest_hit", closest_hit, ray, primitives, t_range);
}

} // namespace

std::size_t Scene::acceleration_bytes() const { return grid_ ? grid_->bytes() : bvh_ ? bvh_->bytes() : 0; }

const BvhTree& Scene::lab_bvh() const {
    // A build that throws (not written yet) leaves the flag unset: the next call tries again.
    std::call_once(lab_bvh_->built, [this] {
        const std::vector<Aabb> boxes = primitive_boxes(bounded_primitives());
        BvhTree tree = remote_ && remote_->lab_bvh ? remote_->lab_bvh(*this)
                       : lab_builder_                  ? lab_builder_(boxes)
                                                       : detail::call_lab("build_bvh", build_bvh, boxes);
        if (const std::string error = bvh_tree_error(tree, boxes); !error.empty())
            throw std::runtime_error("build_bvh() made a tree that is not a hierarchy over the scene's " +
                                     std::to_string(boxes.size()) + " bounded primitives: " + error);
        lab_bvh_->tree = std::move(tree);
    });
    return lab_bvh_->tree;
}

SceneData Scene::source_data() const {
    SceneData data = data_;
    for (std::size_t i = 0; i < data_.primitives.size(); ++i) data.primitives[source_index_[i]] = data_.primitives[i];
    return data;
}

void Scene::apply_vertex_normals(Hit& hit, const Ray& ray) const {
    const Primitive& primitive = data_.primitives[hit.primitive];
    if (primitive.vertex_normals >= 0) whitted::apply_vertex_normals(hit, ray, data_.vertex_normals[primitive.vertex_normals]);
}

std::optional<Hit> Scene::closest_hit(const Ray& ray, Interval t_range) const {
    const std::span<const Primitive> all = data_.primitives;
    if (data_.acceleration == Acceleration::none) { // every primitive, one after the other: the slow way, on purpose
        std::optional<Hit> nearest = labs_closest_hit(ray, all, t_range);
        if (nearest) apply_vertex_normals(*nearest, ray);
        return nearest;
    }
    if (grid_) { // the planes, then the grid's cells along the ray
        std::optional<Hit> nearest = labs_closest_hit(ray, all.subspan(bounded_count_), t_range);
        if (nearest) t_range.max = nearest->t;
        if (std::optional<Hit> hit = grid_->closest_hit(ray, bounded_primitives(), t_range)) nearest = hit;
        if (nearest) apply_vertex_normals(*nearest, ray);
        return nearest;
    }
    if (kernels_) return closest_hit_with_kernels(ray, t_range);
    if (remote_) [[unlikely]]
        return remote_->closest_hit(*this, ray, t_range);
    // Infinite planes first: a plane hit shortens the range the BVH must search.
    std::optional<Hit> nearest = labs_closest_hit(ray, all.subspan(bounded_count_), t_range);
    if (nearest) t_range.max = nearest->t;
    if (walks_lab_bvh()) {
        if (std::optional<Hit> hit = detail::call_lab("bvh_closest_hit", bvh_closest_hit, *this, ray, t_range)) nearest = hit;
        if (nearest) apply_vertex_normals(*nearest, ray);
        return nearest;
    }
    // At equal distances the lower index wins, in whatever order the leaves come
    // (as in the reference leaf kernels, whose packets of rays walk them in
    // another order than a ray alone); a plane, tested first, wins over them all
    // (a box standing on the floor plane shows the floor).
    bool in_bvh = false;
    bvh_->traverse(ray, t_range.min, t_range.max, [&](std::uint32_t first, std::uint32_t count, double t_max) {
        const bool lower = in_bvh && first < nearest->primitive; // leaves hold consecutive indices
        const Interval range{t_range.min, lower ? std::nextafter(t_max, kInfinity) : t_max};
        if (auto hit = labs_closest_hit(ray, all.subspan(first, count), range)) {
            nearest = hit;
            in_bvh = true;
            return hit->t;
        }
        return t_max;
    });
    if (nearest) apply_vertex_normals(*nearest, ray);
    return nearest;
}

// The same search with the leaf kernels: distances only, and one Hit for the nearest.
std::optional<Hit> Scene::closest_hit_with_kernels(const Ray& ray, Interval t_range) const {
    const SceneView view = kernel_view();
    std::optional<Hit> hit = kernels_->closest(view, ray, t_range);
    if (hit) apply_vertex_normals(*hit, ray);
    return hit;
}

bool Scene::occluded(const Ray& ray, Interval t_range) const {
    std::uint32_t blocker = kNoBlocker;
    return occluded(ray, t_range, blocker);
}

bool Scene::occluded(const Ray& ray, Interval t_range, std::uint32_t& blocker) const {
    const std::span<const Primitive> all = data_.primitives;
    if (data_.acceleration == Acceleration::none) {
        for (const Primitive& primitive : all)
            if (intersect(ray, primitive, t_range)) return true;
        return false;
    }
    if (grid_) {
        for (const Primitive& plane : all.subspan(bounded_count_))
            if (intersect(ray, plane, t_range)) return true;
        return grid_->occluded(ray, bounded_primitives(), t_range);
    }
    if (kernels_) return occluded_with_kernels(ray, t_range, blocker);
    if (remote_) [[unlikely]]
        return remote_->occluded(*this, ray, t_range);
    for (const Primitive& plane : all.subspan(bounded_count_)) {
        if (intersect(ray, plane, t_range)) return true;
    }
    if (walks_lab_bvh()) return detail::call_lab("bvh_occluded", bvh_occluded, *this, ray, t_range);
    bool blocked = false;
    bvh_->traverse(ray, t_range.min, t_range.max, [&](std::uint32_t first, std::uint32_t count, double t_max) {
        for (const Primitive& primitive : all.subspan(first, count)) {
            if (intersect(ray, primitive, Interval{t_range.min, t_max})) {
                blocked = true;
                return -1.0; // any hit will do: stop
            }
        }
        return t_max;
    });
    return blocked;
}

QueryCost Scene::query_cost(const Ray& ray, Interval t_range, bool any_hit) const {
    if (!bvh_) throw std::logic_error("Scene::query_cost: this scene's queries are answered by another process");
    const std::span<const Primitive> all = data_.primitives;
    QueryCost cost;
    std::uint64_t nodes = 0;
    // Occlusion tests one shape at a time and stops at the first hit; the
    // closest hit tests every shape of a leaf (the labs' closest_hit()), and
    // the planes first, as closest_hit() and occluded() do.
    const auto test_one_by_one = [&](std::span<const Primitive> shapes, Interval range) {
        for (const Primitive& primitive : shapes) {
            ++cost.primitive_tests;
            if (intersect(ray, primitive, range)) return true;
        }
        return false;
    };
    const std::span<const Primitive> planes = all.subspan(bounded_count_);
    if (any_hit) {
        if (test_one_by_one(planes, t_range)) return cost;
        bvh_->traverse_counting<false>(ray, t_range.min, t_range.max, [&](std::uint32_t first, std::uint32_t count, double t_max) {
            return test_one_by_one(all.subspan(first, count), Interval{t_range.min, t_max}) ? -1.0 : t_max;
        }, nodes);
    } else {
        cost.primitive_tests = planes.size();
        if (const std::optional<Hit> hit = labs_closest_hit(ray, planes, t_range)) t_range.max = hit->t;
        bvh_->traverse_counting(ray, t_range.min, t_range.max, [&](std::uint32_t first, std::uint32_t count, double t_max) {
            cost.primitive_tests += count;
            const std::optional<Hit> hit = labs_closest_hit(ray, all.subspan(first, count), Interval{t_range.min, t_max});
            return hit ? hit->t : t_max;
        }, nodes);
    }
    cost.box_tests = nodes * WideBvh::kWidth;
    return cost;
}

namespace {

// Calls packet(first, count) for consecutive packets of at most RayPacket::kMaxRays of `size` rays.
template <class PacketFn>
void for_each_packet(std::size_t size, PacketFn&& packet) {
    for (std::size_t first = 0; first < size; first += RayPacket::kMaxRays)
        packet(first, std::min<std::size_t>(RayPacket::kMaxRays, size - first));
}

} // namespace

SceneView Scene::kernel_view() const { return SceneView{data_.primitives, bounded_count_, *bvh_}; }

bool Scene::queries_packets() const {
    // A BVH of one leaf has no boxes for a packet to share.
    return kernels_ && kernels_->closest_packet && kernels_->occluded_packet && data_.acceleration != Acceleration::none &&
           !grid_ && !bvh_->nodes().empty();
}

void Scene::closest_hits(std::span<const Ray> rays, std::span<const Interval> t_ranges,
                         std::span<std::optional<Hit>> hits) const {
    if (!queries_packets()) {
        for (std::size_t i = 0; i < rays.size(); ++i) hits[i] = closest_hit(rays[i], t_ranges[i]);
        return;
    }
    const SceneView view = kernel_view();
    for_each_packet(rays.size(), [&](std::size_t first, std::size_t count) {
        kernels_->closest_packet(view, rays.subspan(first, count), t_ranges.subspan(first, count), hits.subspan(first, count));
    });
    for (std::size_t i = 0; i < rays.size(); ++i)
        if (hits[i]) apply_vertex_normals(*hits[i], rays[i]);
}

void Scene::occluded_rays(std::span<const Ray> rays, std::span<const Interval> t_ranges, std::span<bool> blocked) const {
    std::uint32_t blocker = kNoBlocker;
    occluded_rays(rays, t_ranges, blocked, blocker);
}

void Scene::occluded_rays(std::span<const Ray> rays, std::span<const Interval> t_ranges, std::span<bool> blocked,
                          std::uint32_t& blocker) const {
    if (!queries_packets()) {
        for (std::size_t i = 0; i < rays.size(); ++i) blocked[i] = occluded(rays[i], t_ranges[i], blocker);
        return;
    }
    const SceneView view = kernel_view();
    for_each_packet(rays.size(), [&](std::size_t first, std::size_t count) {
        kernels_->occluded_packet(view, rays.subspan(first, count), t_ranges.subspan(first, count), blocked.subspan(first, count),
                                  blocker);
    });
}

bool Scene::occluded_with_kernels(const Ray& ray, Interval t_range, std::uint32_t& blocker) const {
    return kernels_->occluded(kernel_view(), ray, t_range, blocker);
}

} // namespace whitted
