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

// ---- Labs 1-3: small hand-built scenes and direct calls to the shading labs ----

#include <utility>
#include <vector>

namespace whitted::testing_helpers {

/// A Tracer with its own settings and ray counts, to call lab functions such as
/// lambert() or blinn_phong() directly. Render with the features of labs 1..stage.
struct TestTracer {
    explicit TestTracer(const Scene& scene, int stage = 6) : tracer(scene, settings, stats) { settings.stage = stage; }
    RenderSettings settings;
    RayStats stats;
    Tracer tracer;
};

/// A hit at `point` on a surface whose unit normal there is `normal` (facing the viewer),
/// with material index `material`: what an intersection routine would report.
inline Hit surface_hit(const Point3& point, const Vec3& normal, std::uint32_t material = 0) {
    Hit hit;
    hit.point = point;
    hit.normal = normal;
    hit.geometric_normal = normal;
    hit.front_face = true;
    hit.material = material;
    return hit;
}

/// A material with diffuse colour C and weight Kd, and a highlight of colour Cs, weight Ks and exponent n.
inline Material shiny_material(Color color, double kd, Color specular_color = Color(1.0), double ks = 0.0,
                               double shininess = 1.0) {
    Material m;
    m.color = color;
    m.diffuse = kd;
    m.specular_color = specular_color;
    m.specular = ks;
    m.shininess = shininess;
    return m;
}

/// A scene of the given shapes, all with material 0, lit by `lights`, with ambient light `ambient`.
inline Scene scene_of(std::vector<Shape> shapes, Material material, std::vector<PointLight> lights,
                      Color ambient = Color(0.0)) {
    SceneData data;
    data.materials = {std::move(material)};
    for (Shape& shape : shapes) data.primitives.push_back(Primitive{std::move(shape), 0});
    data.lights = std::move(lights);
    data.ambient = ambient;
    return Scene(std::move(data));
}

/// The floor z = 0 facing +z (kUp), so that direction_at(theta) is theta degrees from its normal.
inline Plane floor_z0() { return Plane{Point3(0.0), kUp}; }

} // namespace whitted::testing_helpers
