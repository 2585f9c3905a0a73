// Up to sixteen rays that walk the wide BVH together, and their box tests.
//
// Why: the eye rays of neighbouring pixels, and the shadow feelers from their
// hits towards one light, meet nearly the same boxes. A packet tests each box
// once for all its rays, with interval arithmetic: the rays' origins and
// reciprocal directions lie in small ranges, and the box's entry distance is at
// least the smallest one those ranges allow, its exit distance at most the
// largest. Near the root, where every ray meets every box, that one test does
// the work of sixteen. Only at a leaf's box is each ray tested alone (as
// WideRay does it, four rays at a time), so that only the rays that may meet
// the leaf test its primitives.
//
// Conservative, like WideRay: rounding to nearest never decreases when its
// argument grows, so the interval test computed in float is at most each ray's
// own float entry distance (and at least its exit), which WideRay already keeps
// on the side of "hit". A packet may visit a box no ray of it meets; it never
// skips one that any of its rays' exact tests would enter. The rays must share
// the signs of their direction components and the power of two WideRay scales
// them by, and have finite origins (`coherent()`); the leaf kernels trace the
// others one by one.
#pragma once

#include "whitted/engine/wide_ray.hpp"
#include "whitted/interval.hpp"

#include <span>

namespace whitted {

class RayPacket {
  public:
    static constexpr int kMaxRays = 16;

    /// Prepares rays[i] for t in t_ranges[i] (at most kMaxRays rays), for the boxes of a WideBvh of `extent`.
    RayPacket(std::span<const Ray> rays, std::span<const Interval> t_ranges, double extent);

    /// True when the rays may walk together (same direction signs and scale, finite origins).
    bool coherent() const { return coherent_; }
    /// Lane i's numbers, which are WideRay::numbers() of rays[i] (of a coherent packet; for tests).
    WideRay::Numbers lane(int i) const;
    /// The rays still searching, one bit each.
    unsigned active() const { return active_; }
    /// Ends the search of `rays` (bits): an occlusion query that found its answer.
    void retire(unsigned rays) {
        active_ &= ~rays;
        refresh_t_max();
    }
    /// Lowers ray i's far end after a hit at t (in the ray's own units); call refresh_t_max() after a batch.
    void shrink(int i, double t) { t_max_[i] = WideRay::round_up(t * inverse_scale_); }
    /// Recomputes the packet's far end: the farthest of its active rays'.
    void refresh_t_max();
    /// The packet's far end: no active ray searches beyond it.
    float t_max() const { return t_max_hi_; }

    /// The packet's test of side-by-side boxes (bounds[6][kBoxes] as in
    /// WideBvh::Node): a bit per box some ray may meet, and a distance no ray
    /// enters it before.
    template <int kBoxes>
    unsigned hit_boxes(const float (&bounds)[6][kBoxes], float (&t_entry)[kBoxes]) const;

    /// Which of `rays` (bits) may meet box `slot` of `bounds`: each ray's own test.
    template <int kBoxes>
    unsigned rays_meeting(const float (&bounds)[6][kBoxes], int slot, unsigned rays) const;

#if WHITTED_AVX2_WALK
    /// hit_boxes() for eight boxes, and rays_meeting() eight rays at a time, in
    /// AVX2 (only where the CPU has it): the same operations on the same
    /// numbers, lane for lane, so the same bits and the same answers.
    [[gnu::target("avx2")]] unsigned hit_eight_boxes_avx2(const float (&bounds)[6][8], float (&t_entry)[8]) const {
        __m256 entry = _mm256_set1_ps(t_min_low_);
        __m256 exit = _mm256_set1_ps(t_max_hi_);
        for (int axis = 0; axis < 3; ++axis) {
            const __m256 low = _mm256_set1_ps(inv_low_[axis]), high = _mm256_set1_ps(inv_high_[axis]);
            const __m256 to_near = _mm256_sub_ps(_mm256_loadu_ps(bounds[near_[axis]]), _mm256_set1_ps(entry_origin_[axis]));
            const __m256 to_far = _mm256_sub_ps(_mm256_loadu_ps(bounds[far_[axis]]), _mm256_set1_ps(exit_origin_[axis]));
            entry = _mm256_max_ps(entry, _mm256_min_ps(_mm256_mul_ps(to_near, low), _mm256_mul_ps(to_near, high)));
            exit = _mm256_min_ps(exit, _mm256_max_ps(_mm256_mul_ps(to_far, low), _mm256_mul_ps(to_far, high)));
        }
        _mm256_storeu_ps(t_entry, entry);
        return static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(entry, exit, _CMP_LE_OQ)));
    }
    [[gnu::target("avx2")]] unsigned rays_meeting_avx2(const float (&bounds)[6][8], int slot, unsigned rays) const {
        static_assert(kMaxRays % 8 == 0, "rays are tested eight at a time");
        unsigned meeting = 0;
        for (int first = 0; first < kMaxRays; first += 8) {
            if (((rays >> first) & 0xffu) == 0) continue;
            __m256 entry = _mm256_loadu_ps(t_min_ + first);
            __m256 exit = _mm256_loadu_ps(t_max_ + first);
            for (int axis = 0; axis < 3; ++axis) {
                const __m256 inv = _mm256_loadu_ps(inv_[axis] + first);
                entry = _mm256_max_ps(entry, _mm256_mul_ps(_mm256_sub_ps(_mm256_set1_ps(bounds[near_[axis]][slot]),
                                                                         _mm256_loadu_ps(origin_entry_[axis] + first)), inv));
                exit = _mm256_min_ps(exit, _mm256_mul_ps(_mm256_sub_ps(_mm256_set1_ps(bounds[far_[axis]][slot]),
                                                                       _mm256_loadu_ps(origin_exit_[axis] + first)), inv));
            }
            meeting |= static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(entry, exit, _CMP_LE_OQ))) << first;
        }
        return meeting & rays;
    }
#endif

  private:
    // Each ray's WideRay numbers into its lanes and the packet's scale: one by
    // one (not t_min_, t_max_) clears coherent_ when the scales differ; at once
    // (also the ranges, its lanes' and the packet's) declines (false) rays it does not take.
    void lanes_one_by_one(std::span<const Ray> rays, double extent);
    bool lanes_at_once(std::span<const Ray> rays, std::span<const Interval> t_ranges, double extent);

    // Each ray's numbers (WideRay's, lane by lane), four rays to an SSE register.
    alignas(16) float inv_[3][kMaxRays];
    alignas(16) float origin_entry_[3][kMaxRays];
    alignas(16) float origin_exit_[3][kMaxRays];
    alignas(16) float t_min_[kMaxRays];
    alignas(16) float t_max_[kMaxRays];
    // The packet's ranges, per axis: the reciprocal directions' ends, and the
    // origins that give the smallest entry and the largest exit distances.
    float inv_low_[3], inv_high_[3], entry_origin_[3], exit_origin_[3];
    int near_[3], far_[3];
    float t_min_low_ = 0.0f, t_max_hi_ = 0.0f;
    double inverse_scale_ = 1.0;
    unsigned active_ = 0;
    bool coherent_ = true;
};

template <int kBoxes>
unsigned RayPacket::hit_boxes(const float (&bounds)[6][kBoxes], float (&t_entry)[kBoxes]) const {
    static_assert(kBoxes % 4 == 0, "boxes are tested four at a time");
    unsigned mask = 0;
    for (int first = 0; first < kBoxes; first += 4) {
#if defined(__SSE2__)
        __m128 entry = _mm_set1_ps(t_min_low_);
        __m128 exit = _mm_set1_ps(t_max_hi_);
        for (int axis = 0; axis < 3; ++axis) {
            const __m128 low = _mm_set1_ps(inv_low_[axis]), high = _mm_set1_ps(inv_high_[axis]);
            const __m128 to_near = _mm_sub_ps(_mm_load_ps(bounds[near_[axis]] + first), _mm_set1_ps(entry_origin_[axis]));
            const __m128 to_far = _mm_sub_ps(_mm_load_ps(bounds[far_[axis]] + first), _mm_set1_ps(exit_origin_[axis]));
            entry = _mm_max_ps(entry, _mm_min_ps(_mm_mul_ps(to_near, low), _mm_mul_ps(to_near, high)));
            exit = _mm_min_ps(exit, _mm_max_ps(_mm_mul_ps(to_far, low), _mm_mul_ps(to_far, high)));
        }
        _mm_storeu_ps(t_entry + first, entry);
        mask |= static_cast<unsigned>(_mm_movemask_ps(_mm_cmple_ps(entry, exit))) << first;
#else
        for (int i = first; i < first + 4; ++i) {
            float entry = t_min_low_, exit = t_max_hi_;
            for (int axis = 0; axis < 3; ++axis) {
                const float to_near = bounds[near_[axis]][i] - entry_origin_[axis];
                const float to_far = bounds[far_[axis]][i] - exit_origin_[axis];
                entry = std::max(entry, std::min(to_near * inv_low_[axis], to_near * inv_high_[axis]));
                exit = std::min(exit, std::max(to_far * inv_low_[axis], to_far * inv_high_[axis]));
            }
            t_entry[i] = entry;
            if (entry <= exit) mask |= 1u << i;
        }
#endif
    }
    return mask;
}

template <int kBoxes>
unsigned RayPacket::rays_meeting(const float (&bounds)[6][kBoxes], int slot, unsigned rays) const {
    unsigned meeting = 0;
    for (int first = 0; first < kMaxRays; first += 4) {
        if (((rays >> first) & 0xfu) == 0) continue;
#if defined(__SSE2__)
        __m128 entry = _mm_load_ps(t_min_ + first);
        __m128 exit = _mm_load_ps(t_max_ + first);
        for (int axis = 0; axis < 3; ++axis) {
            const __m128 inv = _mm_load_ps(inv_[axis] + first);
            entry = _mm_max_ps(entry, _mm_mul_ps(_mm_sub_ps(_mm_set1_ps(bounds[near_[axis]][slot]),
                                                            _mm_load_ps(origin_entry_[axis] + first)), inv));
            exit = _mm_min_ps(exit, _mm_mul_ps(_mm_sub_ps(_mm_set1_ps(bounds[far_[axis]][slot]),
                                                          _mm_load_ps(origin_exit_[axis] + first)), inv));
        }
        meeting |= static_cast<unsigned>(_mm_movemask_ps(_mm_cmple_ps(entry, exit))) << first;
#else
        for (int i = first; i < first + 4; ++i) {
            float entry = t_min_[i], exit = t_max_[i];
            for (int axis = 0; axis < 3; ++axis) {
                entry = std::max(entry, (bounds[near_[axis]][slot] - origin_entry_[axis][i]) * inv_[axis][i]);
                exit = std::min(exit, (bounds[far_[axis]][slot] - origin_exit_[axis][i]) * inv_[axis][i]);
            }
            if (entry <= exit) meeting |= 1u << i;
        }
#endif
    }
    return meeting & rays;
}

} // namespace whitted
