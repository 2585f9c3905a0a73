// Bundling rays for the packet walk: each ray's WideRay numbers, side by side,
// and the ranges they span.
#include "whitted/engine/ray_packet.hpp"

#include <algorithm>
#include <cassert>
#include <limits>

namespace whitted {

RayPacket::RayPacket(std::span<const Ray> rays, std::span<const Interval> t_ranges, double extent) {
    assert(rays.size() == t_ranges.size() && rays.size() <= static_cast<std::size_t>(kMaxRays));
    constexpr float kInf = std::numeric_limits<float>::infinity();
    // Lanes without a ray: an empty range, which no box test passes.
    std::fill(std::begin(t_min_), std::end(t_min_), kInf);
    std::fill(std::begin(t_max_), std::end(t_max_), -kInf);
    for (int axis = 0; axis < 3; ++axis) {
        std::fill(std::begin(inv_[axis]), std::end(inv_[axis]), 1.0f);
        std::fill(std::begin(origin_entry_[axis]), std::end(origin_entry_[axis]), 0.0f);
        std::fill(std::begin(origin_exit_[axis]), std::end(origin_exit_[axis]), 0.0f);
    }
    const int count = static_cast<int>(rays.size());
    active_ = count == kMaxRays ? 0xffffu : (1u << count) - 1u;
    coherent_ = count > 0;
    for (int i = 0; i < count; ++i) {
        const WideRay wide(rays[i], extent, t_ranges[i].min, t_ranges[i].max);
        if (i == 0) {
            inverse_scale_ = wide.inverse_scale_;
            for (int axis = 0; axis < 3; ++axis) {
                near_[axis] = wide.near_[axis];
                far_[axis] = wide.far_[axis];
            }
        } else if (wide.inverse_scale_ != inverse_scale_ || !std::equal(near_, near_ + 3, wide.near_)) {
            coherent_ = false;
        }
        for (int axis = 0; axis < 3; ++axis) {
            inv_[axis][i] = wide.inv_[axis][0];
            origin_entry_[axis][i] = wide.origin_entry_[axis][0];
            origin_exit_[axis][i] = wide.origin_exit_[axis][0];
        }
        t_min_[i] = wide.t_min_;
        t_max_[i] = wide.t_max_;
    }
    if (!coherent_) return;
    t_min_low_ = *std::min_element(t_min_, t_min_ + count);
    for (int axis = 0; axis < 3; ++axis) {
        const float* inv = inv_[axis];
        inv_low_[axis] = *std::min_element(inv, inv + count);
        inv_high_[axis] = *std::max_element(inv, inv + count);
        // Positive direction: the entry distance is smallest from the farthest-along
        // origin, the exit distance largest from the least-along one; negative: the reverse.
        const bool positive = near_[axis] == 2 * axis;
        const float* entry = origin_entry_[axis];
        const float* exit = origin_exit_[axis];
        entry_origin_[axis] = positive ? *std::max_element(entry, entry + count) : *std::min_element(entry, entry + count);
        exit_origin_[axis] = positive ? *std::min_element(exit, exit + count) : *std::max_element(exit, exit + count);
    }
    refresh_t_max();
}

void RayPacket::refresh_t_max() {
    float t_max = -std::numeric_limits<float>::infinity();
    for (unsigned rays = active_; rays != 0; rays &= rays - 1) t_max = std::max(t_max, t_max_[__builtin_ctz(rays)]);
    t_max_hi_ = t_max;
}

} // namespace whitted
