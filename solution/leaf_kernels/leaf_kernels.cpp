// The reference renderer's leaf kernels: the BVH walk with hit distances only.
// Spheres, planes and triangles go through the reference lab 1's own distance
// functions (whitted/engine/hit_distances.hpp, defined in solution/01), boxes and
// cones through the framework's intersections, so the nearest primitive and its
// distance are the labs' own, bit for bit, by construction. The one exception,
// two neighbouring triangles tested at once (screens.hpp), repeats lab 1's
// triangle test operation for operation, and a test holds it to that.
//
// Why here and not in framework/: these are the answers to lab 1, and the
// student handout ships framework/ but not solution/.
#include "whitted/engine/leaf_kernels.hpp"
#include "whitted/engine/hit_distances.hpp"
#include "whitted/engine/result_in_place.hpp"

#include "screens.hpp"
#include "whitted/scene.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <new>
#include <type_traits>

namespace whitted {
namespace {

// What distance() returns for "no hit in the range" (no valid t equals it:
// ranges are open, so even an infinite maximum excludes it).
constexpr double kMiss = std::numeric_limits<double>::infinity();

// std::nextafter(t, kMiss), the next double up, without the library call.
inline double next_up(double t) {
    if (!(t < kMiss)) return t; // +infinity and NaN stay
    if (t == 0.0) return std::numeric_limits<double>::denorm_min();
    const auto bits = std::bit_cast<std::uint64_t>(t);
    return std::bit_cast<double>(t > 0.0 ? bits + 1 : bits - 1);
}

// The distance of the ray's hit with the primitive inside t_range, or kMiss;
// for a triangle, also where on it (`on_triangle`), to build its hit from later.
inline double distance(const Ray& ray, const Primitive& primitive, Interval t_range, TriangleDistance& on_triangle) {
    const Shape& shape = primitive.shape;
    if (const auto* sphere = std::get_if<Sphere>(&shape)) return sphere_distance(ray, *sphere, t_range).value_or(kMiss);
    if (const auto* triangle = std::get_if<Triangle>(&shape)) {
        const std::optional<TriangleDistance> found = triangle_distance(ray, *triangle, t_range);
        if (!found) return kMiss;
        on_triangle = *found;
        return found->t;
    }
    if (const auto* plane = std::get_if<Plane>(&shape)) return plane_distance(ray, *plane, t_range).value_or(kMiss);
    const std::optional<Hit> hit = std::holds_alternative<Box>(shape) ? intersect_box(ray, std::get<Box>(shape), t_range)
                                                                      : intersect_cone(ray, std::get<Cone>(shape), t_range);
    return hit ? hit->t : kMiss;
}

inline double distance(const Ray& ray, const Primitive& primitive, Interval t_range) {
    TriangleDistance unused;
    return distance(ray, primitive, t_range, unused);
}

// The hit the labs' intersect() returns for the primitive found at distance t
// (`on_triangle` where a triangle was met), without testing it again.
std::optional<Hit> hit_at(const Ray& ray, const Primitive& primitive, double t, const TriangleDistance& on_triangle, Interval t_range) {
    const Shape& shape = primitive.shape;
    // Built in place (result_in_place.hpp), and returned as the one named result, so
    // that (g++ eliding the return) a sphere's, triangle's or plane's Hit is written
    // once, into the caller's optional; boxes and cones, rare, are built aside.
    std::optional<Hit> hit;
    if (const auto* sphere = std::get_if<Sphere>(&shape)) hit.emplace(ResultOf{[&] { return sphere_hit(ray, *sphere, t); }});
    else if (const auto* triangle = std::get_if<Triangle>(&shape))
        hit.emplace(ResultOf{[&] { return triangle_hit(ray, *triangle, on_triangle); }});
    else if (const auto* plane = std::get_if<Plane>(&shape)) hit.emplace(ResultOf{[&] { return plane_hit(ray, *plane, t); }});
    else hit = intersect(ray, primitive, t_range); // boxes and cones: the framework's own test, once more
    if (hit) {
        hit->primitive = primitive.index;
        hit->material = primitive.material;
    }
    return hit;
}

// Primitives i and i + 1 when both are triangles (the pair lab 1's test takes at once, screens.hpp).
struct TwoTriangles {
    const Triangle* a = nullptr;
    const Triangle* b = nullptr;

    TwoTriangles(const SceneView& scene, std::uint32_t i)
        : a(std::get_if<Triangle>(&scene.primitives[i].shape)), b(std::get_if<Triangle>(&scene.primitives[i + 1].shape)) {}
    explicit operator bool() const { return a && b; }
};

// One ray's nearest hit so far: which primitive, how far, where on a triangle.
struct Nearest {
    double t;                          // the search's upper end until something is found
    std::uint32_t index = kNoPrimitive; // kNoPrimitive: nothing yet, or an infinite plane (`plane`)
    std::uint32_t plane = 0;
    bool found = false;
    TriangleDistance on_triangle{};

    static constexpr std::uint32_t kNoPrimitive = 0xffffffffu;

    // Tests primitive i of the BVH. At equal distances the lower index wins,
    // whatever order the leaves come in (a ray alone and a packet of rays walk
    // them in different orders, and must agree), and a plane, tested first, wins
    // over any primitive of the BVH (a box standing on the floor plane shows the floor).
    [[gnu::always_inline]] void test(const Ray& ray, const Primitive& primitive, std::uint32_t i, double t_min) {
        TriangleDistance candidate;
        if (const double hit_t = distance(ray, primitive, Interval{t_min, limit_for(i)}, candidate); hit_t != kMiss)
            take(i, hit_t, candidate);
    }

    // Primitive i is the nearest so far, met at hit_t (`where` on it, for a triangle).
    void take(std::uint32_t i, double hit_t, const TriangleDistance& where) {
        t = hit_t;
        index = i;
        found = true;
        on_triangle = where;
    }

    // The limit test() searches primitive i up to.
    double limit_for(std::uint32_t i) const { return index != kNoPrimitive && i < index ? next_up(t) : t; }

    // Tests the primitives of a leaf, [first, first + count): neighbouring
    // triangles two at a time (screens.hpp), the same answers as test().
    [[gnu::always_inline]] void test_leaf(const Ray& ray, const SceneView& scene, std::uint32_t first, std::uint32_t count, double t_min) {
        const std::uint32_t end = first + count;
        std::uint32_t i = first;
#if WHITTED_PAIR_LANES
        for (; i + 1 < end; i += 2) {
            const TwoTriangles two(scene, i);
            if (!two) {
                test(ray, scene.primitives[i], i, t_min);
                test(ray, scene.primitives[i + 1], i + 1, t_min);
                continue;
            }
            // The widest range either search may have: to t and a hair beyond.
            const screens::TrianglePair pair = screens::triangle_pair_distances(ray, *two.a, *two.b, Interval{t_min, next_up(t)});
            for (unsigned lane = 0; lane < 2; ++lane)
                if ((pair.hit >> lane & 1u) && pair.t[lane] < limit_for(i + lane))
                    take(i + lane, pair.t[lane], TriangleDistance{pair.t[lane], pair.b1[lane], pair.b2[lane]});
        }
#endif
        for (; i < end; ++i) test(ray, scene.primitives[i], i, t_min);
    }
};

// The infinite planes, which the BVH does not hold: tested first, so that a hit
// there shortens the range the BVH must search. `nearest` starts the search
// afresh; it is filled in place (a packet's Nearest built aside and then copied
// was read back in 16-byte pieces from smaller stores, a stall on every ray).
void nearest_plane(const SceneView& scene, const Ray& ray, Interval t_range, Nearest& nearest) {
    nearest.t = t_range.max;
    nearest.index = Nearest::kNoPrimitive;
    nearest.plane = 0;
    nearest.found = false;
    TriangleDistance unused;
    for (std::size_t i = scene.bounded_count; i < scene.primitives.size(); ++i) {
        if (const double t = distance(ray, scene.primitives[i], Interval{t_range.min, nearest.t}, unused); t != kMiss) {
            nearest.t = t;
            nearest.found = true;
            nearest.plane = static_cast<std::uint32_t>(i);
        }
    }
}

// The hit the search found, built once.
std::optional<Hit> nearest_hit(const SceneView& scene, const Ray& ray, const Nearest& nearest, Interval t_range) {
    if (!nearest.found) return std::nullopt;
    const std::uint32_t i = nearest.index != Nearest::kNoPrimitive ? nearest.index : nearest.plane;
    return hit_at(ray, scene.primitives[i], nearest.t, nearest.on_triangle, t_range);
}

// The scene's closest-hit query: planes first, then the BVH, nearer boxes first.
// A single ray's leaf search is inlined into the walk (1 % on every scene; a
// packet's is not, which measured level or slower).
std::optional<Hit> closest(const SceneView& scene, const Ray& ray, Interval t_range) {
    Nearest nearest{t_range.max};
    nearest_plane(scene, ray, t_range, nearest);
    scene.bvh.traverse(ray, t_range.min, nearest.t, [&](std::uint32_t first, std::uint32_t count, double) __attribute__((always_inline)) {
        nearest.test_leaf(ray, scene, first, count, t_range.min);
        return nearest.t;
    });
    return nearest_hit(scene, ray, nearest, t_range);
}

// The infinite plane that lies along the ray within t_range, or kNoBlocker.
std::uint32_t plane_blocking(const SceneView& scene, const Ray& ray, Interval t_range) {
    for (std::size_t i = scene.bounded_count; i < scene.primitives.size(); ++i)
        if (distance(ray, scene.primitives[i], t_range) != kMiss) return static_cast<std::uint32_t>(i);
    return kNoBlocker;
}

// True when primitive i, a former blocker (or kNoBlocker), lies along the ray within t_range.
bool blocks(const SceneView& scene, const Ray& ray, std::uint32_t i, Interval t_range) {
    return i < scene.primitives.size() && distance(ray, scene.primitives[i], t_range) != kMiss;
}

// The primitive of the leaf [first, first + count) that lies along the ray within
// t_range, or kNoBlocker; neighbouring triangles are tested two at a time (screens.hpp).
[[gnu::always_inline]] inline std::uint32_t leaf_blocker(const Ray& ray, const SceneView& scene, std::uint32_t first, std::uint32_t count,
                                                         Interval t_range) {
    const std::uint32_t end = first + count;
    std::uint32_t i = first;
#if WHITTED_PAIR_LANES
    for (; i + 1 < end; i += 2) {
        if (const TwoTriangles two(scene, i); two) {
            if (const unsigned hit = screens::triangle_pair_distances(ray, *two.a, *two.b, t_range).hit; hit != 0)
                return i + static_cast<std::uint32_t>(__builtin_ctz(hit));
        } else {
            if (distance(ray, scene.primitives[i], t_range) != kMiss) return i;
            if (distance(ray, scene.primitives[i + 1], t_range) != kMiss) return i + 1;
        }
    }
#endif
    for (; i < end; ++i)
        if (distance(ray, scene.primitives[i], t_range) != kMiss) return i;
    return kNoBlocker;
}

// The primitive of the BVH that lies along the ray within t_range (the first
// one the walk finds), or kNoBlocker: any hit will do, so the first one ends it.
std::uint32_t bvh_blocker(const SceneView& scene, const Ray& ray, Interval t_range) {
    std::uint32_t found = kNoBlocker;
    scene.bvh.traverse<false>(ray, t_range.min, t_range.max, [&](std::uint32_t first, std::uint32_t count, double t_max) __attribute__((always_inline)) {
        found = leaf_blocker(ray, scene, first, count, Interval{t_range.min, t_max});
        return found != kNoBlocker ? -1.0 : t_max;
    });
    return found;
}

// The scene's occlusion query: the former blocker first (the next feeler towards
// a light likely passes it too), then the planes, then the BVH.
bool occluded(const SceneView& scene, const Ray& ray, Interval t_range, std::uint32_t& blocker) {
    if (blocks(scene, ray, blocker, t_range)) return true;
    blocker = plane_blocking(scene, ray, t_range);
    if (blocker == kNoBlocker) blocker = bvh_blocker(scene, ray, t_range);
    return blocker != kNoBlocker;
}

// closest() for a packet of rays: the same planes, the same leaves for each
// ray that may meet them, and the same rule at equal distances, so the same hits.
void closest_packet(const SceneView& scene, std::span<const Ray> rays, std::span<const Interval> t_ranges,
                    std::span<std::optional<Hit>> hits) {
    RayPacket packet(rays, t_ranges, scene.bvh.extent());
    if (!packet.coherent()) {
        for (std::size_t r = 0; r < rays.size(); ++r) hits[r] = closest(scene, rays[r], t_ranges[r]);
        return;
    }
    Nearest nearest[RayPacket::kMaxRays];
    for (std::size_t r = 0; r < rays.size(); ++r) {
        nearest_plane(scene, rays[r], t_ranges[r], nearest[r]);
        if (nearest[r].found) packet.shrink(static_cast<int>(r), nearest[r].t);
    }
    packet.refresh_t_max();
    scene.bvh.traverse_packet(packet, [&](std::uint32_t first, std::uint32_t count, unsigned which) {
        bool shrunk = false;
        for (; which != 0; which &= which - 1) {
            const int r = __builtin_ctz(which);
            const double before = nearest[r].t;
            nearest[r].test_leaf(rays[r], scene, first, count, t_ranges[r].min);
            if (nearest[r].t != before) {
                packet.shrink(r, nearest[r].t);
                shrunk = true;
            }
        }
        if (shrunk) packet.refresh_t_max();
    });
    // Each hit made in its place: built aside and assigned, it would be read back
    // in 16-byte pieces from the narrower stores that wrote it, and wait.
    static_assert(std::is_trivially_destructible_v<std::optional<Hit>>);
    for (std::size_t r = 0; r < rays.size(); ++r)
        ::new (&hits[r]) std::optional<Hit>(nearest_hit(scene, rays[r], nearest[r], t_ranges[r]));
}

// occluded() for a packet of rays: the former blocker and the planes for each
// ray first, then the walk, which a ray leaves at its first blocker.
void occluded_packet(const SceneView& scene, std::span<const Ray> rays, std::span<const Interval> t_ranges,
                     std::span<bool> blocked, std::uint32_t& blocker) {
    const std::uint32_t former = blocker;
    blocker = kNoBlocker; // unless a ray of the packet is blocked
    const auto note = [&](std::size_t r, std::uint32_t found) {
        blocked[r] = found != kNoBlocker;
        if (blocked[r]) blocker = found;
        return blocked[r];
    };
    unsigned done = 0;
    for (std::size_t r = 0; r < rays.size(); ++r)
        if (note(r, blocks(scene, rays[r], former, t_ranges[r]) ? former : plane_blocking(scene, rays[r], t_ranges[r])))
            done |= 1u << r;
    if (done == (1u << rays.size()) - 1u) return; // at most RayPacket::kMaxRays rays
    RayPacket packet(rays, t_ranges, scene.bvh.extent());
    if (!packet.coherent()) {
        for (std::size_t r = 0; r < rays.size(); ++r)
            if (!(done >> r & 1u)) note(r, bvh_blocker(scene, rays[r], t_ranges[r]));
        return;
    }
    if (done != 0) packet.retire(done);
    scene.bvh.traverse_packet<false>(packet, [&](std::uint32_t first, std::uint32_t count, unsigned which) {
        unsigned found = 0;
        for (; which != 0; which &= which - 1) {
            const int r = __builtin_ctz(which);
            if (note(static_cast<std::size_t>(r), leaf_blocker(rays[r], scene, first, count, t_ranges[r]))) found |= 1u << r;
        }
        if (found != 0) packet.retire(found);
    });
}

constexpr LeafKernels kReferenceKernels{closest, occluded, closest_packet, occluded_packet};

} // namespace

const LeafKernels* linked_leaf_kernels() { return &kReferenceKernels; }

} // namespace whitted
