// The ray traffic of a whitted render, without the shading: the same eye,
// shadow, reflected and refracted rays, shot into an EmbreeScene (or into
// whitted's own Scene, through the same RayQueries interface).
//
// Why: `make bench` compares the renderer with the fastest traversal it could
// hope for. That comparison is fair only when both shoot exactly the same ray
// tree, so this follows stage 6 of `whitted render` with --min-weight 0 step by
// step (tracer.cpp and the reference labs): one eye ray per pixel centre; at
// every hit one shadow feeler per light in front of the surface; below the
// maximum depth, a Fresnel pair (reflected always, refracted unless totally
// reflected) on transparent materials, else a reflected ray when Ks > 0. Only
// the colours are left out. Pixels are split into the same 16 x 16 tiles over
// the same kind of threads as render.cpp.
#pragma once

#include "embree_scene.hpp"

#include <cstdint>

namespace whitted::bench {

/// Rays shot, by kind (the same kinds as whitted's RayStats).
struct RayCounts {
    std::uint64_t eye = 0;
    std::uint64_t shadow = 0;
    std::uint64_t reflected = 0;
    std::uint64_t refracted = 0;

    std::uint64_t total() const { return eye + shadow + reflected + refracted; }
};

struct TrafficResult {
    RayCounts rays;
    double seconds = 0.0; // wall clock of the whole image
    int threads = 1;
};

/// Shoots the whole image's ray tree (camera, lights and materials from `data`)
/// into `scene` (Embree's or whitted's) with `threads` threads (0: one per hardware thread); the eye ray
/// is depth 1. With `eye_packets`, the eye rays of each 4 x 4 pixel block go to
/// Embree as one coherent packet (rtcIntersect16); every other ray goes alone.
TrafficResult shoot_ray_traffic(const RayQueries& scene, const SceneData& data, int max_depth, int threads,
                                bool eye_packets = false);

} // namespace whitted::bench
