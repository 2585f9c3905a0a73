// What an intersection routine reports about the nearest surface point.
//
// Why: shading needs the point, a normal and which side was hit. The normal is
// always turned to face the incoming ray (dot(normal, ray.direction) <= 0), and
// `front_face` remembers whether the ray came from the outside of the surface.
// Refraction uses `front_face` to tell entering from leaving.
#pragma once

#include "whitted/ray.hpp"

#include <cstdint>

namespace whitted {

struct Hit {
    double t = 0.0;         // ray parameter of the hit
    Point3 point{};         // ray.at(t)
    Vec3 normal{};          // unit shading normal, facing the incoming ray
    Vec3 geometric_normal{};// unit normal of the true surface, facing the incoming ray
    bool front_face = true; // true when the ray hit the outward side
    Vec2 uv{};              // surface coordinates (barycentric b1, b2 on triangles)
    std::uint32_t primitive = 0; // index of the primitive hit (set by the framework)
    std::uint32_t material = 0;  // index of its material (set by the framework)
};

/// Builds a hit at parameter t: computes the point and turns the outward unit
/// normal to face the ray, recording on which side the ray arrived.
inline Hit make_hit(const Ray& ray, double t, const Vec3& outward_normal) {
    Hit hit;
    hit.t = t;
    hit.point = ray.at(t);
    hit.front_face = glm::dot(ray.direction, outward_normal) < 0.0;
    hit.normal = hit.front_face ? outward_normal : -outward_normal;
    hit.geometric_normal = hit.normal;
    return hit;
}

} // namespace whitted
