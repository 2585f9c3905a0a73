// The list of scene generators, and the one check every generator makes.
//
// Why: `whitted generate` and `whitted-bench` both pick generators by name and
// must reject a bad level with the same one-line message; the table keeps each
// generator's name, level range and writer together.
#include "whitted/generators.hpp"

#include <array>

namespace whitted {
namespace {

constexpr std::array<Generator, 4> kGenerators{{
    {"sphereflake", "flake", "spheres", ".nff", 0, kMaxSphereflakeLevel, 4, sphereflake_sphere_count, write_sphereflake_nff},
    {"tetra", "tetra", "triangles", ".nff", kMinTetraLevel, kMaxTetraLevel, 6, tetra_triangle_count, write_tetra_nff},
    {"torus", "torus", "triangles", ".p3f", kMinTorusLevel, kMaxTorusLevel, 5, torus_triangle_count, write_torus_p3f},
    {"soup", "soup", "triangles", ".nff", kMinSoupLevel, kMaxSoupLevel, 3, soup_triangle_count, write_soup_nff},
}};

} // namespace

std::string generator_level_error(const std::string& kind, int level, int low, int high) {
    if (level >= low && level <= high) return {};
    return kind + " level must be " + std::to_string(low) + " to " + std::to_string(high) + ", found " +
           std::to_string(level);
}

std::span<const Generator> generators() { return kGenerators; }

const Generator* find_generator(std::string_view name) {
    for (const Generator& generator : kGenerators)
        if (generator.name == name) return &generator;
    return nullptr;
}

} // namespace whitted
