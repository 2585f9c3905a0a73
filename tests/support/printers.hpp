// How a failing test prints the framework's values: "(1, 0.5, -2)" for a vector,
// a ray, a hit or a box by its fields, instead of GoogleTest's
// "24-byte object <00-00 00-00 ...>".
//
// GoogleTest prints a value with the PrintTo() that argument-dependent lookup
// finds in the namespace of the value's type: glm's for Vec2, Vec3, Point3 and
// Color (they are glm::dvec2 and glm::dvec3), whitted's for the rest; it prints
// std::optional and std::vector of them with these too. Numbers are written in
// full: the shortest text that reads back as exactly that double ("0.1",
// "0.30000000000000004"), so two values that differ never print alike.
//
// Every test file sees this header: tests/CMakeLists.txt includes it first in
// each of them, because a program whose files printed the same type two ways
// would break the one-definition rule (GoogleTest's printers are templates).
#pragma once

#include "whitted/bvh_tree.hpp"
#include "whitted/camera.hpp"
#include "whitted/hit.hpp"
#include "whitted/interval.hpp"
#include "whitted/material.hpp"
#include "whitted/primitive.hpp"
#include "whitted/ray.hpp"
#include "whitted/sampling.hpp"

#include <iosfwd>

namespace glm {

/// Vec2 as "(x, y)".
void PrintTo(const dvec2& v, std::ostream* os);
/// Vec3, Point3 and Color as "(x, y, z)".
void PrintTo(const dvec3& v, std::ostream* os);

} // namespace glm

namespace whitted {

/// "Ray{origin (0, 0, 5), direction (0, 0, -1)}".
void PrintTo(const Ray& ray, std::ostream* os);
/// Every field of the hit: t, point, both normals, the face, uv, primitive and material.
void PrintTo(const Hit& hit, std::ostream* os);
/// "Interval{min 0, max inf}" (the open range min < t < max).
void PrintTo(const Interval& interval, std::ostream* os);
/// "Aabb{min (...), max (...)}".
void PrintTo(const Aabb& box, std::ostream* os);
/// "PointLight{position (...), color (...)}".
void PrintTo(const PointLight& light, std::ostream* os);
/// The area light's centre, colour, edges and samples.
void PrintTo(const AreaLight& light, std::ostream* os);
/// The camera's fields from the scene file, then its frame (df, w, h, xe, ye, ze).
void PrintTo(const Camera& camera, std::ostream* os);
/// "BvhNode{bounds ..., first 0, count 3 (a leaf)}".
void PrintTo(const BvhNode& node, std::ostream* os);
/// The tree's size and its root: a whole tree would be thousands of lines.
void PrintTo(const BvhTree& tree, std::ostream* os);
/// "PixelSample{x 3, y 5, index 2}".
void PrintTo(const PixelSample& sample, std::ostream* os);
/// "Sphere{center (...), radius 1}" (and "inward" for a negative radius in the file).
void PrintTo(const Sphere& sphere, std::ostream* os);
/// "Plane{point (...), normal (...)}".
void PrintTo(const Plane& plane, std::ostream* os);
/// "Triangle{p0 (...), p1 (...), p2 (...)}".
void PrintTo(const Triangle& triangle, std::ostream* os);
/// "Box{min (...), max (...)}".
void PrintTo(const Box& box, std::ostream* os);
/// The cone's base, apex and radii.
void PrintTo(const Cone& cone, std::ostream* os);
/// The primitive's shape, material and index.
void PrintTo(const Primitive& primitive, std::ostream* os);

} // namespace whitted
