// Lab 1's triangle test for two triangles at once.
//
// Why: a leaf's triangles are tested one after the other, each waiting on its
// own division. This computes lab 1's triangle_distance (Moller-Trumbore) for
// two triangles at once, one per SSE2 lane, with the very same operations in
// the same order (no contraction: the build passes -ffp-contract=off), so each
// lane holds the very bits the lab's code computes, and a lane says "hit"
// exactly where the lab's function returns one, with its t, b1 and b2
// (instructor/tests/solution checks that on rays that graze edges and corners).
// Spheres were tried the same way: their discriminant is as cheap one by one.
#pragma once

#include "whitted/interval.hpp"
#include "whitted/ray.hpp"
#include "whitted/shapes.hpp"

// Pairs need double arithmetic done in SSE2 everywhere (x86-64): a 32-bit x87
// build rounds the lab's doubles in extended precision, and the lanes would not
// hold the same bits. Elsewhere the kernels test one triangle at a time.
#if defined(__SSE2__) && defined(__SSE2_MATH__) && __FLT_EVAL_METHOD__ == 0
#define WHITTED_PAIR_LANES 1
#include <emmintrin.h>
#else
#define WHITTED_PAIR_LANES 0
#endif

namespace whitted::screens {

#if WHITTED_PAIR_LANES
namespace detail {

// Three doubles of each of two primitives, lane 0 from `a`, lane 1 from `b`.
struct Pair3 {
    __m128d x, y, z;
};
inline Pair3 pair(const Vec3& a, const Vec3& b) {
    return {_mm_set_pd(b.x, a.x), _mm_set_pd(b.y, a.y), _mm_set_pd(b.z, a.z)};
}
inline Pair3 broadcast(const Vec3& v) { return {_mm_set1_pd(v.x), _mm_set1_pd(v.y), _mm_set1_pd(v.z)}; }
inline Pair3 minus(const Pair3& a, const Pair3& b) {
    return {_mm_sub_pd(a.x, b.x), _mm_sub_pd(a.y, b.y), _mm_sub_pd(a.z, b.z)};
}
// glm::dot: (x x' + y y') + z z'.
inline __m128d dot(const Pair3& a, const Pair3& b) {
    return _mm_add_pd(_mm_add_pd(_mm_mul_pd(a.x, b.x), _mm_mul_pd(a.y, b.y)), _mm_mul_pd(a.z, b.z));
}
// glm::cross, term by term.
inline Pair3 cross(const Pair3& a, const Pair3& b) {
    return {_mm_sub_pd(_mm_mul_pd(a.y, b.z), _mm_mul_pd(b.y, a.z)), _mm_sub_pd(_mm_mul_pd(a.z, b.x), _mm_mul_pd(b.z, a.x)),
            _mm_sub_pd(_mm_mul_pd(a.x, b.y), _mm_mul_pd(b.x, a.y))};
}

} // namespace detail

/// What triangle_distance(ray, a, t_range) and triangle_distance(ray, b, t_range) return.
struct TrianglePair {
    unsigned hit = 0;                         // bit 0: a is hit within t_range, bit 1: b is
    alignas(16) double t[2], b1[2], b2[2];    // their TriangleDistance where hit
};

/// Lab 1's triangle_distance for two triangles at once.
inline TrianglePair triangle_pair_distances(const Ray& ray, const Triangle& a, const Triangle& b, Interval t_range) {
    using namespace detail;
    const Pair3 direction = broadcast(ray.direction);
    const Pair3 p0 = pair(a.p0, b.p0);
    const Pair3 e1 = minus(pair(a.p1, b.p1), p0);
    const Pair3 e2 = minus(pair(a.p2, b.p2), p0);
    const Pair3 p = cross(direction, e2);
    const __m128d determinant = dot(e1, p);
    const __m128d inverse = _mm_div_pd(_mm_set1_pd(1.0), determinant); // a lane of 0 is turned away below
    const Pair3 s = minus(broadcast(ray.origin), p0);
    const __m128d b1 = _mm_mul_pd(dot(s, p), inverse);
    const Pair3 q = cross(s, e1);
    const __m128d b2 = _mm_mul_pd(dot(direction, q), inverse);
    const __m128d t = _mm_mul_pd(dot(e2, q), inverse);
    const __m128d zero = _mm_setzero_pd(), one = _mm_set1_pd(1.0);
    // The lab's tests, each turning the triangle away where it holds (NaN turns
    // nothing away but the range, as there).
    __m128d away = _mm_cmpeq_pd(determinant, zero);
    away = _mm_or_pd(away, _mm_or_pd(_mm_cmplt_pd(b1, zero), _mm_cmpgt_pd(b1, one)));
    away = _mm_or_pd(away, _mm_or_pd(_mm_cmplt_pd(b2, zero), _mm_cmpgt_pd(_mm_add_pd(b1, b2), one)));
    const __m128d inside = _mm_and_pd(_mm_cmplt_pd(_mm_set1_pd(t_range.min), t), _mm_cmplt_pd(t, _mm_set1_pd(t_range.max)));
    TrianglePair found;
    found.hit = static_cast<unsigned>(_mm_movemask_pd(_mm_andnot_pd(away, inside)));
    _mm_store_pd(found.t, t);
    _mm_store_pd(found.b1, b1);
    _mm_store_pd(found.b2, b2);
    return found;
}
#endif

} // namespace whitted::screens
