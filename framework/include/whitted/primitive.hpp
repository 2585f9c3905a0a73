// A primitive is a shape with its material, and `intersect()` is the single
// place where the renderer dispatches on the kind of shape.
//
// Why: the acceleration structure and the labs' `closest_hit()` see a flat list
// of primitives. The three shapes of lab 1 (sphere, plane, triangle) go to the
// student's code; boxes and cones to the framework's own routines.
#pragma once

#include "whitted/aabb.hpp"
#include "whitted/hit.hpp"
#include "whitted/interval.hpp"
#include "whitted/shapes.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace whitted {

struct Primitive {
    Shape shape;
    std::uint32_t material = 0;       // index into the scene's materials
    std::int32_t vertex_normals = -1; // triangles from NFF `pp`: index into the scene's vertex normals
    std::uint32_t index = 0;          // own index in the built scene (set by Scene; a hit on it has hit.primitive == index)
    std::uint32_t line = 0;           // line of the scene file that made it (0: made by code)
};

/// Unit normals at a triangle's three corners, interpolated over its face.
using VertexNormals = std::array<Vec3, 3>;

/// The nearest hit of the ray on the primitive with t inside t_range, if any,
/// with the hit's primitive and material indices filled in. Vertex normals are
/// interpolated later, once the closest hit is known (Scene::closest_hit).
std::optional<Hit> intersect(const Ray& ray, const Primitive& primitive, Interval t_range);

/// The nearest hit on the box with t inside t_range (framework-provided shape).
std::optional<Hit> intersect_box(const Ray& ray, const Box& box, Interval t_range);

/// The nearest hit on the open cone with t inside t_range (framework-provided shape).
std::optional<Hit> intersect_cone(const Ray& ray, const Cone& cone, Interval t_range);

/// A box around the shape; infinite planes have none (an empty optional).
std::optional<Aabb> bounds(const Shape& shape);

} // namespace whitted
