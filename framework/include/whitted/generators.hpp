// Procedural benchmark scenes in the spirit of Eric Haines' Standard Procedural
// Databases: the sphereflake and the fractal tetrahedron, written as NFF.
//
// Why: a benchmark needs scenes of any size with a known primitive count, and
// the project cannot ship SPD's output. These generators derive the same shapes
// from their geometric rules, with SPD's view, lights and materials, so that a
// level-4 sphereflake is comparable to SPD's balls4 and level 6 of the
// tetrahedron to tetra6. Both are visited without building a list, so a
// five-million-sphere flake streams straight to a file.
#pragma once

#include "whitted/math.hpp"

#include <array>
#include <cstddef>
#include <functional>
#include <iosfwd>
#include <span>
#include <string>
#include <string_view>

namespace whitted {

inline constexpr int kMaxSphereflakeLevel = 7; // 5,380,840 spheres
inline constexpr int kMinTetraLevel = 1;       // one tetrahedron, 4 triangles
inline constexpr int kMaxTetraLevel = 9;       // 262,144 triangles
inline constexpr int kMinTorusLevel = 1;       // 392 triangles
inline constexpr int kMaxTorusLevel = 7;       // 1,605,632 triangles
inline constexpr int kMinSoupLevel = 1;        // 1,000 triangles
inline constexpr int kMaxSoupLevel = 6;        // 1,024,000 triangles

/// One sphere of a sphereflake; the root has index 0 and no parent.
struct FlakeSphere {
    std::size_t index = 0;  // in visiting order, parents before their children
    std::size_t parent = 0; // the parent's index (0 for the root, which has none)
    Point3 centre{0.0};
    double radius = 0.0;
    Vec3 axis{0.0, 0.0, 1.0}; // unit direction from the parent's centre; +z for the root
};

/// Number of spheres in a flake of `level`: 1 + 9 + ... + 9^level.
std::size_t sphereflake_sphere_count(int level);

/// Calls `visit` for each sphere of the flake, every parent before its children.
/// Throws std::invalid_argument when the level is outside 0..kMaxSphereflakeLevel.
void for_each_flake_sphere(int level, const std::function<void(const FlakeSphere&)>& visit);

/// Writes the whole NFF scene: view, background, 3 lights, ground square and flake.
void write_sphereflake_nff(int level, std::ostream& out);

/// Number of triangles of a fractal tetrahedron of `level`: 4^level.
std::size_t tetra_triangle_count(int level);

/// Calls `visit` with each triangle's corners, counter-clockwise seen from outside.
/// Throws std::invalid_argument when the level is outside kMinTetraLevel..kMaxTetraLevel.
void for_each_tetra_triangle(int level, const std::function<void(const std::array<Point3, 3>&)>& visit);

/// Writes the whole NFF scene: view, background, one light and the triangles.
void write_tetra_nff(int level, std::ostream& out);

/// Number of triangles of the bumpy torus of `level`: 2 n^2 with n = 7 2^level.
std::size_t torus_triangle_count(int level);

/// Writes the whole P3F scene: `accel 2`, view, lights, a floor and the torus as one `mesh`.
void write_torus_p3f(int level, std::ostream& out);

/// Number of triangles of the random triangle soup of `level`: 1,000 4^(level - 1).
std::size_t soup_triangle_count(int level);

/// Calls `visit` with each triangle of the soup, the same ones on every machine.
/// Throws std::invalid_argument when the level is outside kMinSoupLevel..kMaxSoupLevel.
void for_each_soup_triangle(int level, const std::function<void(const std::array<Point3, 3>&)>& visit);

/// Writes the whole NFF scene: view, background, two lights and the triangles in six clusters.
void write_soup_nff(int level, std::ostream& out);

/// The one-line message for a level outside `low..high`, or "" when it is inside.
std::string generator_level_error(const std::string& kind, int level, int low, int high);

/// A generator by name, for `whitted generate` and `whitted-bench`.
struct Generator {
    std::string_view name;          // "sphereflake", "tetra"
    std::string_view short_name;    // file names: "flake4.nff", "tetra6.nff"
    std::string_view what;          // "spheres", "triangles"
    std::string_view extension;     // ".nff" or ".p3f": the dialect it writes
    int min_level, max_level, default_level;
    std::size_t (*primitive_count)(int level);
    void (*write)(int level, std::ostream& out); // throws std::invalid_argument for a bad level
};

/// Every generator, sphereflake first.
std::span<const Generator> generators();

/// The generator called `name`, or nullptr.
const Generator* find_generator(std::string_view name);

} // namespace whitted
