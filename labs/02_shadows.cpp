// Lab 2 — shadows: secondary rays that do not hit their own surface, shadow
// feelers, and Lambert's diffuse light.
// Handout: docs/labs/02_shadows.md. Tests: make test LAB=2
#include "whitted/labs.hpp"

namespace whitted {

// A ray that leaves the hit point in `direction` (unit length) and cannot hit
// the surface it starts on because of rounding errors ("shadow acne"). Use
// hit.geometric_normal; the handout explains why a fixed distance along the
// ray is not enough.
Ray spawn_ray(const Hit& hit, const Vec3& direction) {
    not_implemented();
}

// True when nothing lies between the hit point and the light. Cast a shadow
// feeler with spawn_ray and ask tracer.occluded(feeler, distance_to_the_light).
bool is_lit(const Tracer& tracer, const Hit& hit, const PointLight& light) {
    not_implemented();
}

// The diffuse light at the hit point: the sum over the lights that reach it of
// light colour x kd x (n . L), where kd = material.diffuse * material.color_at(point).
// The lights are tracer.lights() (each a PointLight with a position and a colour).
// Lights behind the surface (n . L <= 0) give nothing and need no shadow feeler.
Color lambert(const Tracer& tracer, const Hit& hit) {
    not_implemented();
}

} // namespace whitted
