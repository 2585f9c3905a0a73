#include "whitted/engine/uniform_grid.hpp"

#include "clip_to_box.hpp"

#include "whitted/labs.hpp"

#include <algorithm>
#include <cmath>

namespace whitted {
namespace {

constexpr double kCellsPerPrimitive = 2.0;
constexpr int kMostCellsPerAxis = 512;
constexpr double kMostCells = 1 << 24; // 64 MiB of cell offsets at most

} // namespace

UniformGrid::UniformGrid(std::span<const Aabb> boxes) {
    for (const Aabb& box : boxes) bounds_.expand(box);
    if (boxes.empty()) {
        bounds_ = Aabb{Point3(0.0), Point3(1.0)};
        first_.assign(2, 0);
        return;
    }
    // A little larger than the boxes, and never flat: every point of a box falls in a cell.
    const double largest = std::max(1.0, max_abs_component(bounds_.max - bounds_.min));
    bounds_.min -= Vec3(1e-7 * largest);
    bounds_.max += Vec3(1e-7 * largest);
    const Vec3 extent = bounds_.max - bounds_.min;
    // Cells as close to cubes as the box allows, about kCellsPerPrimitive per primitive.
    const double per_length = std::cbrt(kCellsPerPrimitive * static_cast<double>(boxes.size()) / (extent.x * extent.y * extent.z));
    for (int axis = 0; axis < 3; ++axis)
        cells_[axis] = std::clamp(static_cast<int>(std::ceil(extent[axis] * per_length)), 1, kMostCellsPerAxis);
    while (static_cast<double>(cells_[0]) * cells_[1] * cells_[2] > kMostCells) // a huge scene: halve every axis
        for (int& n : cells_) n = std::max(1, n / 2);
    for (int axis = 0; axis < 3; ++axis) cell_size_[axis] = extent[axis] / cells_[axis];

    // The cells a box overlaps, as a range per axis.
    const auto cell_range = [this](const Aabb& box, int axis) {
        const auto cell = [&](double v) {
            return std::clamp(static_cast<int>(std::floor((v - bounds_.min[axis]) / cell_size_[axis])), 0, cells_[axis] - 1);
        };
        return std::pair{cell(box.min[axis]), cell(box.max[axis])};
    };
    // Two passes: count each cell's primitives, then place them (one array for all cells).
    const std::size_t cell_count = static_cast<std::size_t>(cells_[0]) * cells_[1] * cells_[2];
    std::vector<std::uint32_t> count(cell_count + 1, 0);
    const auto for_each_cell = [&](const Aabb& box, auto&& visit) {
        const auto [x0, x1] = cell_range(box, 0);
        const auto [y0, y1] = cell_range(box, 1);
        const auto [z0, z1] = cell_range(box, 2);
        for (int z = z0; z <= z1; ++z)
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x) visit(cell_index(x, y, z));
    };
    for (const Aabb& box : boxes) for_each_cell(box, [&](std::size_t c) { ++count[c + 1]; });
    for (std::size_t c = 0; c < cell_count; ++c) count[c + 1] += count[c];
    first_ = count;
    items_.resize(first_.back());
    for (std::uint32_t i = 0; i < boxes.size(); ++i) for_each_cell(boxes[i], [&](std::size_t c) { items_[count[c]++] = i; });
}

template <class Visit>
void UniformGrid::walk(const Ray& ray, Interval t_range, Visit&& visit) const {
    // Where the ray is inside the grid's box.
    const Vec3 inv_direction = 1.0 / ray.direction;
    const std::optional<Interval> inside = clip_to_box(ray, inv_direction, bounds_, t_range);
    if (!inside) return;
    const double t_enter = inside->min, t_exit = inside->max;
    // The first cell, and for each axis the t of the next cell wall and the t between walls.
    const Point3 start = ray.at(t_enter);
    std::array<int, 3> cell{}, step{};
    std::array<double, 3> t_next{}, t_delta{};
    for (int axis = 0; axis < 3; ++axis) {
        const double d = ray.direction[axis];
        cell[axis] = std::clamp(static_cast<int>(std::floor((start[axis] - bounds_.min[axis]) / cell_size_[axis])), 0,
                                cells_[axis] - 1);
        const double wall = bounds_.min[axis] + (cell[axis] + (d > 0.0 ? 1 : 0)) * cell_size_[axis];
        step[axis] = d > 0.0 ? 1 : d < 0.0 ? -1 : 0;
        t_next[axis] = step[axis] != 0 ? (wall - ray.origin[axis]) * inv_direction[axis] : kInfinity;
        t_delta[axis] = step[axis] != 0 ? cell_size_[axis] * std::abs(inv_direction[axis]) : kInfinity;
    }
    // Each step crosses one wall, so a ray crosses at most this many cells.
    for (int steps = cells_[0] + cells_[1] + cells_[2]; steps >= 0; --steps) {
        const int axis = t_next[0] < t_next[1] ? (t_next[0] < t_next[2] ? 0 : 2) : (t_next[1] < t_next[2] ? 1 : 2);
        const std::size_t c = cell_index(cell[0], cell[1], cell[2]);
        const std::span<const std::uint32_t> items(items_.data() + first_[c], first_[c + 1] - first_[c]);
        if (!visit(items, std::min(t_next[axis], t_exit))) return;
        if (!(t_next[axis] <= t_exit)) return;
        cell[axis] += step[axis];
        if (cell[axis] < 0 || cell[axis] >= cells_[axis]) return;
        t_next[axis] += t_delta[axis];
    }
}

std::optional<Hit> UniformGrid::closest_hit(const Ray& ray, std::span<const Primitive> primitives, Interval t_range) const {
    std::optional<Hit> nearest;
    walk(ray, t_range, [&](std::span<const std::uint32_t> items, double cell_exit) {
        for (const std::uint32_t i : items)
            if (std::optional<Hit> hit = intersect(ray, primitives[i], t_range)) {
                nearest = hit;
                t_range.max = hit->t;
            }
        // A hit inside this cell is nearer than anything in the cells after it; one beyond it may not be.
        return !(nearest && nearest->t <= cell_exit);
    });
    return nearest;
}

bool UniformGrid::occluded(const Ray& ray, std::span<const Primitive> primitives, Interval t_range) const {
    bool blocked = false;
    walk(ray, t_range, [&](std::span<const std::uint32_t> items, double) {
        for (const std::uint32_t i : items)
            if (intersect(ray, primitives[i], t_range)) return !(blocked = true);
        return true;
    });
    return blocked;
}

} // namespace whitted
