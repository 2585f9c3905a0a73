// Smooth shading of NFF `pp` triangles: the normal interpolated from the
// triangle's vertex normals.
//
// Why here: the scene applies it to every hit on such a triangle, and the
// benchmark's Embree harness must shade exactly alike.
#pragma once

#include "whitted/hit.hpp"
#include "whitted/primitive.hpp"

namespace whitted {

/// Sets hit.normal to the vertex normals interpolated at the hit's barycentric
/// coordinates (hit.uv), on the side of the geometric normal. The result is kept
/// only when it honours what the labs rely on: it faces the incoming ray, and
/// the mirror direction about it leaves on the ray's side of the true surface.
/// Near silhouettes of coarse meshes neither need hold; there the geometric
/// normal stays.
void apply_vertex_normals(Hit& hit, const Ray& ray, const VertexNormals& normals);

} // namespace whitted
