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
    if (!lanes_at_once(rays, extent)) lanes_one_by_one(rays, extent);
    if (!coherent_) return;
    constexpr float kInf = std::numeric_limits<float>::infinity();
    for (int i = 0; i < kMaxRays; ++i) {
        if (i >= count) { // a lane without a ray: an empty range, which no box test passes
            t_min_[i] = kInf;
            t_max_[i] = -kInf;
            for (int axis = 0; axis < 3; ++axis) inv_[axis][i] = 1.0f, origin_entry_[axis][i] = origin_exit_[axis][i] = 0.0f;
            continue;
        }
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
    refresh_t_max();
}

void RayPacket::lanes_one_by_one(std::span<const Ray> rays, double extent) {
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const WideRay::Numbers n = WideRay::numbers(rays[i], extent, 0.0, 0.0);
        if (i == 0) inverse_scale_ = n.inverse_scale;
        if (n.inverse_scale != inverse_scale_) coherent_ = false; // distances in other units
        for (int axis = 0; axis < 3; ++axis) {
            inv_[axis][i] = n.inv[axis];
            origin_entry_[axis][i] = n.origin_entry[axis];
            origin_exit_[axis][i] = n.origin_exit[axis];
        }
    }
}

bool RayPacket::lanes_at_once(std::span<const Ray> rays, double extent) {
#if defined(__SSE2__) && defined(__SSE2_MATH__) && __FLT_EVAL_METHOD__ == 0 // WideRay::numbers() in SSE2 doubles too
    // WideRay::numbers() for four rays at a time, the same operations in the same
    // order (so the same numbers), when every ray's largest direction component
    // has ray 0's binary exponent, the one scale of the packet, and is an
    // ordinary number (zero, subnormal, infinite and NaN rays go one by one).
    const int count = static_cast<int>(rays.size());
    const __m128d sign_bit = _mm_set1_pd(-0.0);
    const auto largest_bits = [&](const Ray& ray) {
        return std::bit_cast<std::uint64_t>(std::max({std::abs(ray.direction.x), std::abs(ray.direction.y), std::abs(ray.direction.z)})) >> 52;
    };
    const std::uint64_t biased = largest_bits(rays[0]);
    if (biased < 2 || biased > 2042) return false; // zero, subnormal, infinite, or clamped by WideRay::numbers()
    for (int i = 1; i < count; ++i)
        if (largest_bits(rays[i]) != biased) return false;
    for (const Ray& ray : rays)
        for (int axis = 0; axis < 3; ++axis)
            if (std::isnan(ray.direction[axis]) || std::isnan(ray.origin[axis])) return false;
    const int exponent = static_cast<int>(biased) - 1022;
    inverse_scale_ = WideRay::power_of_two(exponent);
    const __m128d scale = _mm_set1_pd(WideRay::power_of_two(-exponent));
    const __m128d tiny = _mm_set1_pd(0x1p-62);
    const __m128d extent_share = _mm_set1_pd(0x1p-58 * extent);
    for (int first = 0; first < count; first += 4) {
        // Lanes past the last ray repeat it; the constructor empties them afterwards.
        const Ray& r0 = rays[first];
        const Ray& r1 = rays[std::min(first + 1, count - 1)];
        const Ray& r2 = rays[std::min(first + 2, count - 1)];
        const Ray& r3 = rays[std::min(first + 3, count - 1)];
        __m128d origin_01[3], origin_23[3];
        for (int axis = 0; axis < 3; ++axis) {
            origin_01[axis] = _mm_set_pd(r1.origin[axis], r0.origin[axis]);
            origin_23[axis] = _mm_set_pd(r3.origin[axis], r2.origin[axis]);
        }
        const auto margin = [&](const __m128d (&origin)[3]) {
            const __m128d size = _mm_max_pd(_mm_max_pd(_mm_andnot_pd(sign_bit, origin[0]), _mm_andnot_pd(sign_bit, origin[1])),
                                            _mm_andnot_pd(sign_bit, origin[2]));
            return _mm_add_pd(_mm_add_pd(_mm_mul_pd(_mm_set1_pd(0x1p-20), size), extent_share), _mm_set1_pd(1e-30));
        };
        const __m128d margin_01 = margin(origin_01), margin_23 = margin(origin_23);
        for (int axis = 0; axis < 3; ++axis) {
            const auto scaled = [&](double a, double b) {
                const __m128d d = _mm_mul_pd(_mm_set_pd(b, a), scale);
                const __m128d too_small = _mm_cmpnge_pd(_mm_andnot_pd(sign_bit, d), tiny);
                const __m128d replacement = _mm_or_pd(_mm_and_pd(d, sign_bit), tiny);
                return _mm_or_pd(_mm_and_pd(too_small, replacement), _mm_andnot_pd(too_small, d));
            };
            const __m128 d = _mm_movelh_ps(_mm_cvtpd_ps(scaled(r0.direction[axis], r1.direction[axis])),
                                           _mm_cvtpd_ps(scaled(r2.direction[axis], r3.direction[axis])));
            _mm_store_ps(inv_[axis] + first, _mm_div_ps(_mm_set1_ps(1.0f), d));
            // Entry: origin moved along the ray by the margin; exit: moved back.
            const bool negative = near_[axis] != 2 * axis;
            const __m128d shift_01 = negative ? _mm_xor_pd(margin_01, sign_bit) : margin_01;
            const __m128d shift_23 = negative ? _mm_xor_pd(margin_23, sign_bit) : margin_23;
            _mm_store_ps(origin_entry_[axis] + first, _mm_movelh_ps(_mm_cvtpd_ps(_mm_add_pd(origin_01[axis], shift_01)),
                                                                    _mm_cvtpd_ps(_mm_add_pd(origin_23[axis], shift_23))));
            _mm_store_ps(origin_exit_[axis] + first, _mm_movelh_ps(_mm_cvtpd_ps(_mm_sub_pd(origin_01[axis], shift_01)),
                                                                   _mm_cvtpd_ps(_mm_sub_pd(origin_23[axis], shift_23))));
        }
    }
    return true;
#else
    (void)rays, (void)extent;
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
    for (unsigned rays = active_; rays != 0; rays &= rays - 1) t_max = std::max(t_max, t_max_[__builtin_ctz(rays)]);
    t_max_hi_ = t_max;
}

} // namespace whitted
