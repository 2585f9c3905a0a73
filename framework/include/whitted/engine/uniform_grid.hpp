// A uniform grid over bounded primitives: the course's other acceleration
// structure (P3F `accel 1`).
//
// Why: a grid is the simplest structure that beats testing everything. The
// scene's box is cut into equal cells, about two per primitive; each cell lists
// the primitives whose boxes overlap it, and a ray walks the cells it crosses
// in order (Amanatides and Woo's 3D DDA), stopping at the first cell whose
// nearest hit lies inside it. It adapts badly to uneven scenes (a teapot in a
// stadium), which is what the BVH of lab 10 fixes: `whitted render --accel
// grid|bvh` shows both.
#pragma once

#include "whitted/aabb.hpp"
#include "whitted/hit.hpp"
#include "whitted/interval.hpp"
#include "whitted/primitive.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace whitted {

class UniformGrid {
  public:
    /// Builds the grid over the boxes (box i is primitive i's).
    explicit UniformGrid(std::span<const Aabb> boxes);

    /// The nearest hit among `primitives` (those the boxes were of) with t inside t_range.
    std::optional<Hit> closest_hit(const Ray& ray, std::span<const Primitive> primitives, Interval t_range) const;
    /// True when any of `primitives` is hit with t inside t_range.
    bool occluded(const Ray& ray, std::span<const Primitive> primitives, Interval t_range) const;

    /// Cells along x, y and z.
    const std::array<int, 3>& resolution() const { return cells_; }
    /// Bytes held by the cell lists.
    std::size_t bytes() const { return first_.size() * sizeof(std::uint32_t) + items_.size() * sizeof(std::uint32_t); }

  private:
    /// Calls `visit(primitive indices of the cell, t where the ray leaves the cell)` for the
    /// cells the ray crosses within t_range, in order, until `visit` returns false.
    template <class Visit>
    void walk(const Ray& ray, Interval t_range, Visit&& visit) const;

    std::size_t cell_index(int x, int y, int z) const {
        return (static_cast<std::size_t>(z) * cells_[1] + y) * cells_[0] + x;
    }

    Aabb bounds_;
    std::array<int, 3> cells_{1, 1, 1};
    Vec3 cell_size_{1.0};
    std::vector<std::uint32_t> first_; // cell c's primitives are items_[first_[c] .. first_[c + 1])
    std::vector<std::uint32_t> items_;
};

} // namespace whitted
