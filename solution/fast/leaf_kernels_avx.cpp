// The reference renderer's fast queries with AVX: a leaf's spheres, or its
// triangles, are tested four at a time, one primitive per lane of a 256-bit
// register of doubles. Each lane performs the plain kernels' operations
// (distances.hpp) in the same order; additions, products, quotients and square
// roots round the same in a lane as in a scalar register, and the build forbids
// fused multiply-adds (-ffp-contract=off), so each lane's distance is bit for
// bit the plain one. Boxes, cones and runs of a single sphere or triangle take
// the plain route.
//
// Why a translation unit of its own: it is compiled with -mavx, and only called
// once the CPU is known to have AVX (leaf_kernels.cpp chooses).
#include "kernel_sets.hpp"
#include "queries.hpp"

#if defined(__AVX__)
#include <immintrin.h>

#include <type_traits>
#include <variant>

namespace whitted {
namespace {

// The shapes' places in the Shape variant, to tell a primitive's kind by one load.
constexpr std::size_t kSphereIndex = 0, kTriangleIndex = 2;
static_assert(std::is_same_v<std::variant_alternative_t<kSphereIndex, Shape>, Sphere>);
static_assert(std::is_same_v<std::variant_alternative_t<kTriangleIndex, Shape>, Triangle>);

// Four lanes of one coordinate.
using Lanes = __m256d;

struct LaneVec {
    Lanes x, y, z;
};

// A ray's origin and direction, each coordinate repeated in four lanes.
struct RayLanes {
    LaneVec origin, direction;
};

inline Lanes dot(const LaneVec& a, const LaneVec& b) { // (ax bx + ay by) + az bz, as glm::dot
    return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(a.x, b.x), _mm256_mul_pd(a.y, b.y)), _mm256_mul_pd(a.z, b.z));
}

inline LaneVec cross(const LaneVec& a, const LaneVec& b) { // as glm::cross
    return {_mm256_sub_pd(_mm256_mul_pd(a.y, b.z), _mm256_mul_pd(b.y, a.z)),
            _mm256_sub_pd(_mm256_mul_pd(a.z, b.x), _mm256_mul_pd(b.z, a.x)),
            _mm256_sub_pd(_mm256_mul_pd(a.x, b.y), _mm256_mul_pd(b.x, a.y))};
}

inline LaneVec sub(const LaneVec& a, const LaneVec& b) {
    return {_mm256_sub_pd(a.x, b.x), _mm256_sub_pd(a.y, b.y), _mm256_sub_pd(a.z, b.z)};
}

// Gathers one point of up to four primitives into lanes; missing lanes repeat lane 0.
template <class Get>
inline LaneVec gather(const Primitive* primitives, std::uint32_t first, unsigned lanes, Get get) {
    const Point3& a = get(primitives[first]);
    const Point3& b = get(primitives[first + (lanes > 1 ? 1 : 0)]);
    const Point3& c = get(primitives[first + (lanes > 2 ? 2 : 0)]);
    const Point3& d = get(primitives[first + (lanes > 3 ? 3 : 0)]);
    return {_mm256_setr_pd(a.x, b.x, c.x, d.x), _mm256_setr_pd(a.y, b.y, c.y, d.y), _mm256_setr_pd(a.z, b.z, c.z, d.z)};
}

inline const Triangle& triangle_of(const Primitive& p) { return *std::get_if<Triangle>(&p.shape); }
inline const Sphere& sphere_of(const Primitive& p) { return *std::get_if<Sphere>(&p.shape); }

// min < t < max in each lane (false for NaN, as Interval::surrounds).
inline Lanes surrounds(Lanes t, Lanes t_min, Lanes t_max) {
    return _mm256_and_pd(_mm256_cmp_pd(t_min, t, _CMP_LT_OQ), _mm256_cmp_pd(t, t_max, _CMP_LT_OQ));
}

// The distances to up to four consecutive triangles (kMiss where none), as triangle_distance.
inline Lanes triangle_distances(const RayLanes& ray, const Primitive* primitives, std::uint32_t first, unsigned lanes,
                                Lanes t_min, Lanes t_max) {
    const LaneVec p0 = gather(primitives, first, lanes, [](const Primitive& p) -> const Point3& { return triangle_of(p).p0; });
    const LaneVec p1 = gather(primitives, first, lanes, [](const Primitive& p) -> const Point3& { return triangle_of(p).p1; });
    const LaneVec p2 = gather(primitives, first, lanes, [](const Primitive& p) -> const Point3& { return triangle_of(p).p2; });
    const LaneVec e1 = sub(p1, p0);
    const LaneVec e2 = sub(p2, p0);
    const LaneVec p = cross(ray.direction, e2);
    const Lanes determinant = dot(e1, p);
    const Lanes inverse = _mm256_div_pd(_mm256_set1_pd(1.0), determinant);
    const LaneVec s = sub(ray.origin, p0);
    const Lanes b1 = _mm256_mul_pd(dot(s, p), inverse);
    const LaneVec q = cross(s, e1);
    const Lanes b2 = _mm256_mul_pd(dot(ray.direction, q), inverse);
    const Lanes t = _mm256_mul_pd(dot(e2, q), inverse);
    // The plain test's early exits, as one mask of lanes that miss (ordered
    // comparisons: a NaN passes them, as it passes the plain test's `if`s).
    const Lanes zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
    Lanes miss = _mm256_cmp_pd(determinant, zero, _CMP_EQ_OQ);
    miss = _mm256_or_pd(miss, _mm256_or_pd(_mm256_cmp_pd(b1, zero, _CMP_LT_OQ), _mm256_cmp_pd(b1, one, _CMP_GT_OQ)));
    miss = _mm256_or_pd(miss, _mm256_cmp_pd(b2, zero, _CMP_LT_OQ));
    miss = _mm256_or_pd(miss, _mm256_cmp_pd(_mm256_add_pd(b1, b2), one, _CMP_GT_OQ));
    const Lanes hit = _mm256_andnot_pd(miss, surrounds(t, t_min, t_max));
    return _mm256_blendv_pd(_mm256_set1_pd(kMiss), t, hit);
}

// The distances to up to four consecutive spheres (kMiss where none), as sphere_distance.
inline Lanes sphere_distances(const RayLanes& ray, const Primitive* primitives, std::uint32_t first, unsigned lanes,
                              Lanes t_min, Lanes t_max) {
    const LaneVec center = gather(primitives, first, lanes, [](const Primitive& p) -> const Point3& { return sphere_of(p).center; });
    const Lanes radius = _mm256_setr_pd(sphere_of(primitives[first]).radius, sphere_of(primitives[first + (lanes > 1 ? 1 : 0)]).radius,
                                        sphere_of(primitives[first + (lanes > 2 ? 2 : 0)]).radius,
                                        sphere_of(primitives[first + (lanes > 3 ? 3 : 0)]).radius);
    const LaneVec oc = sub(ray.origin, center);
    const Lanes b = dot(oc, ray.direction);
    const Lanes radius_squared = _mm256_mul_pd(radius, radius);
    const Lanes c = _mm256_sub_pd(dot(oc, oc), radius_squared);
    const LaneVec to_line = {_mm256_sub_pd(oc.x, _mm256_mul_pd(b, ray.direction.x)), _mm256_sub_pd(oc.y, _mm256_mul_pd(b, ray.direction.y)),
                             _mm256_sub_pd(oc.z, _mm256_mul_pd(b, ray.direction.z))};
    const Lanes discriminant = _mm256_sub_pd(radius_squared, dot(to_line, to_line));
    const Lanes zero = _mm256_setzero_pd();
    const Lanes sign = _mm256_set1_pd(-0.0);
    // q = -b - copysign(sqrt(discriminant), b), with the sign moved bit by bit (exact).
    const Lanes root = _mm256_sqrt_pd(discriminant);
    const Lanes signed_root = _mm256_or_pd(_mm256_andnot_pd(sign, root), _mm256_and_pd(sign, b));
    const Lanes q = _mm256_sub_pd(_mm256_xor_pd(b, sign), signed_root);
    const Lanes t1_quotient = _mm256_blendv_pd(_mm256_div_pd(c, q), zero, _mm256_cmp_pd(q, zero, _CMP_EQ_OQ));
    const Lanes swap = _mm256_cmp_pd(q, t1_quotient, _CMP_GT_OQ);
    const Lanes t0 = _mm256_blendv_pd(q, t1_quotient, swap);
    const Lanes t1 = _mm256_blendv_pd(t1_quotient, q, swap);
    const Lanes in0 = surrounds(t0, t_min, t_max), in1 = surrounds(t1, t_min, t_max);
    const Lanes t = _mm256_blendv_pd(_mm256_blendv_pd(_mm256_set1_pd(kMiss), t1, in1), t0, in0);
    return _mm256_blendv_pd(t, _mm256_set1_pd(kMiss), _mm256_cmp_pd(discriminant, zero, _CMP_LT_OQ));
}

// Tests a leaf's primitives in runs: up to four consecutive spheres or
// triangles at once, anything else (or a run of one) on its own.
struct AvxLeaf {
    RayLanes lanes;

    explicit AvxLeaf(const Ray& ray)
        : lanes{{_mm256_set1_pd(ray.origin.x), _mm256_set1_pd(ray.origin.y), _mm256_set1_pd(ray.origin.z)},
                {_mm256_set1_pd(ray.direction.x), _mm256_set1_pd(ray.direction.y), _mm256_set1_pd(ray.direction.z)}} {}

    // Calls visit(first, lanes_in_run, distances) for each run of two to four
    // spheres or triangles, and single(i) for every other primitive, in order;
    // stops when either returns true.
    template <class Visit, class Single>
    void runs(const Primitive* primitives, std::uint32_t first, std::uint32_t count, double t_min, const double& t_max,
              Visit visit, Single single) const {
        const std::uint32_t end = first + count;
        for (std::uint32_t i = first; i < end;) {
            const std::size_t kind = primitives[i].shape.index();
            std::uint32_t run = 1;
            const bool packable = kind == kSphereIndex || kind == kTriangleIndex;
            if (packable)
                while (run < 4 && i + run < end && primitives[i + run].shape.index() == kind) ++run;
            if (run == 1) {
                if (single(i)) return;
            } else {
                const Lanes low = _mm256_set1_pd(t_min), high = _mm256_set1_pd(t_max);
                const Lanes t = kind == kSphereIndex ? sphere_distances(lanes, primitives, i, run, low, high)
                                                           : triangle_distances(lanes, primitives, i, run, low, high);
                alignas(32) double distances[4];
                _mm256_store_pd(distances, t);
                if (visit(i, run, distances)) return;
            }
            i += run;
        }
    }

    double nearest(const Ray& ray, const Primitive* primitives, std::uint32_t first, std::uint32_t count, double t_min,
                   double t_max, std::optional<std::uint32_t>& nearest_index) const {
        // A lane's distance is the plain test's with the range's max at the
        // run's start; keeping those below the current max, lane by lane, is
        // what the plain loop with its shrinking max finds (a test with a
        // larger max finds the same nearest root, or one beyond the max).
        runs(
            primitives, first, count, t_min, t_max,
            [&](std::uint32_t run_first, unsigned run, const double* distances) {
                for (unsigned lane = 0; lane < run; ++lane)
                    if (distances[lane] < t_max) t_max = distances[lane], nearest_index = run_first + lane;
                return false;
            },
            [&](std::uint32_t i) {
                if (const double t = distance(ray, primitives[i], Interval{t_min, t_max}); t != kMiss) t_max = t, nearest_index = i;
                return false;
            });
        return t_max;
    }

    bool any(const Ray& ray, const Primitive* primitives, std::uint32_t first, std::uint32_t count, double t_min,
             double t_max) const {
        bool found = false;
        runs(
            primitives, first, count, t_min, t_max,
            [&](std::uint32_t, unsigned run, const double* distances) {
                for (unsigned lane = 0; lane < run; ++lane) found = found || distances[lane] != kMiss;
                return found;
            },
            [&](std::uint32_t i) { return found = distance(ray, primitives[i], Interval{t_min, t_max}) != kMiss; });
        return found;
    }

};

constexpr LeafKernels kAvxKernels{closest_query<AvxLeaf>, occluded_query<AvxLeaf>};

} // namespace

const LeafKernels* avx_leaf_kernels() { return &kAvxKernels; }

} // namespace whitted

#else

namespace whitted {

const LeafKernels* avx_leaf_kernels() { return nullptr; }

} // namespace whitted

#endif
