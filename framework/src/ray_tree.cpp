#include "whitted/ray_tree.hpp"

#include "whitted/scene.hpp"

#include <variant>

namespace whitted {

// Shadow acne is a physical impossibility, not a dark pixel: a feeler goes only
// towards a light in front of the surface, and seen from outside a sphere or a
// box cannot stand between its own point and such a light, nor can a flat shape
// ever (each lies wholly behind its tangent plane at the point). So a feeler
// that meets its own shape again has met the rounding error of its own start
// (the hit point, off the true surface by a few ulps): acne. From inside a
// sphere or a box, or on a cone, the shape may really be in the way; there only
// a hit just after the start (t tiny beside the coordinates) is that error.
// Whatever other objects block, however many of an area light's points (a
// penumbra), is a shadow: this test never looks at how dark a pixel is.
bool hits_its_own_surface(const Scene& scene, const Hit& start, const RayNode& feeler) {
    if (feeler.kind != RayKind::shadow || !feeler.blocked || !feeler.hit || start.primitive != feeler.hit->primitive)
        return false;
    const Shape& shape = scene.primitives()[feeler.hit->primitive].shape;
    const Sphere* sphere = std::get_if<Sphere>(&shape);
    const bool flat = std::holds_alternative<Plane>(shape) || std::holds_alternative<Triangle>(shape);
    const bool from_outside = start.front_face != (sphere && sphere->inward);
    // (Only for a feeler that leaves on the outer side: code that casts feelers
    // to lights behind the surface rightly finds the far side of the shape.)
    const bool leaves_outwards = glm::dot(feeler.ray.direction, start.geometric_normal) > 0.0;
    const bool convex = leaves_outwards && (flat || ((sphere || std::holds_alternative<Box>(shape)) && from_outside));
    return convex || feeler.hit->t < 1e-6 * (1.0 + max_abs_component(feeler.ray.origin));
}

} // namespace whitted
