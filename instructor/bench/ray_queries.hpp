// The two ray queries a ray tracer asks of a scene, closest hit and occlusion,
// as an interface the benchmark's ray traffic can be shot into.
//
// Why: `make bench` compares whitted's full render with Embree's traversal of
// the same rays. To tell how much of the difference is traversal and how much
// is shading, the very same traffic is shot into whitted's own Scene too
// (whitted-embree-rays --engine whitted): then only the queries differ.
#pragma once

#include "whitted/hit.hpp"
#include "whitted/scene.hpp"

#include <optional>
#include <utility>

namespace whitted::bench {

class RayQueries {
  public:
    virtual ~RayQueries() = default;

    /// The nearest surface along the ray with 0 < t, as a framework Hit (normals facing the ray).
    virtual std::optional<Hit> closest_hit(const Ray& ray) const = 0;

    /// True when a surface lies along the ray with 0 < t < t_max.
    virtual bool occluded(const Ray& ray, double t_max) const = 0;

    /// The nearest hits of up to 16 coherent rays; hits[i] answers rays[i] for i < count.
    virtual void closest_hits16(const Ray* rays, int count, std::optional<Hit>* hits) const {
        for (int i = 0; i < count; ++i) hits[i] = closest_hit(rays[i]);
    }
};

/// whitted's own Scene, built over `data` with the given leaf kernels, behind the interface.
class SceneQueries final : public RayQueries {
  public:
    SceneQueries(SceneData data, const LeafKernels* kernels) : scene_(std::move(data), kernels) {}
    std::optional<Hit> closest_hit(const Ray& ray) const override { return scene_.closest_hit(ray); }
    bool occluded(const Ray& ray, double t_max) const override { return scene_.occluded(ray, Interval{0.0, t_max}); }

  private:
    Scene scene_;
};

} // namespace whitted::bench
