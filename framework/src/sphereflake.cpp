// The sphereflake: a sphere with nine children a third of its size, each
// touching it, recursively; written with SPD balls' view, lights and materials.
//
// Why this geometry: every sphere has an axis, the direction from its parent
// (+z for the root). Seen along that axis, six children sit in a ring on the
// sphere's equator, 60 degrees apart starting at 15 degrees, and three sit above
// it, tilted atan(sqrt 2) up from the equator, 120 degrees apart starting at 45
// degrees. That pattern is carried from +z to each sphere's axis by the shortest
// rotation, which gives the classic flake: SPD's balls4 has the same 7,381
// spheres to its six printed digits. Straight down (-z) the shortest rotation is
// not unique; a half turn about the horizontal axis at 30 degrees matches balls4.
#include "whitted/generators.hpp"

#include "nff_writer.hpp"

#include <array>
#include <cmath>
#include <ostream>
#include <stdexcept>

namespace whitted {
namespace {

// The nine child directions around +z.
std::array<Vec3, 9> child_pattern() {
    std::array<Vec3, 9> pattern;
    for (int k = 0; k < 6; ++k) {
        const double azimuth = radians(15.0 + 60.0 * k);
        pattern[k] = {std::cos(azimuth), std::sin(azimuth), 0.0};
    }
    const double horizontal = 1.0 / std::sqrt(3.0), vertical = std::sqrt(2.0 / 3.0);
    for (int k = 0; k < 3; ++k) {
        const double azimuth = radians(45.0 + 120.0 * k);
        pattern[6 + k] = {horizontal * std::cos(azimuth), horizontal * std::sin(azimuth), vertical};
    }
    return pattern;
}

// `v` turned by the shortest rotation that takes +z to the unit vector `axis`.
Vec3 carry_from_z(const Vec3& axis, const Vec3& v) {
    const double cosine = axis.z;
    if (cosine < -1.0 + 1e-9) {
        const Vec3 k{std::cos(radians(30.0)), std::sin(radians(30.0)), 0.0};
        return 2.0 * glm::dot(k, v) * k - v; // half turn about k
    }
    const Vec3 turn{-axis.y, axis.x, 0.0}; // z x axis: the rotation axis scaled by the sine
    // Rodrigues' formula with the unnormalised axis: v cos + (turn x v) + turn (turn . v) / (1 + cos).
    return v * cosine + glm::cross(turn, v) + turn * (glm::dot(turn, v) / (1.0 + cosine));
}

struct FlakeWalk {
    const std::array<Vec3, 9> pattern = child_pattern();
    const std::function<void(const FlakeSphere&)>& visit;
    std::size_t next_index = 0;

    void sphere(FlakeSphere s, int levels_below) {
        s.index = next_index++;
        visit(s);
        if (levels_below == 0) return;
        const double child_radius = s.radius / 3.0;
        for (const Vec3& direction : pattern) {
            FlakeSphere child;
            child.parent = s.index;
            child.axis = carry_from_z(s.axis, direction);
            child.centre = s.centre + child.axis * (s.radius + child_radius);
            child.radius = child_radius;
            sphere(child, levels_below - 1);
        }
    }
};

} // namespace

std::size_t sphereflake_sphere_count(int level) {
    std::size_t count = 0, layer = 1;
    for (int i = 0; i <= level; ++i, layer *= 9) count += layer;
    return count;
}

void for_each_flake_sphere(int level, const std::function<void(const FlakeSphere&)>& visit) {
    const std::string error = generator_level_error("sphereflake", level, 0, kMaxSphereflakeLevel);
    if (!error.empty()) throw std::invalid_argument(error);
    FlakeSphere root;
    root.radius = 0.5;
    FlakeWalk{.visit = visit}.sphere(root, level);
}

void write_sphereflake_nff(int level, std::ostream& out) {
    const std::string error = generator_level_error("sphereflake", level, 0, kMaxSphereflakeLevel);
    if (!error.empty()) throw std::invalid_argument(error);
    nff::comment(out, "Sphereflake, level " + std::to_string(level) + ": " +
                          std::to_string(sphereflake_sphere_count(level)) + " spheres (whitted generate sphereflake)");
    nff::background(out, {0.078, 0.361, 0.753});
    nff::view(out, {.from = {2.1, 1.3, 1.7}, .at = {0, 0, 0}, .up = {0, 0, 1}, .hither = 0.01});
    for (const Point3 light : {Point3{4, 3, 2}, Point3{1, -4, 4}, Point3{-3, 1, 5}}) nff::light(out, light);
    // The ground: a dull yellow square just under the root sphere, without highlight.
    nff::fill(out, {{1, 0.75, 0.33}, 0.8, 0.0, 100000, 0.0, 1.0});
    const std::array<Point3, 4> ground{Point3{12, 12, -0.5}, {-12, 12, -0.5}, {-12, -12, -0.5}, {12, -12, -0.5}};
    nff::polygon(out, ground);
    // The flake: a warm, half-mirror material.
    nff::fill(out, {{1, 0.9, 0.7}, 0.5, 0.5, 3.0827, 0.0, 1.0});
    for_each_flake_sphere(level, [&](const FlakeSphere& s) { nff::sphere(out, s.centre, s.radius); });
}

} // namespace whitted
