// The lab contract: every function the labs ask you to write.
//
// Your code goes in labs/NN_*.cpp, one file per lab. The framework calls these
// functions and nothing else of yours.
// Conventions used everywhere:
//   - directions are unit vectors; wo points from the surface back along the
//     incoming ray (wo = -ray.direction); wi points from the surface outwards
//     (towards a light, or along a new reflected / refracted ray);
//   - hit.normal is a unit vector on the same side as wo (see hit.hpp);
//   - eta_i is the index of refraction on the side of wo (where the ray we
//     trace comes from), eta_t the one on the other side (air is 1);
//   - total internal reflection is sin^2(theta_t) = (eta_i / eta_t)^2 (1 - cos^2(theta_i)) >= 1:
//     at the critical angle itself and beyond (labs 5 and 6 alike).
#pragma once

#include "whitted/aabb.hpp"
#include "whitted/bvh_tree.hpp"
#include "whitted/camera.hpp"
#include "whitted/hit.hpp"
#include "whitted/interval.hpp"
#include "whitted/primitive.hpp"
#include "whitted/not_implemented.hpp"
#include "whitted/tracer.hpp"

#include <optional>
#include <span>
#include <vector>

namespace whitted {

// ---- Lab 1: ray casting (01_ray_casting.cpp) --------------------------------
/// The eye ray through viewport position (x, y), in pixels from the bottom-left
/// corner of the viewport: the centre of pixel (i, j) is (i + 0.5, j + 0.5).
Ray primary_ray(const Camera& camera, double x, double y);
/// The nearest hit on the sphere with t inside t_range (uv unused).
std::optional<Hit> intersect_sphere(const Ray& ray, const Sphere& sphere, Interval t_range);
/// The hit on the infinite plane with t inside t_range (uv unused).
std::optional<Hit> intersect_plane(const Ray& ray, const Plane& plane, Interval t_range);
/// The hit on the triangle with t inside t_range; uv = barycentric (b1, b2) of p1 and p2.
std::optional<Hit> intersect_triangle(const Ray& ray, const Triangle& triangle, Interval t_range);
/// The nearest hit among `primitives` with t inside t_range (use `intersect()` on each).
std::optional<Hit> closest_hit(const Ray& ray, std::span<const Primitive> primitives, Interval t_range);

// ---- Lab 2: shadows (02_shadows.cpp) ----------------------------------------
/// A ray leaving the hit point in `direction` that cannot hit the surface it starts on.
Ray spawn_ray(const Hit& hit, const Vec3& direction);
/// True when nothing lies between the hit point and the light (a shadow feeler).
bool is_lit(const Tracer& tracer, const Hit& hit, const PointLight& light);
/// Lambert diffuse light from every light of tracer.lights() that reaches the hit point.
Color lambert(const Tracer& tracer, const Hit& hit);

// ---- Lab 3: Blinn-Phong (03_blinn_phong.cpp) --------------------------------
/// Ambient plus, for every light of tracer.lights() that reaches the hit point,
/// diffuse and Blinn-Phong specular.
Color blinn_phong(const Tracer& tracer, const Hit& hit, const Vec3& wo);

// ---- Lab 4: reflection (04_reflection.cpp) ----------------------------------
/// The mirror direction wi of wo about the normal n: 2 (wo . n) n - wo.
Vec3 mirror_direction(const Vec3& wo, const Vec3& n);
/// The mirror-reflected light: a ray traced one level deeper with the weight Ks (times the specular colour).
Color reflection(const Tracer& tracer, const Hit& hit, const Vec3& wo, int depth);

// ---- Lab 5: refraction (05_refraction.cpp) ----------------------------------
/// The refracted direction for wo on the side of n (Snell's law), or nothing on
/// total internal reflection.
std::optional<Vec3> refracted_direction(const Vec3& wo, const Vec3& n, double eta_i, double eta_t);
/// The refracted light: a ray traced one level deeper with the weight T (none on total internal reflection).
Color refraction(const Tracer& tracer, const Hit& hit, const Vec3& wo, int depth);

// ---- Lab 6: Fresnel (06_fresnel.cpp) ----------------------------------------
/// The unpolarised Fresnel reflectance Kr = (Rs + Rp) / 2 for light arriving at
/// cos_theta_i (> 0) from eta_i into eta_t; 1 on total internal reflection.
double fresnel_reflectance(double cos_theta_i, double eta_i, double eta_t);
/// Reflected and refracted light of a dielectric, weighted Kr and (1 - Kr) T.
Color fresnel_blend(const Tracer& tracer, const Hit& hit, const Vec3& wo, int depth);

// ---- Lab 7: anti-aliasing (07_anti_aliasing.cpp) ----------------------------
/// Where sample `index` (0..count-1) of `count` lies in its pixel, as (x, y) in
/// [0, 1)^2: in cell `index` of a grid of cols x rows equal cells (rows = the
/// largest divisor of count that is at most sqrt(count), cols = count / rows;
/// cells numbered row by row from the bottom left), at the place u within the cell.
Vec2 stratified_sample(int index, int count, Vec2 u);
/// The colour of pixel (x, y) (column from the left, row from the bottom): the
/// average of tracer.settings().samples_per_pixel samples; sample k is traced
/// with tracer.trace_sample({x, y, k}, ...) through the place stratified_sample
/// gives it for the numbers sample_numbers({x, y, k}, SampleUse::pixel).
Color pixel_color(const Tracer& tracer, int x, int y);

// ---- Lab 8: soft shadows (08_soft_shadows.cpp) ------------------------------
/// The point of the area light at (u, v) in [0, 1)^2: (0, 0) is the corner
/// center - edge_u / 2 - edge_v / 2, u runs along edge_u and v along edge_v.
Point3 point_on_light(const AreaLight& light, Vec2 uv);
/// The area light as light.samples point lights for the current pixel sample,
/// each with 1 / light.samples of its colour. Point k lies where
/// stratified_sample(k, light.samples, u) puts it on the light, for the numbers
/// u = sample_numbers(tracer.pixel_sample(), SampleUse::light, light.first_number + k).
std::vector<PointLight> light_samples(const Tracer& tracer, const AreaLight& light);

// ---- Lab 9: depth of field (09_depth_of_field.cpp) --------------------------
/// The point of the unit disk for u in [0, 1)^2 by Shirley and Chiu's concentric
/// mapping, which keeps areas (and so a stratified grid stays one): a = 2u - 1
/// (the square [-1, 1]^2); a = (0, 0) gives (0, 0); when |a.x| > |a.y| the
/// point is at radius r = a.x and angle (pi / 4) (a.y / a.x), otherwise at
/// radius r = a.y and angle pi / 2 - (pi / 4) (a.x / a.y); the point is
/// (r cos(angle), r sin(angle)) (a negative r puts it on the opposite side).
Vec2 concentric_disk(Vec2 u);
/// The eye ray of the thin lens through viewport position (x, y) (in pixels,
/// as for primary_ray) from the lens point lens_u picks: the lens point is
/// eye + (camera.aperture / 2) (d.x xe + d.y ye) with d = concentric_disk(lens_u),
/// and the ray goes from it (unit direction) through the focal point
/// eye + camera.focal_ratio p, where p = (x / res_x - 1/2) w xe + (y / res_y - 1/2) h ye - df ze
/// is the point primary_ray aims at, seen from the eye.
Ray thin_lens_ray(const Camera& camera, double x, double y, Vec2 lens_u);

// ---- Lab 10: bounding volume hierarchy (10_bvh.cpp) -------------------------
/// Where the ray enters the box: the largest of t_range.min and the three slabs'
/// entry distances, when that is no more than the smallest of t_range.max and
/// their exit distances; nothing otherwise (the ray misses the box within
/// t_range). inv_direction is 1 / ray.direction, axis by axis.
std::optional<double> box_entry(const Ray& ray, const Vec3& inv_direction, const Aabb& box, Interval t_range);
/// A bounding volume hierarchy over the boxes (box i is primitive i's): every
/// index in exactly one leaf, children after their parent, every node's bounds
/// around everything below it (whitted/bvh_tree.hpp); split so that rays test few
/// boxes and primitives (the surface area heuristic, or at least the median).
/// No boxes (a scene of planes only): a tree with no nodes and an empty order.
BvhTree build_bvh(std::span<const Aabb> boxes);
/// The nearest hit with t inside t_range among scene.bounded_primitives(),
/// found by walking scene.lab_bvh() (a leaf's order[i] indexes those primitives).
std::optional<Hit> bvh_closest_hit(const Scene& scene, const Ray& ray, Interval t_range);
/// True when any of scene.bounded_primitives() is hit with t inside t_range,
/// walking scene.lab_bvh() and stopping at the first hit found.
bool bvh_occluded(const Scene& scene, const Ray& ray, Interval t_range);

} // namespace whitted
