// Lab 8 — soft shadows: a light with a size, seen from a point in its
// penumbra, is partly hidden. Replace it by many point lights spread over it:
// labs 2 and 3 then light and shadow each of them, and the shadow's edge
// becomes the fraction of those points the hit point sees.
// Handout: docs/labs/08_soft_shadows.md. Tests: make test LAB=8
#include "whitted/labs.hpp"

namespace whitted {

// The point of the light at (u, v), u and v in [0, 1): the light is the
// parallelogram light.center + s light.edge_u + t light.edge_v with s and t
// from -1/2 to 1/2. (u, v) = (0, 0) is its corner center - edge_u/2 - edge_v/2;
// u runs along edge_u, v along edge_v.
Point3 point_on_light(const AreaLight& light, Vec2 uv) {
    not_implemented();
}

// The area light as light.samples point lights for the pixel sample being
// traced, each with an equal share of light.color. Point k is placed with
// lab 7's stratified_sample(k, light.samples, u), where u are its numbers:
// sample_numbers(tracer.pixel_sample(), SampleUse::light, light.first_number + k).
std::vector<PointLight> light_samples(const Tracer& tracer, const AreaLight& light) {
    not_implemented();
}

} // namespace whitted
