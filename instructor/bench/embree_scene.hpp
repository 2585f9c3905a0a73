// Our scene as an Embree 3 scene, answering the two ray queries of a ray
// tracer (closest hit, occlusion) with Embree's kernels.
//
// Why: `make bench` needs an upper bound for the renderer's ray traversal: the
// same rays, shot into one of the fastest CPU ray tracing libraries. Triangles
// and spheres use Embree's own primitives (float precision, as Embree works);
// boxes and cones are Embree user geometry calling the framework's own double
// precision routines; infinite planes cannot go into a bounding volume
// hierarchy, so they are tested first, outside Embree, as our Scene does.
// A hit is reported as the framework's `Hit`, normals facing the ray, so the
// ray tree above it is written exactly as the labs write it.
#pragma once

#include "ray_queries.hpp"

#include "whitted/hit.hpp"
#include "whitted/scene.hpp"

#include <embree3/rtcore.h>

#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace whitted::bench {

/// The first error an Embree device reported (its error callback writes here).
struct EmbreeErrors {
    std::mutex mutex;
    std::string first;
};

struct EmbreeSettings {
    int build_threads = 0;                          // threads for rtcCommitScene (0: Embree's default)
    RTCBuildQuality quality = RTC_BUILD_QUALITY_HIGH;
};

class EmbreeScene final : public RayQueries {
  public:
    /// Builds the Embree scene over `data`'s primitives (which must outlive it). Throws std::runtime_error.
    EmbreeScene(const SceneData& data, const EmbreeSettings& settings);
    ~EmbreeScene() override;
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    /// The nearest surface along the ray with 0 < t, as a framework Hit (normals facing the ray).
    std::optional<Hit> closest_hit(const Ray& ray) const override;

    /// The nearest hits of up to 16 coherent rays (eye rays of a 4 x 4 block) in one
    /// rtcIntersect16 packet query; hits[i] answers rays[i] for i < count.
    void closest_hits16(const Ray* rays, int count, std::optional<Hit>* hits) const override;

    /// True when a surface lies along the ray with 0 < t < t_max.
    bool occluded(const Ray& ray, double t_max) const override;

    /// Wall-clock seconds that rtcCommitScene (the BVH build) took.
    double build_seconds() const { return build_seconds_; }

    /// "embree 3.13.5", from the library itself.
    static std::string version();

  private:
    Hit surface_hit(const Ray& ray, const RTCRayHit& ray_hit) const;
    void build(const EmbreeSettings& settings);
    [[noreturn]] void fail(const std::string& fallback);

    const SceneData& data_;
    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    unsigned triangle_geometry_ = RTC_INVALID_GEOMETRY_ID;
    unsigned sphere_geometry_ = RTC_INVALID_GEOMETRY_ID;
    unsigned user_geometry_ = RTC_INVALID_GEOMETRY_ID;
    // Embree primID -> index into data_.primitives, per geometry.
    std::vector<std::uint32_t> triangles_, spheres_, user_;
    std::vector<Shape> user_shapes_;        // boxes and cones, in user primID order (the callbacks read them)
    std::vector<std::uint32_t> planes_;     // infinite planes, tested outside Embree
    double build_seconds_ = 0.0;
    EmbreeErrors errors_;
};

} // namespace whitted::bench
