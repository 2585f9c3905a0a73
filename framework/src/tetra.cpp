// The fractal tetrahedron (Sierpinski's): a tetrahedron replaced by the four
// half-size tetrahedra at its corners, recursively; written with SPD tetra's
// view, light and material.
//
// Why this geometry: level 1 is the regular tetrahedron with corners (1,1,1),
// (-1,-1,1), (-1,1,-1) and (1,-1,-1), four triangles. Each further level keeps
// the corner tetrahedra, scaled by one half about each corner, so level n has
// 4^(n-1) tetrahedra and 4^n triangles: level 6 is SPD's tetra6 (4,096).
// Every small tetrahedron is a copy of the big one, so its faces are written
// counter-clockwise seen from outside, as the big one's are.
#include "whitted/generators.hpp"

#include "nff_writer.hpp"

#include <ostream>
#include <stdexcept>

namespace whitted {
namespace {

using Tetrahedron = std::array<Point3, 4>;

// Emits the four faces of `t`, each ordered so that its normal points away from the opposite corner.
void emit_faces(const Tetrahedron& t, const std::function<void(const std::array<Point3, 3>&)>& visit) {
    for (int opposite = 0; opposite < 4; ++opposite) {
        std::array<Point3, 3> face;
        for (int i = 0, k = 0; i < 4; ++i)
            if (i != opposite) face[k++] = t[i];
        const Vec3 normal = glm::cross(face[1] - face[0], face[2] - face[0]);
        if (glm::dot(normal, face[0] - t[opposite]) < 0.0) std::swap(face[1], face[2]);
        visit(face);
    }
}

void subdivide(const Tetrahedron& t, int level, const std::function<void(const std::array<Point3, 3>&)>& visit) {
    if (level == 1) {
        emit_faces(t, visit);
        return;
    }
    for (int corner = 0; corner < 4; ++corner) {
        Tetrahedron part;
        for (int i = 0; i < 4; ++i) part[i] = 0.5 * (t[corner] + t[i]);
        subdivide(part, level - 1, visit);
    }
}

} // namespace

std::size_t tetra_triangle_count(int level) {
    std::size_t count = 1;
    for (int i = 0; i < level; ++i) count *= 4;
    return count;
}

void for_each_tetra_triangle(int level, const std::function<void(const std::array<Point3, 3>&)>& visit) {
    const std::string error = generator_level_error("tetra", level, kMinTetraLevel, kMaxTetraLevel);
    if (!error.empty()) throw std::invalid_argument(error);
    subdivide({Point3{1, 1, 1}, {-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}}, level, visit);
}

void write_tetra_nff(int level, std::ostream& out) {
    const std::string error = generator_level_error("tetra", level, kMinTetraLevel, kMaxTetraLevel);
    if (!error.empty()) throw std::invalid_argument(error);
    nff::comment(out, "Fractal tetrahedron, level " + std::to_string(level) + ": " +
                          std::to_string(tetra_triangle_count(level)) + " triangles (whitted generate tetra)");
    nff::background(out, {0.078, 0.361, 0.753});
    // SPD tetra's oblique view, from below one edge.
    nff::view(out, {.from = {1.02285, -3.17715, -2.17451},
                    .at = {-0.004103, -0.004103, 0.216539},
                    .up = {-0.816497, -0.816497, 0.816497},
                    .hither = 1.0});
    nff::light(out, {2, -18, -5});
    nff::fill(out, {{1, 0.2, 0.2}, 1.0, 0.0, 100000, 0.0, 1.0});
    for_each_tetra_triangle(level, [&](const std::array<Point3, 3>& corners) { nff::polygon(out, corners); });
}

} // namespace whitted
