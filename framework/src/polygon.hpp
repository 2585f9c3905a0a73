// Splitting a planar polygon (convex or concave) into triangles.
//
// Why: NFF and P3F polygons may be concave and have many vertices, while the
// renderer only knows triangles. A fan from vertex 0 is wrong for concave
// polygons, so the loader clips ears in the polygon's own plane instead.
#pragma once

#include "whitted/math.hpp"

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace whitted::detail {

/// Three indices into the polygon's vertex list.
using TriangleIndices = std::array<std::size_t, 3>;

/// The Newell normal: its direction is the polygon's front normal (vertices
/// counter-clockwise seen from the front), its length twice the polygon's area.
Vec3 newell_normal(std::span<const Point3> vertices);

/// Triangles covering the polygon, each with the polygon's winding, so every
/// triangle's normal points like the Newell normal. Empty when the polygon has
/// no area (fewer than 3 distinct vertices, or all of them on one line).
std::vector<TriangleIndices> triangulate_polygon(std::span<const Point3> vertices);

} // namespace whitted::detail
