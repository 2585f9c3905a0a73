// A ray prepared for testing float boxes four (SSE2) or eight (AVX2) at once, conservatively.
//
// Why: the wide BVH stores boxes in float and tests four per instruction, but a
// box test that rounds the wrong way would lose a hit the exact test finds: a
// hole in the image. So the test is made to err only towards "hit". Every
// rounding error of the computation (origin, direction and bounds in float, the
// subtraction, the reciprocal, the product) is below 2^-22 (|origin| + |bound|)
// in position, times |1/d| in t. The bound's share is covered by the BVH, which
// moves every box face outwards by 2^-20 |bound| before rounding it outwards;
// the origin's share by the ray: each slab's entry distance is computed from an
// origin moved forward by m = 2^-20 |origin|, its exit distance from one moved
// back by m. A box may then be visited that the exact test would skip; that
// costs a little time and never changes a hit. The direction is first scaled by
// a power of two to unit size, and components of 0 become tiny ones of the same
// sign, so no 0 × infinity (NaN) ever appears; the margin then also holds
// 2^-58 of the scene's size, which keeps such a ray's slab open past the scene.
#pragma once

#include "whitted/ray.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

// On x86-64, WideBvh's walk can also test a node's eight boxes in one AVX2 pass,
// compiled for AVX2 whatever the build targets and chosen only where the CPU has it.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define WHITTED_AVX2_WALK 1
#include <immintrin.h>
#else
#define WHITTED_AVX2_WALK 0
#endif

namespace whitted {

class WideRay {
  public:
    /// One ray's numbers for the slab test, before they are spread over lanes.
    struct Numbers {
        float inv[3];          // 1 / direction, the direction scaled by a power of two
        float origin_entry[3]; // the origin moved along the ray by the margin (entry distances)
        float origin_exit[3];  // ... and moved back (exit distances)
        bool negative[3];      // the direction's sign on each axis
        double inverse_scale;  // distances in the scaled ray's units are t * inverse_scale
        float t_min, t_max;    // the range in those units, rounded outwards
    };

    /// The numbers WideRay(ray, extent, t_min, t_max) tests boxes with.
    static Numbers numbers(const Ray& ray, double extent, double t_min, double t_max) {
        Numbers n;
        // Scale the direction by a power of two (exactly) so that its largest
        // component lies in [0.5, 1): float then holds every direction, however
        // long or short; distances along the scaled ray are t / scale.
        // std::abs, not glm::abs: glm's is a branch on the sign, which rays of all
        // directions mispredict (the -0 it keeps changes no number below).
        const double largest = std::max({std::abs(ray.direction.x), std::abs(ray.direction.y), std::abs(ray.direction.z)});
        const int exponent = std::clamp(binary_exponent(largest), -1020, 1020); // both scales stay finite
        n.inverse_scale = power_of_two(exponent);
        const double scale = power_of_two(-exponent);
        const double origin_size = std::max({std::abs(ray.origin.x), std::abs(ray.origin.y), std::abs(ray.origin.z)});
        // The origin's share of the rounding, plus a sliver of the scene's size so
        // that a direction component of 0 (replaced by 2^-62) keeps a slab the ray
        // runs inside open for far longer than any distance in the scene.
        const double margin = 0x1p-20 * origin_size + 0x1p-58 * extent + 1e-30;
        for (int axis = 0; axis < 3; ++axis) {
            double d = ray.direction[axis] * scale; // exact: a power of two
            if (!(std::abs(d) >= 0x1p-62)) d = std::copysign(0x1p-62, d);
            n.negative[axis] = d < 0.0;
            n.inv[axis] = 1.0f / static_cast<float>(d); // its rounding, like every other, is far below the margin
            // Entry: origin moved along the ray by the margin; exit: moved back.
            const double shift = n.negative[axis] ? -margin : margin;
            n.origin_entry[axis] = static_cast<float>(ray.origin[axis] + shift);
            n.origin_exit[axis] = static_cast<float>(ray.origin[axis] - shift);
        }
        n.t_min = round_down(t_min * n.inverse_scale);
        n.t_max = round_up(t_max * n.inverse_scale);
        return n;
    }

    /// Prepares `ray` for boxes built by WideBvh (faces moved outwards) within a
    /// scene whose coordinates are at most `extent` in size, for t in (t_min, t_max).
    WideRay(const Ray& ray, double extent, double t_min, double t_max) {
        const Numbers n = numbers(ray, extent, t_min, t_max);
        for (int axis = 0; axis < 3; ++axis) {
            for (int lane = 0; lane < 4; ++lane) {
                inv_[axis][lane] = n.inv[axis];
                origin_entry_[axis][lane] = n.origin_entry[axis];
                origin_exit_[axis][lane] = n.origin_exit[axis];
            }
            near_[axis] = 2 * axis + (n.negative[axis] ? 1 : 0);
            far_[axis] = 2 * axis + (n.negative[axis] ? 0 : 1);
        }
        inverse_scale_ = n.inverse_scale;
        t_min_ = n.t_min;
        t_max_ = n.t_max;
    }

    float t_min() const { return t_min_; }
    float t_max() const { return t_max_; }
    /// Lowers the far end of the range after a hit at t.
    void shrink(double t) const { t_max_ = round_up(t * inverse_scale_); }

    /// Tests boxes side by side, four at a time (bounds[6][kBoxes] as in
    /// WideBvh::Node); returns a bit per box the ray may meet within its range,
    /// and each box's entry distance.
    template <int kBoxes>
    unsigned hit_boxes(const float (&bounds)[6][kBoxes], float (&t_entry)[kBoxes]) const {
        static_assert(kBoxes % 4 == 0, "boxes are tested four at a time");
        unsigned mask = 0;
        for (int first = 0; first < kBoxes; first += 4) {
#if defined(__SSE2__)
            __m128 entry = _mm_set1_ps(t_min_);
            __m128 exit = _mm_set1_ps(t_max_);
            for (int axis = 0; axis < 3; ++axis) {
                const __m128 inv = _mm_load_ps(inv_[axis]);
                const __m128 t_near =
                    _mm_mul_ps(_mm_sub_ps(_mm_load_ps(bounds[near_[axis]] + first), _mm_load_ps(origin_entry_[axis])), inv);
                const __m128 t_far =
                    _mm_mul_ps(_mm_sub_ps(_mm_load_ps(bounds[far_[axis]] + first), _mm_load_ps(origin_exit_[axis])), inv);
                entry = _mm_max_ps(entry, t_near);
                exit = _mm_min_ps(exit, t_far);
            }
            _mm_storeu_ps(t_entry + first, entry);
            mask |= static_cast<unsigned>(_mm_movemask_ps(_mm_cmple_ps(entry, exit))) << first;
#else
            for (int i = first; i < first + 4; ++i) {
                float entry = t_min_, exit = t_max_;
                for (int axis = 0; axis < 3; ++axis) {
                    entry = std::max(entry, (bounds[near_[axis]][i] - origin_entry_[axis][i % 4]) * inv_[axis][i % 4]);
                    exit = std::min(exit, (bounds[far_[axis]][i] - origin_exit_[axis][i % 4]) * inv_[axis][i % 4]);
                }
                t_entry[i] = entry;
                if (entry <= exit) mask |= 1u << i;
            }
#endif
        }
        return mask;
    }

#if WHITTED_AVX2_WALK
    /// hit_boxes() for eight boxes in one AVX2 pass (only where the CPU has
    /// AVX2): the same operations on the same numbers, lane for lane, so the
    /// same bits and the same answer. Not a fused multiply-add: that rounds
    /// differently, and overflows differently for huge origins.
    [[gnu::target("avx2")]] unsigned hit_eight_boxes_avx2(const float (&bounds)[6][8], float (&t_entry)[8]) const {
        __m256 entry = _mm256_set1_ps(t_min_);
        __m256 exit = _mm256_set1_ps(t_max_);
        for (int axis = 0; axis < 3; ++axis) {
            const __m256 inv = _mm256_set1_ps(inv_[axis][0]);
            const __m256 t_near =
                _mm256_mul_ps(_mm256_sub_ps(_mm256_loadu_ps(bounds[near_[axis]]), _mm256_set1_ps(origin_entry_[axis][0])), inv);
            const __m256 t_far =
                _mm256_mul_ps(_mm256_sub_ps(_mm256_loadu_ps(bounds[far_[axis]]), _mm256_set1_ps(origin_exit_[axis][0])), inv);
            entry = _mm256_max_ps(entry, t_near); // a NaN keeps _mm_max_ps's rule (the second operand wins): the same bits
            exit = _mm256_min_ps(exit, t_far);
        }
        _mm256_storeu_ps(t_entry, entry);
        return static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(entry, exit, _CMP_LE_OQ)));
    }
#endif

  private:
    friend class RayPacket; // bundles the per-ray numbers of several rays

    // e such that x = m 2^e with m in [0.5, 1); 0 for 0, infinities and NaN.
    static int binary_exponent(double x) {
        const auto biased = static_cast<int>(std::bit_cast<std::uint64_t>(x) >> 52 & 0x7ff);
        if (biased == 0x7ff || x == 0.0) return 0;
        if (biased == 0) {
            int e = 0;
            std::frexp(x, &e); // subnormal: rare, let the library count
            return e;
        }
        return biased - 1022;
    }
    // 2^k, by its bit pattern when it is a normal double (std::ldexp is a library call).
    static double power_of_two(int k) {
        if (k < -1022 || k > 1023) return std::ldexp(1.0, k);
        return std::bit_cast<double>(static_cast<std::uint64_t>(k + 1023) << 52);
    }
    // The float nearest t on the side of -infinity (round_down) or +infinity
    // (round_up). Whether the conversion rounded the wrong way is a coin toss
    // from ray to ray, so the step to the neighbouring float is taken by
    // arithmetic on its bits, without a branch (std::nextafter is a library call).
    static float round_down(double t) {
        if (t < -std::numeric_limits<float>::max()) return -std::numeric_limits<float>::infinity();
        if (t > std::numeric_limits<float>::max()) return std::numeric_limits<float>::max();
        const float f = static_cast<float>(t);
        const std::int32_t rounded_up = static_cast<double>(f) > t; // 1: step to the float below
        // The float below 0 (either sign) is the one after -0; a negative float's bits grow downwards.
        const std::int32_t bits = std::bit_cast<std::int32_t>(f) | (kSignBit & -((f == 0.0f) & rounded_up));
        return std::bit_cast<float>(bits + (-((bits >> 31) | 1) & -rounded_up));
    }
    static float round_up(double t) {
        if (t > std::numeric_limits<float>::max()) return std::numeric_limits<float>::infinity();
        if (t < -std::numeric_limits<float>::max()) return -std::numeric_limits<float>::max();
        const float f = static_cast<float>(t);
        const std::int32_t rounded_down = static_cast<double>(f) < t; // 1: step to the float above
        // The float above 0 (either sign) is the one after +0.
        const std::int32_t bits = std::bit_cast<std::int32_t>(f) & ~(kSignBit & -((f == 0.0f) & rounded_down));
        return std::bit_cast<float>(bits + (((bits >> 31) | 1) & -rounded_down));
    }
    static constexpr std::int32_t kSignBit = std::numeric_limits<std::int32_t>::min();

    // Per axis, repeated in four lanes for the four-box test.
    alignas(16) float inv_[3][4];
    alignas(16) float origin_entry_[3][4];
    alignas(16) float origin_exit_[3][4];
    int near_[3], far_[3];
    double inverse_scale_ = 1.0; // 2^exponent: distances in the scaled ray's units are t * inverse_scale_
    float t_min_;
    mutable float t_max_;
};

} // namespace whitted
