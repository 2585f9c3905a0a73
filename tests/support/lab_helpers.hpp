// Helpers for the labs' tests: directions at given angles, simple materials,
// and tracing one ray through a small scene. (A failing test prints vectors,
// rays and hits by their fields: printers.hpp, which every test file includes.)
#pragma once

#include "whitted/labs.hpp"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

namespace whitted::testing_helpers {

/// For a test that checks many inputs in a loop: true once `most` of the test's
/// assertions have failed, after adding one failure that says the test stops
/// there. End the loop's body with `if (enough_failures()) return;`: one mistake
/// usually fails every input alike, and pages of the same failure would bury
/// the first ones, which tell the most.
inline bool enough_failures(int most = 5) {
    const ::testing::TestResult& result = *::testing::UnitTest::GetInstance()->current_test_info()->result();
    int failed = 0;
    for (int i = 0; i < result.total_part_count(); ++i) failed += result.GetTestPartResult(i).failed() ? 1 : 0;
    if (failed < most) return false;
    ADD_FAILURE() << "the test stops after these " << failed << " failures: its other inputs were not checked "
                  << "(fix the first failure above, then run it again)";
    return true;
}

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
inline Color trace_one(const Scene& scene, const Ray& ray, int stage = kLabCount, int max_depth = 10) {
    RenderSettings settings;
    settings.stage = stage;
    settings.max_depth = max_depth;
    RayStats stats;
    const Tracer tracer(scene, settings, stats);
    return tracer.trace(ray, 1, RayKind::eye, Color(1.0));
}

// ---- Labs 4-6: secondary rays --------------------------------------------------

/// A unit direction at theta degrees from +z whose tangential part points at phi
/// degrees from +x (phi = 0 is direction_at(theta)).
inline Vec3 direction_at(double theta_degrees, double phi_degrees) {
    const double theta = radians(theta_degrees), phi = radians(phi_degrees);
    return Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
}

/// The angle between two unit vectors, in degrees.
inline double degrees_between(const Vec3& a, const Vec3& b) {
    return degrees(std::acos(glm::clamp(glm::dot(a, b), -1.0, 1.0)));
}

/// A mirror: no diffuse light, mirror weight Ks = ks with the given specular colour.
inline Material mirror_material(double ks, Color specular_color = Color(1.0)) {
    Material m;
    m.diffuse = 0.0;
    m.specular = ks;
    m.specular_color = specular_color;
    return m;
}

/// Clear glass: no diffuse light, no mirror term (Ks = 0), transmittance t, index ior.
inline Material glass_material(double ior, double transmittance = 1.0) {
    Material m;
    m.diffuse = 0.0;
    m.transmittance = transmittance;
    m.ior = ior;
    return m;
}

/// `count` parallel sheets of glass (planes facing +z at z = 0, -1, -2, ...) of index `ior` and transmittance
/// `transmittance` (no diffuse light, no mirror term) in front of a white background: an eye ray straight
/// down crosses them all, one refracted ray per sheet.
inline SceneData glass_sheets(int count, double ior, double transmittance) {
    SceneData data;
    data.background = Color(1.0);
    data.materials = {glass_material(ior, transmittance)};
    for (int k = 0; k < count; ++k) data.primitives.push_back({Plane{Point3(0.0, 0.0, -k), kUp}, 0});
    return data;
}

/// A scene, its render settings, ray counts and a tracer, for tests that call a
/// lab function directly or count the rays one trace casts. min_weight defaults
/// to 0: every secondary ray is traced down to max_depth.
struct TracerRig {
    TracerRig(SceneData data, int stage, int max_depth, double min_weight = 0.0)
        : scene(std::move(data)), settings{stage, max_depth, min_weight}, tracer(scene, settings, stats) {}
    TracerRig(const TracerRig&) = delete;
    TracerRig& operator=(const TracerRig&) = delete;

    /// The colour seen along an eye ray (depth 1).
    Color trace(const Ray& ray) const { return tracer.trace(ray, 1, RayKind::eye, Color(1.0)); }

    Scene scene;
    RenderSettings settings;
    RayStats stats;
    Tracer tracer;
};

/// A hit at `point` on a surface whose outward normal is `outward`, reached by a
/// ray arriving along -wo: normal and front_face as an intersection routine would
/// set them. Material index `material`.
inline Hit hit_seen_from(const Point3& point, const Vec3& outward, const Vec3& wo, std::uint32_t material = 0) {
    Hit hit = make_hit(Ray{point + wo, -wo}, 1.0, outward);
    hit.point = point;
    hit.material = material;
    return hit;
}

} // namespace whitted::testing_helpers

// ---- Labs 1-3: small hand-built scenes and direct calls to the shading labs ----

#include <utility>
#include <vector>

namespace whitted::testing_helpers {

/// A Tracer with its own settings and ray counts, to call lab functions such as
/// lambert() or blinn_phong() directly. Render with the features of labs 1..stage.
struct TestTracer {
    explicit TestTracer(const Scene& scene, int stage = kLabCount) : tracer(scene, settings, stats) { settings.stage = stage; }
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

/// The data of a scene of the given shapes, all with material 0, lit by `lights`, with ambient light `ambient`.
inline SceneData scene_data_of(std::vector<Shape> shapes, Material material, std::vector<PointLight> lights,
                               Color ambient = Color(0.0)) {
    SceneData data;
    data.materials = {std::move(material)};
    for (Shape& shape : shapes) data.primitives.push_back(Primitive{std::move(shape), 0});
    data.lights = std::move(lights);
    data.ambient = ambient;
    return data;
}

/// That scene, built.
inline Scene scene_of(std::vector<Shape> shapes, Material material, std::vector<PointLight> lights,
                      Color ambient = Color(0.0)) {
    return Scene(scene_data_of(std::move(shapes), std::move(material), std::move(lights), ambient));
}

/// The floor z = 0 facing +z (kUp), so that direction_at(theta) is theta degrees from its normal.
inline Plane floor_z0() { return Plane{Point3(0.0), kUp}; }

/// Whether `ray` leaves from the hit point in `direction`, as spawn_ray's must: the direction kept and
/// the origin moved off the point by less than 1e-5 (1 + largest |coordinate| of the point).
inline bool leaves_from(const Hit& hit, const Vec3& direction, const Ray& ray) {
    return glm::length(ray.direction - direction) <= 1e-12 &&
           glm::length(ray.origin - hit.point) < 1e-5 * (1.0 + max_abs_component(hit.point));
}

/// A smooth surface: scene_of()'s scene whose first primitive is a large flat triangle in the plane z = 0
/// (geometric normal +z) with all three vertex normals `shading`, so that the framework reports the
/// shading normal `shading` (hit.normal) and the geometric normal +z (hit.geometric_normal) everywhere on it.
inline Scene smooth_floor_scene(const Vec3& shading, std::vector<Shape> extra, Material material,
                                std::vector<PointLight> lights, Color ambient = Color(0.0)) {
    SceneData data = scene_data_of(std::move(extra), std::move(material), std::move(lights), ambient);
    data.vertex_normals.push_back({shading, shading, shading});
    Primitive triangle{Triangle{Point3(-10.0, -10.0, 0.0), Point3(10.0, -10.0, 0.0), Point3(0.0, 10.0, 0.0)}, 0};
    triangle.vertex_normals = static_cast<std::int32_t>(data.vertex_normals.size() - 1);
    data.primitives.insert(data.primitives.begin(), triangle);
    return Scene(std::move(data));
}

/// The eye ray straight down (-z) onto the point (x, y, 0) of smooth_floor_scene()'s triangle.
inline Ray ray_down_to(double x = 0.0, double y = 0.0) { return Ray{Point3(x, y, 5.0), -kUp}; }

/// What that ray hits: the smooth triangle (or a shape in front of it).
inline Hit smooth_floor_hit(const Scene& scene, double x = 0.0, double y = 0.0) {
    return scene.closest_hit(ray_down_to(x, y)).value();
}

// ---- Lab 7: pixel samples -----------------------------------------------------

/// A camera at the origin looking down -z at an 8 x 8 image, the view plane 1 away
/// and 2 wide (fovy 90 degrees): viewport x maps to x_world = (x / 8 - 0.5) * 2 at
/// z = -1, so at depth 10 the viewport line x = X is the world line x = (X / 8 - 0.5) * 20.
inline Camera eight_by_eight() {
    return Camera::create(Point3(0.0), Point3(0.0, 0.0, -1.0), Vec3(0.0, 1.0, 0.0), 90.0, 8, 8);
}

/// A black wall at depth 10 covering everything left of the viewport line x = edge
/// (in a band around the middle rows), in front of a white background; no lights.
inline SceneData black_left_of(double edge) {
    SceneData data;
    data.camera = eight_by_eight();
    data.background = Color(1.0);
    Material black;
    black.color = Color(0.0);
    black.diffuse = 0.0;
    data.materials = {black};
    const double x = (edge / 8.0 - 0.5) * 20.0;
    data.primitives.push_back({Triangle{Point3(x, -40.0, -10.0), Point3(x, 40.0, -10.0), Point3(x - 80.0, 0.0, -10.0)}, 0});
    return data;
}

/// The grid of `count` cells the handout describes: rows is the largest divisor of count up to sqrt(count).
struct SampleGrid {
    int cols, rows;
};
inline SampleGrid sample_grid(int count) {
    int rows = 1;
    for (int r = 1; r * r <= count; ++r)
        if (count % r == 0) rows = r;
    return {count / rows, rows};
}

/// Settings for the anti-aliasing stage with `samples` a pixel.
inline RenderSettings with_samples(int samples) {
    RenderSettings settings;
    settings.stage = stage_number(Stage::anti_aliasing);
    settings.samples_per_pixel = samples;
    return settings;
}

// ---- Lab 8: soft shadows --------------------------------------------------------

/// Settings for the soft-shadows stage (Whitted sampling of the pixel: one eye ray).
inline RenderSettings soft_shadow_settings() {
    RenderSettings settings;
    settings.stage = stage_number(Stage::soft_shadows);
    return settings;
}

/// A size x size square light facing down: edge_u along +x, edge_v along +z.
inline AreaLight square_light(const Point3& center, double size, int samples, Color color = Color(1.0)) {
    AreaLight light;
    light.center = center;
    light.color = color;
    light.edge_u = Vec3(size, 0.0, 0.0);
    light.edge_v = Vec3(0.0, 0.0, size);
    light.samples = samples;
    return light;
}

/// Expects `got` within 1e-15 of (x, y) in each coordinate (places in a pixel, points of the unit disk).
inline void expect_vec2(Vec2 got, double x, double y, const std::string& what) {
    EXPECT_NEAR(got.x, x, 1e-15) << what << ": x";
    EXPECT_NEAR(got.y, y, 1e-15) << what << ": y";
}

/// Expects `got` within 1e-12 of `expected` in each coordinate.
inline void expect_point(const Point3& got, const Point3& expected, const std::string& what) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], expected[i], 1e-12) << what << ", coordinate " << i;
}

/// Where the handout puts point k of `light` for pixel sample `sample`: the numbers
/// of SampleUse::light number first_number + k, in cell k of the grid, on the parallelogram.
inline Point3 expected_light_point(const AreaLight& light, const PixelSample& sample, int k) {
    const Vec2 u = sample_numbers(sample, SampleUse::light, light.first_number + static_cast<std::uint32_t>(k));
    const SampleGrid grid = sample_grid(light.samples);
    const double s = (k % grid.cols + u.x) / grid.cols, t = (k / grid.cols + u.y) / grid.rows;
    return light.center + (s - 0.5) * light.edge_u + (t - 0.5) * light.edge_v;
}

// ---- Lab 9: depth of field -------------------------------------------------------

/// Settings for the depth-of-field stage with `samples` a pixel (0: one eye ray a pixel).
inline RenderSettings depth_of_field_settings(int samples = 0) {
    RenderSettings settings;
    settings.stage = stage_number(Stage::depth_of_field);
    settings.samples_per_pixel = samples;
    return settings;
}

/// The concentric mapping as the handout writes it, for the expected values of the
/// tests that use it on many numbers (the mapping's own tests use values by hand).
inline Vec2 expected_disk_point(Vec2 u) {
    const double ax = 2.0 * u.x - 1.0, ay = 2.0 * u.y - 1.0;
    if (ax == 0.0 && ay == 0.0) return Vec2(0.0);
    const bool sideways = std::abs(ax) > std::abs(ay);
    const double r = sideways ? ax : ay;
    const double angle = sideways ? (kPi / 4.0) * (ay / ax) : kPi / 2.0 - (kPi / 4.0) * (ax / ay);
    return Vec2(r * std::cos(angle), r * std::sin(angle));
}

/// The point of the view plane that viewport position (x, y) aims at, seen from the eye (lab 1's p).
inline Vec3 view_plane_offset(const Camera& camera, double x, double y) {
    return camera.w * (x / camera.res_x - 0.5) * camera.xe + camera.h * (y / camera.res_y - 0.5) * camera.ye -
           camera.df * camera.ze;
}

/// The focal point of viewport position (x, y): eye + focal_ratio p, where every lens ray of (x, y) passes.
inline Point3 focal_point(const Camera& camera, double x, double y) {
    return camera.eye + camera.focal_ratio * view_plane_offset(camera, x, y);
}

/// The lens point of the numbers u, as the handout places it: eye + (aperture / 2) (d.x xe + d.y ye).
inline Point3 expected_lens_point(const Camera& camera, Vec2 u) {
    const Vec2 d = expected_disk_point(u);
    return camera.eye + (camera.aperture / 2.0) * (d.x * camera.xe + d.y * camera.ye);
}

/// The distance from `point` to the line of `ray` (its unit direction).
inline double distance_to_ray(const Point3& point, const Ray& ray) {
    const Vec3 to_point = point - ray.origin;
    return glm::length(to_point - glm::dot(to_point, ray.direction) * ray.direction);
}

/// A camera with a tilted frame (xe, ye not the world's x, y) and a thin lens.
inline Camera tilted_lens_camera(double aperture, double focal_ratio, int res_x = 64, int res_y = 48) {
    Camera camera = Camera::create(Point3(1.0, 2.0, 3.0), Point3(-2.0, 0.5, -4.0), Vec3(0.0, 1.0, 0.0), 50.0, res_x, res_y);
    camera.aperture = aperture;
    camera.focal_ratio = focal_ratio;
    return camera;
}

// ---- Lab 10: bounding volume hierarchy -------------------------------------------

/// Numbers in [0, 1) from a seed, the same on every machine (a 64-bit LCG's top bits).
struct TestNumbers {
    std::uint64_t state;
    double next() {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(state >> 11) * 0x1.0p-53;
    }
    Point3 point(double size) { return size * Point3(next() - 0.5, next() - 0.5, next() - 0.5); }
};

/// `count` small triangles scattered through a cube of side `size` (a soup: no mesh order to exploit).
inline std::vector<Primitive> triangle_soup(std::size_t count, double size, std::uint64_t seed) {
    TestNumbers numbers{seed};
    std::vector<Primitive> soup;
    for (std::size_t i = 0; i < count; ++i) {
        const Point3 corner = numbers.point(size);
        soup.push_back({Triangle{corner, corner + numbers.point(2.0), corner + numbers.point(2.0)}, 0});
    }
    return soup;
}

/// A scene of the primitives (material 0: grey, diffuse) with a camera looking at them from +z.
inline SceneData bvh_test_scene(std::vector<Primitive> primitives, double size) {
    SceneData data;
    data.camera = Camera::create(Point3(0.3, 0.2, 1.5 * size), Point3(0.0), Vec3(0.0, 1.0, 0.0), 50.0, 24, 18);
    data.materials = {diffuse_material(Color(0.7))};
    data.primitives = std::move(primitives);
    return data;
}

/// Rays through a grid of the camera's viewport and from inside the cloud outwards: what a render asks a BVH.
inline std::vector<Ray> bvh_test_rays(const Camera& camera, double size, std::uint64_t seed) {
    std::vector<Ray> rays;
    for (int y = 0; y < camera.res_y; ++y)
        for (int x = 0; x < camera.res_x; ++x) {
            rays.push_back(Ray{camera.eye, glm::normalize(view_plane_offset(camera, x + 0.5, y + 0.5))});
        }
    TestNumbers numbers{seed};
    for (int i = 0; i < 200; ++i) rays.push_back(Ray{numbers.point(size), glm::normalize(numbers.point(1.0) + Vec3(1e-3))});
    return rays;
}

} // namespace whitted::testing_helpers
