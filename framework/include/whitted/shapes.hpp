// The geometric shapes a scene can contain: plain values, no behaviour.
//
// Why: the set is closed (NFF and P3F name exactly these), so a scene stores a
// `std::variant` of them and `intersect()` in primitive.hpp is the one place
// that dispatches on the kind. Polygons and meshes are split into triangles when
// the scene is loaded, so the renderer only ever sees the shapes below.
#pragma once

#include "whitted/math.hpp"

#include <variant>

namespace whitted {

/// A sphere. With `inward` set (NFF negative radius) its outward side faces the
/// centre: the surface is meant to be seen from inside, like the inner wall of
/// a hollow glass shell.
struct Sphere {
    Point3 center;
    double radius = 1.0; // always > 0
    bool inward = false;
};

/// An infinite plane through `point`; `normal` is unit length and marks the outward side.
struct Plane {
    Point3 point;
    Vec3 normal;
};

/// A triangle; its outward side is the one from which p0, p1, p2 appear
/// counter-clockwise, so the outward normal is normalize(cross(p1 - p0, p2 - p0)).
struct Triangle {
    Point3 p0, p1, p2;
};

/// An axis-aligned box between two corners (min < max on every axis).
struct Box {
    Point3 min;
    Point3 max;
};

/// A truncated cone (a cylinder when both radii are equal) around the axis from
/// `base` to `apex`, open at both ends. With `inward` set (NFF negative radii)
/// the outward side faces the axis.
struct Cone {
    Point3 base;
    double base_radius = 1.0; // >= 0
    Point3 apex;
    double apex_radius = 1.0; // >= 0, not both 0
    bool inward = false;
};

using Shape = std::variant<Sphere, Plane, Triangle, Box, Cone>;

} // namespace whitted
