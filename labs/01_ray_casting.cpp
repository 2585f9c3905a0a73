// Lab 1 — ray casting: primary rays, three shapes, and the closest hit.
// Handout: docs/labs/01_ray_casting.md. Tests: make test LAB=1
// Replace each `not_implemented();` line with your code.
#include "whitted/labs.hpp"

namespace whitted {

// The eye ray through the point (x, y) of the viewport, measured in pixels from
// its bottom-left corner (the framework passes pixel centres: x = i + 0.5).
// Use camera.eye, camera.xe, camera.ye, camera.ze, camera.w, camera.h,
// camera.df, camera.res_x and camera.res_y. The direction must have length 1.
Ray primary_ray(const Camera& camera, double x, double y) {
    not_implemented();
}

// The nearest hit of the ray on the sphere with t strictly inside t_range.
// Build the result with make_hit(ray, t, outward_normal); when sphere.inward is
// set, the outward normal points towards the centre.
std::optional<Hit> intersect_sphere(const Ray& ray, const Sphere& sphere, Interval t_range) {
    not_implemented();
}

// The hit of the ray on the infinite plane with t strictly inside t_range.
std::optional<Hit> intersect_plane(const Ray& ray, const Plane& plane, Interval t_range) {
    not_implemented();
}

// The hit of the ray on the triangle with t strictly inside t_range. Set
// hit.uv to the barycentric coordinates (b1, b2) of the hit point, the weights
// of p1 and p2. The outward normal is normalize(cross(p1 - p0, p2 - p0)).
std::optional<Hit> intersect_triangle(const Ray& ray, const Triangle& triangle, Interval t_range) {
    not_implemented();
}

// The nearest hit among the primitives with t strictly inside t_range. Call
// intersect(ray, primitive, t_range) for each one; it calls your functions above.
std::optional<Hit> closest_hit(const Ray& ray, std::span<const Primitive> primitives, Interval t_range) {
    not_implemented();
}

} // namespace whitted
