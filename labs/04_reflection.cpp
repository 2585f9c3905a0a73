// Lab 4 — mirror reflection: the reflected direction and one more level of
// the ray tree.
// Handout: docs/labs/04_reflection.md. Tests: make test LAB=4
#include "whitted/labs.hpp"

namespace whitted {

// The mirror direction of wo about the unit normal n (both pointing away from
// the surface): r = 2 (wo . n) n - wo.
Vec3 mirror_direction(const Vec3& wo, const Vec3& n) {
    not_implemented();
}

// The light reflected by a mirror-like surface: trace a ray in the mirror
// direction one level deeper, tracer.trace(ray, depth + 1, RayKind::reflected, weight),
// with weight = material.specular * material.specular_color. trace() returns the
// colour already multiplied by the weight.
Color reflection(const Tracer& tracer, const Hit& hit, const Vec3& wo, int depth) {
    not_implemented();
}

} // namespace whitted
