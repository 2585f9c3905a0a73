// The ray tree of stage 6 without colours, over tiles and threads.
//
// Why: each step below names the reference function it mirrors (primary_ray,
// is_lit, spawn_ray, refracted_direction, fresnel_reflectance) and repeats its
// formula rather than calling it, so the harness needs no labs and shoots the
// reference's rays whatever state the labs are in. Being those formulas, these
// files stay out of the student handout (instructor/scripts/export-handout.sh).
#include "embree_traffic.hpp"

#include "whitted/engine/tiles.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#if defined(__SSE__) || defined(__x86_64__)
#include <pmmintrin.h>
#include <xmmintrin.h>
#define WHITTED_HAVE_MXCSR 1
#endif

namespace whitted::bench {
namespace {

// How far a new ray starts off the surface, relative to the size of the hit
// point's coordinates, along the geometric normal to the side the ray leaves
// (as the reference's spawn_ray, which uses 1e-7). Hit points are placed in
// double precision (EmbreeScene::closest_hit), but the origin goes to Embree
// rounded to float, up to about 1e-7 |p| off along the normal: 3e-7 leaves a
// margin of 3. On the SPD and lab scenes this shoots the same rays as whitted
// (a few in a million differ where a reflected ray grazes a touching sphere).
constexpr double kRelativeOffset = 3e-7;

Ray spawn_ray(const Hit& hit, const Vec3& direction) {
    const double offset = kRelativeOffset * (1.0 + max_abs_component(hit.point));
    const Vec3 side = glm::dot(direction, hit.geometric_normal) >= 0.0 ? hit.geometric_normal : -hit.geometric_normal;
    return Ray{hit.point + offset * side, direction};
}

// Snell's law for wo on the side of n (as the reference's refracted_direction); nothing on total internal reflection.
std::optional<Vec3> refracted_direction(const Vec3& wo, const Vec3& n, double eta_i, double eta_t) {
    const double cos_theta_i = glm::dot(wo, n);
    const Vec3 vt = cos_theta_i * n - wo;
    const double eta = eta_i / eta_t;
    const double sin2_theta_t = eta * eta * glm::max(0.0, 1.0 - cos_theta_i * cos_theta_i);
    if (sin2_theta_t >= 1.0) return std::nullopt;
    return glm::normalize(eta * vt - std::sqrt(1.0 - sin2_theta_t) * n);
}

// The unpolarised Fresnel reflectance (as the reference's fresnel_reflectance); 1 on total internal reflection.
double fresnel_reflectance(double cos_theta_i, double eta_i, double eta_t) {
    cos_theta_i = glm::clamp(cos_theta_i, 0.0, 1.0);
    const double eta = eta_i / eta_t;
    const double sin2_theta_t = eta * eta * glm::max(0.0, 1.0 - cos_theta_i * cos_theta_i);
    if (sin2_theta_t >= 1.0) return 1.0;
    const double cos_theta_t = std::sqrt(1.0 - sin2_theta_t);
    const double rs = (eta_i * cos_theta_i - eta_t * cos_theta_t) / (eta_i * cos_theta_i + eta_t * cos_theta_t);
    const double rp = (eta_i * cos_theta_t - eta_t * cos_theta_i) / (eta_i * cos_theta_t + eta_t * cos_theta_i);
    return 0.5 * (rs * rs + rp * rp);
}

// One thread's walk through the ray trees of its pixels.
class TrafficTracer {
  public:
    TrafficTracer(const RayQueries& scene, const SceneData& data, int max_depth, RayCounts& counts)
        : scene_(scene), data_(data), max_depth_(max_depth), counts_(counts) {}

    // The eye ray through viewport point (x, y), pixels from the bottom left (as the reference's primary_ray).
    Ray eye_ray(double x, double y) const {
        const Camera& c = data_.camera;
        const Vec3 d = c.w * (x / c.res_x - 0.5) * c.xe + c.h * (y / c.res_y - 0.5) * c.ye - c.df * c.ze;
        return Ray{c.eye, glm::normalize(d)};
    }

    // The whole ray tree of one pixel.
    void trace_pixel(double x, double y) const {
        ++counts_.eye;
        trace(eye_ray(x, y), 1);
    }

    // The ray trees of the pixels of a block whose eye rays were already shot together.
    void continue_eye_rays(const Ray* rays, const std::optional<Hit>* hits, int count) const {
        for (int i = 0; i < count; ++i) {
            ++counts_.eye;
            if (hits[i]) shade(rays[i], *hits[i], 1);
        }
    }

  private:
    void trace(const Ray& ray, int depth) const {
        if (const std::optional<Hit> hit = scene_.closest_hit(ray)) shade(ray, *hit, depth);
    }

    void shade(const Ray& ray, const Hit& hit, int depth) const {
        const Material& material = data_.materials[hit.material];
        const Vec3 wo = -ray.direction;
        // Shadow feelers towards the lights in front of the surface (blinn_phong, is_lit).
        for (const PointLight& light : data_.lights) {
            const Vec3 to_light = light.position - hit.point;
            if (to_light == Vec3(0.0)) continue;
            if (glm::dot(hit.normal, glm::normalize(to_light)) <= 0.0) continue;
            // The feeler stops a millionth short of the light, as Tracer::occluded's does.
            const double distance = glm::length(to_light);
            ++counts_.shadow;
            scene_.occluded(spawn_ray(hit, to_light / distance), distance * (1.0 - 1e-6));
        }
        if (depth >= max_depth_) return;
        const Vec3 mirrored = 2.0 * glm::dot(wo, hit.normal) * hit.normal - wo;
        if (material.transmittance > 0.0) {
            // fresnel_blend: the reflected ray always, the refracted one unless Kr = 1 or total internal reflection.
            const double eta_i = hit.front_face ? 1.0 : material.ior;
            const double eta_t = hit.front_face ? material.ior : 1.0;
            const double kr = fresnel_reflectance(glm::dot(wo, hit.normal), eta_i, eta_t);
            ++counts_.reflected;
            trace(spawn_ray(hit, mirrored), depth + 1);
            if (kr < 1.0) {
                if (const std::optional<Vec3> wt = refracted_direction(wo, hit.normal, eta_i, eta_t)) {
                    ++counts_.refracted;
                    trace(spawn_ray(hit, *wt), depth + 1);
                }
            }
        } else if (material.specular > 0.0) {
            ++counts_.reflected;
            trace(spawn_ray(hit, mirrored), depth + 1);
        }
    }

    const RayQueries& scene_;
    const SceneData& data_;
    int max_depth_;
    RayCounts& counts_;
};

// Embree's advice for speed: flush denormals to zero in every thread that traces.
void set_denormals_to_zero() {
#ifdef WHITTED_HAVE_MXCSR
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
#endif
}

} // namespace

TrafficResult shoot_ray_traffic(const RayQueries& scene, const SceneData& data, int max_depth, int threads,
                                bool eye_packets) {
    const Camera& camera = data.camera;
    threads = tile_threads(camera.res_x, camera.res_y, threads);
    std::vector<PerThread<RayCounts>> counts(static_cast<std::size_t>(threads));
    const auto start = std::chrono::steady_clock::now();
    for_each_tile(camera.res_x, camera.res_y, threads, [&](int thread_index) -> TileFunction {
        set_denormals_to_zero();
        return [&, tracer = TrafficTracer(scene, data, max_depth, counts[static_cast<std::size_t>(thread_index)].value)](const Tile& tile) {
            if (!eye_packets) {
                for (int row = tile.y0; row < tile.y1; ++row) {
                    const int y = camera.res_y - 1 - row; // image rows go top-down, viewport y bottom-up
                    for (int x = tile.x0; x < tile.x1; ++x) tracer.trace_pixel(x + 0.5, y + 0.5);
                }
                return;
            }
            for (int by = tile.y0; by < tile.y1; by += 4) {
                for (int bx = tile.x0; bx < tile.x1; bx += 4) {
                    Ray rays[16];
                    std::optional<Hit> hits[16];
                    int count = 0;
                    for (int row = by; row < std::min(by + 4, tile.y1); ++row)
                        for (int x = bx; x < std::min(bx + 4, tile.x1); ++x)
                            rays[count++] = tracer.eye_ray(x + 0.5, camera.res_y - 1 - row + 0.5);
                    scene.closest_hits16(rays, count, hits);
                    tracer.continue_eye_rays(rays, hits, count);
                }
            }
        };
    });
    TrafficResult result;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.threads = threads;
    for (const PerThread<RayCounts>& thread : counts) {
        const RayCounts& c = thread.value;
        result.rays.eye += c.eye;
        result.rays.shadow += c.shadow;
        result.rays.reflected += c.reflected;
        result.rays.refracted += c.refracted;
    }
    return result;
}

} // namespace whitted::bench
