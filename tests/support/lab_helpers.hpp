// Helpers for the labs' tests: directions at given angles, simple materials,
// and tracing one ray through a small scene.
#pragma once

#include "whitted/labs.hpp"

#include <cmath>

namespace whitted::testing_helpers {

/// Radians to degrees.
inline double degrees(double radians_value) { return radians_value * 180.0 / kPi; }

/// The normal used by angle tests: +z.
inline const Vec3 kUp(0.0, 0.0, 1.0);

/// A unit direction at theta degrees from +z, in the xz-plane, leaning towards +x.
inline Vec3 direction_at(double theta_degrees) {
    const double theta = radians(theta_degrees);
    return Vec3(std::sin(theta), 0.0, std::cos(theta));
}

/// A purely diffuse material (Kd = 1) of the given colour.
inline Material diffuse_material(Color color) {
    Material m;
    m.color = color;
    m.diffuse = 1.0;
    return m;
}

/// The colour seen along one ray, traced as an eye ray with the features of labs 1..stage.
inline Color trace_one(const Scene& scene, const Ray& ray, int stage = 6, int max_depth = 10) {
    RenderSettings settings;
    settings.stage = stage;
    settings.max_depth = max_depth;
    RayStats stats;
    const Tracer tracer(scene, settings, stats);
    return tracer.trace(ray, 1, RayKind::eye, Color(1.0));
}

} // namespace whitted::testing_helpers
