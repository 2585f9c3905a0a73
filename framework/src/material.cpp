#include "whitted/material.hpp"

#include <cmath>

namespace whitted {

Color Material::color_at(const Point3& p) const {
    if (!checker) return color;
    // Cubes of side `size`: the parity of the cube's integer coordinates picks the colour.
    // A tiny bias keeps points lying exactly on a cube face (y = 0 for a floor) on one side.
    const Vec3 cell = glm::floor(p / checker->size + Vec3(1e-9));
    const long long parity = static_cast<long long>(cell.x) + static_cast<long long>(cell.y) +
                             static_cast<long long>(cell.z);
    return (parity & 1) == 0 ? checker->color_a : checker->color_b;
}

} // namespace whitted
