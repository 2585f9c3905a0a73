// Bundling rays for the packet walk: each ray's WideRay numbers, side by side,
// and the ranges they span.
#include "whitted/engine/ray_packet.hpp"

#include <algorithm>
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
    for (int i = 1; i < count && coherent_; ++i)
        for (int axis = 0; axis < 3; ++axis)
            if (std::signbit(rays[i].direction[axis]) != std::signbit(rays[0].direction[axis])) coherent_ = false;
    if (!coherent_) return;
    for (int axis = 0; axis < 3; ++axis) {
        const bool negative = std::signbit(rays[0].direction[axis]);
        near_[axis] = 2 * axis + (negative ? 1 : 0);
        far_[axis] = 2 * axis + (negative ? 0 : 1);
    }
    constexpr float kInf = std::numeric_limits<float>::infinity();
    for (int i = 0; i < kMaxRays; ++i) {
        if (i >= count) { // a lane without a ray: an empty range, which no box test passes
            t_min_[i] = kInf;
            t_max_[i] = -kInf;
            for (int axis = 0; axis < 3; ++axis) inv_[axis][i] = 1.0f, origin_entry_[axis][i] = origin_exit_[axis][i] = 0.0f;
            continue;
        }
        const WideRay::Numbers n = WideRay::numbers(rays[i], extent, t_ranges[i].min, t_ranges[i].max);
        if (i == 0) inverse_scale_ = n.inverse_scale;
        if (n.inverse_scale != inverse_scale_) coherent_ = false; // distances in other units
        for (int axis = 0; axis < 3; ++axis) {
            inv_[axis][i] = n.inv[axis];
            origin_entry_[axis][i] = n.origin_entry[axis];
            origin_exit_[axis][i] = n.origin_exit[axis];
        }
        t_min_[i] = n.t_min;
        t_max_[i] = n.t_max;
    }
    if (!coherent_) return;
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

void RayPacket::refresh_t_max() {
    float t_max = -std::numeric_limits<float>::infinity();
    for (unsigned rays = active_; rays != 0; rays &= rays - 1) t_max = std::max(t_max, t_max_[__builtin_ctz(rays)]);
    t_max_hi_ = t_max;
}

} // namespace whitted
