// Building the Embree scene from our primitives, and turning Embree's answers
// back into the framework's Hits.
//
// Why: Embree finds which primitive a ray hits and roughly where (in float).
// Everything after that is done in double precision on our own copy of the
// primitive, as the reference does: the hit point is placed again exactly on the
// surface, the normal comes from our geometry and pp triangles interpolate
// their vertex normals. So secondary rays start where whitted's start, and the
// harness shoots whitted's ray tree, not a float approximation of it.
#include "embree_scene.hpp"

#include "whitted/engine/vertex_normals.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <variant>

namespace whitted::bench {
namespace {

constexpr float kFloatInfinity = std::numeric_limits<float>::infinity();

void record_error(void* user, RTCError code, const char* message) {
    auto* errors = static_cast<EmbreeErrors*>(user);
    std::lock_guard lock(errors->mutex);
    if (errors->first.empty())
        errors->first = "Embree error " + std::to_string(static_cast<int>(code)) + ": " + (message ? message : "");
}

// A float no larger (towards -inf) or no smaller (towards +inf) than x, so float bounds still enclose the shape.
float float_below(double x) {
    const float f = static_cast<float>(x);
    return static_cast<double>(f) <= x ? f : std::nextafter(f, -kFloatInfinity);
}
float float_above(double x) {
    const float f = static_cast<float>(x);
    return static_cast<double>(f) >= x ? f : std::nextafter(f, kFloatInfinity);
}

void user_bounds(const RTCBoundsFunctionArguments* args) {
    const auto& shapes = *static_cast<const std::vector<Shape>*>(args->geometryUserPtr);
    const Aabb box = *bounds(shapes[args->primID]); // boxes and cones are always bounded
    args->bounds_o->lower_x = float_below(box.min.x);
    args->bounds_o->lower_y = float_below(box.min.y);
    args->bounds_o->lower_z = float_below(box.min.z);
    args->bounds_o->upper_x = float_above(box.max.x);
    args->bounds_o->upper_y = float_above(box.max.y);
    args->bounds_o->upper_z = float_above(box.max.z);
}

// The framework's double-precision box or cone routine on lane i of an Embree ray packet.
std::optional<Hit> user_hit(const Shape& shape, RTCRayN* rays, unsigned n, unsigned i) {
    const Ray ray{Point3(RTCRayN_org_x(rays, n, i), RTCRayN_org_y(rays, n, i), RTCRayN_org_z(rays, n, i)),
                  Vec3(RTCRayN_dir_x(rays, n, i), RTCRayN_dir_y(rays, n, i), RTCRayN_dir_z(rays, n, i))};
    const Interval range{RTCRayN_tnear(rays, n, i), RTCRayN_tfar(rays, n, i)};
    if (const auto* box = std::get_if<Box>(&shape)) return intersect_box(ray, *box, range);
    return intersect_cone(ray, std::get<Cone>(shape), range);
}

void user_intersect(const RTCIntersectFunctionNArguments* args) {
    const auto& shape = (*static_cast<const std::vector<Shape>*>(args->geometryUserPtr))[args->primID];
    RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        const std::optional<Hit> hit = user_hit(shape, rays, args->N, i);
        if (!hit) continue;
        // Embree's Ng carries the outward normal; surface_hit() turns it to face the ray again.
        const Vec3 outward = hit->front_face ? hit->normal : -hit->normal;
        RTCRayN_tfar(rays, args->N, i) = static_cast<float>(hit->t);
        RTCHitN_Ng_x(hits, args->N, i) = static_cast<float>(outward.x);
        RTCHitN_Ng_y(hits, args->N, i) = static_cast<float>(outward.y);
        RTCHitN_Ng_z(hits, args->N, i) = static_cast<float>(outward.z);
        RTCHitN_u(hits, args->N, i) = 0.0f;
        RTCHitN_v(hits, args->N, i) = 0.0f;
        RTCHitN_primID(hits, args->N, i) = args->primID;
        RTCHitN_geomID(hits, args->N, i) = args->geomID;
        RTCHitN_instID(hits, args->N, i, 0) = args->context->instID[0];
    }
}

void user_occluded(const RTCOccludedFunctionNArguments* args) {
    const auto& shape = (*static_cast<const std::vector<Shape>*>(args->geometryUserPtr))[args->primID];
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        if (user_hit(shape, args->ray, args->N, i)) RTCRayN_tfar(args->ray, args->N, i) = -kFloatInfinity;
    }
}

// The plane's hit with 0 < t < t_max (planes never enter Embree).
std::optional<double> plane_t(const Ray& ray, const Plane& plane, double t_max) {
    const double denominator = glm::dot(plane.normal, ray.direction);
    if (denominator == 0.0) return std::nullopt;
    const double t = glm::dot(plane.normal, plane.point - ray.origin) / denominator;
    if (t > 0.0 && t < t_max) return t;
    return std::nullopt;
}

void set_ray(RTCRay& r, const Ray& ray, float t_far) {
    r.org_x = static_cast<float>(ray.origin.x);
    r.org_y = static_cast<float>(ray.origin.y);
    r.org_z = static_cast<float>(ray.origin.z);
    r.tnear = 0.0f;
    r.dir_x = static_cast<float>(ray.direction.x);
    r.dir_y = static_cast<float>(ray.direction.y);
    r.dir_z = static_cast<float>(ray.direction.z);
    r.time = 0.0f;
    r.tfar = t_far;
    r.mask = 0xFFFFFFFFu;
    r.id = 0;
    r.flags = 0;
}

} // namespace

EmbreeScene::EmbreeScene(const SceneData& data, const EmbreeSettings& settings) : data_(data) {
    std::string config = "verbose=0";
    if (settings.build_threads > 0) config += ",threads=" + std::to_string(settings.build_threads);
    device_ = rtcNewDevice(config.c_str());
    if (!device_) throw std::runtime_error("Embree error: cannot create a device (rtcNewDevice failed)");
    rtcSetDeviceErrorFunction(device_, record_error, &errors_);
    scene_ = rtcNewScene(device_);
    if (!scene_) fail("cannot create a scene");
    try {
        build(settings);
    } catch (const std::runtime_error&) {
        throw; // fail() has released everything
    } catch (const std::exception& error) {
        fail(error.what());
    }
}

void EmbreeScene::fail(const std::string& fallback) {
    std::string message = errors_.first.empty() ? "Embree error: " + fallback : errors_.first;
    if (scene_) rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
    scene_ = nullptr;
    device_ = nullptr;
    throw std::runtime_error(message);
}

void EmbreeScene::build(const EmbreeSettings& settings) {
    const SceneData& data = data_;
    rtcSetSceneBuildQuality(scene_, settings.quality);

    for (std::uint32_t i = 0; i < data.primitives.size(); ++i) {
        const Shape& shape = data.primitives[i].shape;
        if (std::holds_alternative<Triangle>(shape)) triangles_.push_back(i);
        else if (std::holds_alternative<Sphere>(shape)) spheres_.push_back(i);
        else if (std::holds_alternative<Plane>(shape)) planes_.push_back(i);
        else {
            user_.push_back(i);
            user_shapes_.push_back(shape);
        }
    }
    if (!triangles_.empty()) {
        RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                     3 * sizeof(float), 3 * triangles_.size()));
        auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                       3 * sizeof(unsigned), triangles_.size()));
        if (!vertices || !indices) fail("cannot allocate the triangles");
        for (std::size_t k = 0; k < triangles_.size(); ++k) {
            const auto& t = std::get<Triangle>(data.primitives[triangles_[k]].shape);
            const Point3 corners[3] = {t.p0, t.p1, t.p2};
            for (int c = 0; c < 3; ++c) {
                for (int axis = 0; axis < 3; ++axis) vertices[9 * k + 3 * c + axis] = static_cast<float>(corners[c][axis]);
                indices[3 * k + c] = static_cast<unsigned>(3 * k + c);
            }
        }
        rtcCommitGeometry(geometry);
        triangle_geometry_ = rtcAttachGeometry(scene_, geometry);
        rtcReleaseGeometry(geometry);
    }
    if (!spheres_.empty()) {
        // Embree's sphere: a point with a radius, float4 (x, y, z, r); it reports the back hit from inside.
        RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* points = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                                   4 * sizeof(float), spheres_.size()));
        if (!points) fail("cannot allocate the spheres");
        for (std::size_t k = 0; k < spheres_.size(); ++k) {
            const auto& s = std::get<Sphere>(data.primitives[spheres_[k]].shape);
            points[4 * k + 0] = static_cast<float>(s.center.x);
            points[4 * k + 1] = static_cast<float>(s.center.y);
            points[4 * k + 2] = static_cast<float>(s.center.z);
            points[4 * k + 3] = static_cast<float>(s.radius);
        }
        rtcCommitGeometry(geometry);
        sphere_geometry_ = rtcAttachGeometry(scene_, geometry);
        rtcReleaseGeometry(geometry);
    }
    if (!user_.empty()) {
        RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned>(user_.size()));
        rtcSetGeometryUserData(geometry, &user_shapes_);
        rtcSetGeometryBoundsFunction(geometry, user_bounds, nullptr);
        rtcSetGeometryIntersectFunction(geometry, user_intersect);
        rtcSetGeometryOccludedFunction(geometry, user_occluded);
        rtcCommitGeometry(geometry);
        user_geometry_ = rtcAttachGeometry(scene_, geometry);
        rtcReleaseGeometry(geometry);
    }
    const auto start = std::chrono::steady_clock::now();
    rtcCommitScene(scene_);
    build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (rtcGetDeviceError(device_) != RTC_ERROR_NONE || !errors_.first.empty()) fail("cannot build the scene");
}

EmbreeScene::~EmbreeScene() {
    if (scene_) rtcReleaseScene(scene_);
    if (device_) rtcReleaseDevice(device_);
}

std::string EmbreeScene::version() {
    return "embree " + std::to_string(RTC_VERSION_MAJOR) + "." + std::to_string(RTC_VERSION_MINOR) + "." +
           std::to_string(RTC_VERSION_PATCH);
}

std::optional<Hit> EmbreeScene::closest_hit(const Ray& ray) const {
    // Infinite planes first, in double precision; a plane hit shortens Embree's range.
    std::optional<Hit> nearest;
    double t_max = kInfinity;
    for (std::uint32_t index : planes_) {
        if (const auto t = plane_t(ray, std::get<Plane>(data_.primitives[index].shape), t_max)) {
            t_max = *t;
            nearest = make_hit(ray, *t, std::get<Plane>(data_.primitives[index].shape).normal);
            nearest->primitive = index;
            nearest->material = data_.primitives[index].material;
        }
    }
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit ray_hit;
    set_ray(ray_hit.ray, ray, std::isinf(t_max) ? kFloatInfinity : static_cast<float>(t_max));
    ray_hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    ray_hit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &ray_hit);
    if (ray_hit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return nearest;
    return surface_hit(ray, ray_hit);
}

void EmbreeScene::closest_hits16(const Ray* rays, int count, std::optional<Hit>* hits) const {
    RTCRayHit16 packet;
    alignas(64) int valid[16];
    for (int i = 0; i < 16; ++i) {
        valid[i] = i < count ? -1 : 0;
        const Ray& ray = rays[i < count ? i : 0];
        // Planes first, as for single rays.
        double t_max = kInfinity;
        hits[i].reset();
        if (i < count) {
            for (std::uint32_t index : planes_) {
                if (const auto t = plane_t(ray, std::get<Plane>(data_.primitives[index].shape), t_max)) {
                    t_max = *t;
                    hits[i] = make_hit(ray, *t, std::get<Plane>(data_.primitives[index].shape).normal);
                    hits[i]->primitive = index;
                    hits[i]->material = data_.primitives[index].material;
                }
            }
        }
        packet.ray.org_x[i] = static_cast<float>(ray.origin.x);
        packet.ray.org_y[i] = static_cast<float>(ray.origin.y);
        packet.ray.org_z[i] = static_cast<float>(ray.origin.z);
        packet.ray.tnear[i] = 0.0f;
        packet.ray.dir_x[i] = static_cast<float>(ray.direction.x);
        packet.ray.dir_y[i] = static_cast<float>(ray.direction.y);
        packet.ray.dir_z[i] = static_cast<float>(ray.direction.z);
        packet.ray.time[i] = 0.0f;
        packet.ray.tfar[i] = std::isinf(t_max) ? kFloatInfinity : static_cast<float>(t_max);
        packet.ray.mask[i] = 0xFFFFFFFFu;
        packet.ray.id[i] = static_cast<unsigned>(i);
        packet.ray.flags[i] = 0;
        packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
        packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
    }
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    rtcIntersect16(valid, scene_, &context, &packet);
    for (int i = 0; i < count; ++i) {
        if (packet.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID) continue;
        RTCRayHit one;
        one.ray.tfar = packet.ray.tfar[i];
        one.hit.Ng_x = packet.hit.Ng_x[i];
        one.hit.Ng_y = packet.hit.Ng_y[i];
        one.hit.Ng_z = packet.hit.Ng_z[i];
        one.hit.u = packet.hit.u[i];
        one.hit.v = packet.hit.v[i];
        one.hit.primID = packet.hit.primID[i];
        one.hit.geomID = packet.hit.geomID[i];
        hits[i] = surface_hit(rays[i], one);
    }
}

bool EmbreeScene::occluded(const Ray& ray, double t_max) const {
    for (std::uint32_t index : planes_)
        if (plane_t(ray, std::get<Plane>(data_.primitives[index].shape), t_max)) return true;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay shadow;
    set_ray(shadow, ray, static_cast<float>(t_max));
    rtcOccluded1(scene_, &context, &shadow);
    return shadow.tfar < 0.0f; // Embree sets tfar to -inf when something is in the way
}

// Embree reports t in float; the hit point is placed again in double precision
// on the primitive's own surface (the nearest root to Embree's t), so secondary
// rays start as precisely as the reference's do, whatever the ray's length.
Hit EmbreeScene::surface_hit(const Ray& ray, const RTCRayHit& ray_hit) const {
    double t = ray_hit.ray.tfar;
    const unsigned geometry = ray_hit.hit.geomID, id = ray_hit.hit.primID;
    std::uint32_t index = 0;
    Vec3 outward;
    if (geometry == triangle_geometry_) {
        index = triangles_[id];
        const auto& tri = std::get<Triangle>(data_.primitives[index].shape);
        const Vec3 n = glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
        const double denominator = glm::dot(n, ray.direction);
        if (denominator != 0.0) {
            const double exact = glm::dot(n, tri.p0 - ray.origin) / denominator; // the triangle's plane
            if (exact > 0.0) t = exact;
        }
        outward = glm::normalize(n);
    } else if (geometry == sphere_geometry_) {
        index = spheres_[id];
        const auto& sphere = std::get<Sphere>(data_.primitives[index].shape);
        const Vec3 oc = ray.origin - sphere.center;
        const double b = glm::dot(oc, ray.direction);
        const Vec3 to_line = oc - b * ray.direction;
        const double discriminant = sphere.radius * sphere.radius - glm::dot(to_line, to_line);
        if (discriminant >= 0.0) {
            const double root = std::sqrt(discriminant);
            const double near = -b - root, far = -b + root;
            const double exact = std::abs(near - t) <= std::abs(far - t) ? near : far;
            if (exact > 0.0) t = exact;
        }
        outward = (ray.at(t) - sphere.center) / sphere.radius;
        if (sphere.inward) outward = -outward;
    } else {
        index = user_[id];
        const Shape& shape = data_.primitives[index].shape;
        const Interval range{0.0, t * (1.0 + 1e-5)};
        const std::optional<Hit> exact =
            std::holds_alternative<Box>(shape) ? intersect_box(ray, std::get<Box>(shape), range)
                                               : intersect_cone(ray, std::get<Cone>(shape), range);
        if (exact) {
            t = exact->t;
            outward = exact->front_face ? exact->normal : -exact->normal;
        } else {
            outward = glm::normalize(Vec3(ray_hit.hit.Ng_x, ray_hit.hit.Ng_y, ray_hit.hit.Ng_z));
        }
    }
    Hit hit = make_hit(ray, t, outward);
    hit.primitive = index;
    hit.material = data_.primitives[index].material;
    if (geometry == triangle_geometry_) {
        hit.uv = Vec2(ray_hit.hit.u, ray_hit.hit.v); // Embree's u, v are our barycentric b1, b2
        const Primitive& primitive = data_.primitives[index];
        if (primitive.vertex_normals >= 0)
            apply_vertex_normals(hit, ray, data_.vertex_normals[static_cast<std::size_t>(primitive.vertex_normals)]);
    }
    return hit;
}

} // namespace whitted::bench
