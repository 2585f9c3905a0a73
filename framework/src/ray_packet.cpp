// Bundling rays for the packet walk: each ray's WideRay numbers, side by side,
// and the ranges they span.
#include "whitted/engine/ray_packet.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cassert>
#include <cmath>
#include <limits>

namespace whitted {
namespace {

// The smallest (or, kHighest, the largest) of values[0..count) (16-byte aligned), four at a time.
template <bool kHighest>
float extreme(const float* values, int count) {
    const auto pick = [](float a, float b) { return kHighest ? std::max(a, b) : std::min(a, b); };
    float found = values[0];
    int i = 0;
#if defined(__SSE2__)
    if (count >= 4) {
        __m128 four = _mm_load_ps(values);
        for (i = 4; i + 4 <= count; i += 4)
            four = kHighest ? _mm_max_ps(four, _mm_load_ps(values + i)) : _mm_min_ps(four, _mm_load_ps(values + i));
        alignas(16) float lanes[4];
        _mm_store_ps(lanes, four);
        found = pick(pick(lanes[0], lanes[1]), pick(lanes[2], lanes[3]));
    }
#endif
    for (; i < count; ++i) found = pick(found, values[i]);
    return found;
}
float lowest(const float* values, int count) { return extreme<false>(values, count); }
float highest(const float* values, int count) { return extreme<true>(values, count); }

} // namespace

RayPacket::RayPacket(std::span<const Ray> rays, std::span<const Interval> t_ranges, double extent) {
    assert(rays.size() == t_ranges.size() && rays.size() <= static_cast<std::size_t>(kMaxRays));
    const int count = static_cast<int>(rays.size());
    active_ = count == kMaxRays ? 0xffffu : (1u << count) - 1u;
    coherent_ = count > 0;
    // Rays that go different ways on an axis cannot share a test: found before any
    // other work (WideRay makes a component of -0 or +0 a tiny one of its sign).
    const auto signs = [](const Vec3& d) {
        return static_cast<unsigned>(std::signbit(d.x)) | static_cast<unsigned>(std::signbit(d.y)) << 1 |
               static_cast<unsigned>(std::signbit(d.z)) << 2;
    };
    const unsigned signs_0 = coherent_ ? signs(rays[0].direction) : 0u;
    for (int i = 1; i < count && coherent_; ++i) coherent_ = signs(rays[i].direction) == signs_0;
    if (!coherent_) return;
    for (int axis = 0; axis < 3; ++axis) {
        const bool negative = (signs_0 >> axis & 1u) != 0;
        near_[axis] = 2 * axis + (negative ? 1 : 0);
        far_[axis] = 2 * axis + (negative ? 0 : 1);
    }
    if (!lanes_at_once(rays, t_ranges, extent)) {
        lanes_one_by_one(rays, extent);
        if (!coherent_) return;
        for (int i = 0; i < count; ++i) {
            t_min_[i] = WideRay::round_down(t_ranges[i].min * inverse_scale_);
            t_max_[i] = WideRay::round_up(t_ranges[i].max * inverse_scale_);
        }
        // The packet's ranges, over the lanes that hold a ray.
        t_min_low_ = lowest(t_min_, count);
        for (int axis = 0; axis < 3; ++axis) {
            inv_low_[axis] = lowest(inv_[axis], count);
            inv_high_[axis] = highest(inv_[axis], count);
            // Positive direction: the entry distance is smallest from the farthest-along
            // origin, the exit distance largest from the least-along one; negative: the reverse.
            const bool positive = near_[axis] == 2 * axis;
            entry_origin_[axis] = positive ? highest(origin_entry_[axis], count) : lowest(origin_entry_[axis], count);
            exit_origin_[axis] = positive ? lowest(origin_exit_[axis], count) : highest(origin_exit_[axis], count);
        }
    }
    constexpr float kInf = std::numeric_limits<float>::infinity();
    for (int i = count; i < kMaxRays; ++i) { // a lane without a ray: an empty range, which no box test passes
        t_min_[i] = kInf;
        t_max_[i] = -kInf;
        for (int axis = 0; axis < 3; ++axis) inv_[axis][i] = 1.0f, origin_entry_[axis][i] = origin_exit_[axis][i] = 0.0f;
    }
    refresh_t_max();
}

void RayPacket::lanes_one_by_one(std::span<const Ray> rays, double extent) {
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const WideRay::Numbers n = WideRay::numbers(rays[i], extent, 0.0, 0.0);
        if (i == 0) inverse_scale_ = n.inverse_scale;
        if (n.inverse_scale != inverse_scale_) coherent_ = false; // distances in other units
        for (int axis = 0; axis < 3; ++axis) {
            // An infinite origin moved by an infinite margin: a NaN would make the packet miss every box.
            if (std::isnan(n.origin_entry[axis]) || std::isnan(n.origin_exit[axis])) coherent_ = false;
            inv_[axis][i] = n.inv[axis];
            origin_entry_[axis][i] = n.origin_entry[axis];
            origin_exit_[axis][i] = n.origin_exit[axis];
        }
    }
}

#if defined(__SSE2__) && defined(__SSE2_MATH__) && __FLT_EVAL_METHOD__ == 0
namespace {

// Four doubles (two pairs) to floats, as WideRay::round_down (kUp false) or
// WideRay::round_up (kUp true) round each: to nearest, then one step outwards
// where that went the wrong way, by arithmetic on the bits (see there).
template <bool kUp>
__m128 round_outwards(__m128d t_01, __m128d t_23) {
    const __m128 f = _mm_movelh_ps(_mm_cvtpd_ps(t_01), _mm_cvtpd_ps(t_23));
    const auto wrong_way = [](__m128d t, __m128d back) { return kUp ? _mm_cmplt_pd(back, t) : _mm_cmpgt_pd(back, t); };
    const __m128d wrong_01 = wrong_way(t_01, _mm_cvtps_pd(f)), wrong_23 = wrong_way(t_23, _mm_cvtps_pd(_mm_movehl_ps(f, f)));
    // Each double lane's mask is all ones or all zeros: its low halves make four float lanes.
    const __m128i wrong = _mm_castps_si128(_mm_shuffle_ps(_mm_castpd_ps(wrong_01), _mm_castpd_ps(wrong_23), _MM_SHUFFLE(2, 0, 2, 0)));
    __m128i bits = _mm_castps_si128(f);
    // Up: +1 for a positive float, -1 for a negative one; down: the reverse. (The
    // conversion keeps t's sign, so a zero that went the wrong way has it too,
    // and steps away from zero as round_down and round_up step it.)
    const __m128i away_from_zero = _mm_or_si128(_mm_srai_epi32(bits, 31), _mm_set1_epi32(1));
    const __m128i step = kUp ? away_from_zero : _mm_sub_epi32(_mm_setzero_si128(), away_from_zero);
    bits = _mm_add_epi32(bits, _mm_and_si128(step, wrong));
    // The one case the steps do not give: an infinity on the inner side ends at the largest float.
    const __m128d inner = _mm_set1_pd(kUp ? -kInfinity : kInfinity);
    const __m128 at_inner = _mm_shuffle_ps(_mm_castpd_ps(_mm_cmpeq_pd(t_01, inner)), _mm_castpd_ps(_mm_cmpeq_pd(t_23, inner)),
                                           _MM_SHUFFLE(2, 0, 2, 0));
    const __m128 largest = _mm_set1_ps(kUp ? -std::numeric_limits<float>::max() : std::numeric_limits<float>::max());
    return _mm_or_ps(_mm_and_ps(at_inner, largest), _mm_andnot_ps(at_inner, _mm_castsi128_ps(bits)));
}

// The smallest (lowest_lane) or the largest (highest_lane) of the four floats.
float lowest_lane(__m128 v) {
    v = _mm_min_ps(v, _mm_movehl_ps(v, v));
    return _mm_cvtss_f32(_mm_min_ss(v, _mm_shuffle_ps(v, v, _MM_SHUFFLE(1, 1, 1, 1))));
}
float highest_lane(__m128 v) {
    v = _mm_max_ps(v, _mm_movehl_ps(v, v));
    return _mm_cvtss_f32(_mm_max_ss(v, _mm_shuffle_ps(v, v, _MM_SHUFFLE(1, 1, 1, 1))));
}

} // namespace
#endif

bool RayPacket::lanes_at_once(std::span<const Ray> rays, std::span<const Interval> t_ranges, double extent) {
#if defined(__SSE2__) && defined(__SSE2_MATH__) && __FLT_EVAL_METHOD__ == 0 // WideRay::numbers() in SSE2 doubles too
    // WideRay::numbers() for four rays at a time, the same operations in the same
    // order (so the same numbers), when every ray's largest direction component
    // has ray 0's binary exponent, the one scale of the packet, and is an
    // ordinary number (zero, subnormal, infinite and NaN rays, infinite
    // origins and NaN range ends go one by one); the packet's ranges are gathered on the way.
    const int count = static_cast<int>(rays.size());
    const __m128d sign_bit = _mm_set1_pd(-0.0);
    const Vec3& d0 = rays[0].direction;
    const auto biased = static_cast<int>(std::bit_cast<std::uint64_t>(std::max({std::abs(d0.x), std::abs(d0.y), std::abs(d0.z)})) >> 52);
    if (biased < 2 || biased > 2042) return false; // zero, subnormal, infinite, or clamped by WideRay::numbers()
    const int exponent = biased - 1022;
    inverse_scale_ = WideRay::power_of_two(exponent);
    const __m128d scale = _mm_set1_pd(WideRay::power_of_two(-exponent));
    const __m128d inverse_scale = _mm_set1_pd(inverse_scale_);
    const __m128d tiny = _mm_set1_pd(0x1p-62);
    const __m128d extent_share = _mm_set1_pd(0x1p-58 * extent);
    const __m128i biased_lanes = _mm_set_epi32(0, biased, 0, biased); // a 64-bit lane's top 12 bits, shifted down
    __m128d odd = _mm_setzero_pd();  // a lane with a NaN
    __m128 odd_origin = _mm_setzero_ps(); // a NaN from an infinite origin moved by its infinite margin
    __m128i same = _mm_set1_epi32(-1); // lanes whose largest component has ray 0's exponent
    constexpr float kInf = std::numeric_limits<float>::infinity();
    __m128 t_min_low = _mm_set1_ps(kInf);
    __m128 inv_low[3], inv_high[3], entry_origin[3], exit_origin[3];
    for (int axis = 0; axis < 3; ++axis) {
        inv_low[axis] = _mm_set1_ps(kInf);
        inv_high[axis] = _mm_set1_ps(-kInf);
        entry_origin[axis] = _mm_set1_ps(near_[axis] == 2 * axis ? -kInf : kInf);
        exit_origin[axis] = _mm_set1_ps(near_[axis] == 2 * axis ? kInf : -kInf);
    }
    for (int first = 0; first < count; first += 4) {
        // Lanes past the last ray repeat it; the constructor empties them afterwards.
        const int i1 = std::min(first + 1, count - 1), i2 = std::min(first + 2, count - 1), i3 = std::min(first + 3, count - 1);
        const Ray &r0 = rays[first], &r1 = rays[i1], &r2 = rays[i2], &r3 = rays[i3];
        __m128d origin_01[3], origin_23[3], direction_01[3], direction_23[3];
        for (int axis = 0; axis < 3; ++axis) {
            origin_01[axis] = _mm_set_pd(r1.origin[axis], r0.origin[axis]);
            origin_23[axis] = _mm_set_pd(r3.origin[axis], r2.origin[axis]);
            direction_01[axis] = _mm_set_pd(r1.direction[axis], r0.direction[axis]);
            direction_23[axis] = _mm_set_pd(r3.direction[axis], r2.direction[axis]);
            odd = _mm_or_pd(odd, _mm_or_pd(_mm_cmpunord_pd(origin_01[axis], direction_01[axis]),
                                           _mm_cmpunord_pd(origin_23[axis], direction_23[axis])));
        }
        const auto largest_exponent = [&](const __m128d (&d)[3]) {
            const __m128d largest = _mm_max_pd(_mm_max_pd(_mm_andnot_pd(sign_bit, d[0]), _mm_andnot_pd(sign_bit, d[1])),
                                               _mm_andnot_pd(sign_bit, d[2]));
            return _mm_cmpeq_epi32(_mm_srli_epi64(_mm_castpd_si128(largest), 52), biased_lanes);
        };
        same = _mm_and_si128(same, _mm_and_si128(largest_exponent(direction_01), largest_exponent(direction_23)));
        const auto margin = [&](const __m128d (&origin)[3]) {
            const __m128d size = _mm_max_pd(_mm_max_pd(_mm_andnot_pd(sign_bit, origin[0]), _mm_andnot_pd(sign_bit, origin[1])),
                                            _mm_andnot_pd(sign_bit, origin[2]));
            return _mm_add_pd(_mm_add_pd(_mm_mul_pd(_mm_set1_pd(0x1p-20), size), extent_share), _mm_set1_pd(1e-30));
        };
        const __m128d margin_01 = margin(origin_01), margin_23 = margin(origin_23);
        for (int axis = 0; axis < 3; ++axis) {
            const auto scaled = [&](__m128d direction) {
                const __m128d d = _mm_mul_pd(direction, scale);
                const __m128d too_small = _mm_cmpnge_pd(_mm_andnot_pd(sign_bit, d), tiny);
                const __m128d replacement = _mm_or_pd(_mm_and_pd(d, sign_bit), tiny);
                return _mm_or_pd(_mm_and_pd(too_small, replacement), _mm_andnot_pd(too_small, d));
            };
            const __m128 d = _mm_movelh_ps(_mm_cvtpd_ps(scaled(direction_01[axis])), _mm_cvtpd_ps(scaled(direction_23[axis])));
            const __m128 inv = _mm_div_ps(_mm_set1_ps(1.0f), d);
            _mm_store_ps(inv_[axis] + first, inv);
            // Entry: origin moved along the ray by the margin; exit: moved back.
            const bool negative = near_[axis] != 2 * axis;
            const __m128d shift_01 = negative ? _mm_xor_pd(margin_01, sign_bit) : margin_01;
            const __m128d shift_23 = negative ? _mm_xor_pd(margin_23, sign_bit) : margin_23;
            const __m128 entry = _mm_movelh_ps(_mm_cvtpd_ps(_mm_add_pd(origin_01[axis], shift_01)),
                                               _mm_cvtpd_ps(_mm_add_pd(origin_23[axis], shift_23)));
            const __m128 exit = _mm_movelh_ps(_mm_cvtpd_ps(_mm_sub_pd(origin_01[axis], shift_01)),
                                              _mm_cvtpd_ps(_mm_sub_pd(origin_23[axis], shift_23)));
            _mm_store_ps(origin_entry_[axis] + first, entry);
            _mm_store_ps(origin_exit_[axis] + first, exit);
            odd_origin = _mm_or_ps(odd_origin, _mm_cmpunord_ps(entry, exit));
            // The packet's ranges. Positive direction: the entry distance is smallest from the
            // farthest-along origin, the exit distance largest from the least-along one; negative: the reverse.
            inv_low[axis] = _mm_min_ps(inv_low[axis], inv);
            inv_high[axis] = _mm_max_ps(inv_high[axis], inv);
            entry_origin[axis] = negative ? _mm_min_ps(entry_origin[axis], entry) : _mm_max_ps(entry_origin[axis], entry);
            exit_origin[axis] = negative ? _mm_max_ps(exit_origin[axis], exit) : _mm_min_ps(exit_origin[axis], exit);
        }
        // The range in the scaled ray's units, rounded outwards.
        const Interval &t0 = t_ranges[first], &t1 = t_ranges[i1], &t2 = t_ranges[i2], &t3 = t_ranges[i3];
        const __m128d t_min_01 = _mm_set_pd(t1.min, t0.min), t_min_23 = _mm_set_pd(t3.min, t2.min);
        const __m128d t_max_01 = _mm_set_pd(t1.max, t0.max), t_max_23 = _mm_set_pd(t3.max, t2.max);
        odd = _mm_or_pd(odd, _mm_or_pd(_mm_cmpunord_pd(t_min_01, t_max_01), _mm_cmpunord_pd(t_min_23, t_max_23)));
        const __m128 t_min = round_outwards<false>(_mm_mul_pd(t_min_01, inverse_scale), _mm_mul_pd(t_min_23, inverse_scale));
        _mm_store_ps(t_min_ + first, t_min);
        _mm_store_ps(t_max_ + first, round_outwards<true>(_mm_mul_pd(t_max_01, inverse_scale), _mm_mul_pd(t_max_23, inverse_scale)));
        t_min_low = _mm_min_ps(t_min_low, t_min);
    }
    if (_mm_movemask_pd(odd) != 0 || _mm_movemask_ps(odd_origin) != 0 || _mm_movemask_epi8(same) != 0xffff) return false;
    t_min_low_ = lowest_lane(t_min_low);
    for (int axis = 0; axis < 3; ++axis) {
        inv_low_[axis] = lowest_lane(inv_low[axis]);
        inv_high_[axis] = highest_lane(inv_high[axis]);
        const bool negative = near_[axis] != 2 * axis;
        entry_origin_[axis] = negative ? lowest_lane(entry_origin[axis]) : highest_lane(entry_origin[axis]);
        exit_origin_[axis] = negative ? highest_lane(exit_origin[axis]) : lowest_lane(exit_origin[axis]);
    }
    return true;
#else
    (void)rays, (void)t_ranges, (void)extent;
    return false;
#endif
}

WideRay::Numbers RayPacket::lane(int i) const {
    WideRay::Numbers n{};
    for (int axis = 0; axis < 3; ++axis) {
        n.inv[axis] = inv_[axis][i];
        n.origin_entry[axis] = origin_entry_[axis][i];
        n.origin_exit[axis] = origin_exit_[axis][i];
        n.negative[axis] = near_[axis] != 2 * axis;
    }
    n.inverse_scale = inverse_scale_;
    n.t_min = t_min_[i];
    n.t_max = t_max_[i];
    return n;
}

void RayPacket::refresh_t_max() {
    float t_max = -std::numeric_limits<float>::infinity();
    for (unsigned rays = active_; rays != 0; rays &= rays - 1) t_max = std::max(t_max, t_max_[std::countr_zero(rays)]);
    t_max_hi_ = t_max;
}

} // namespace whitted
