#include "polygon.hpp"

#include <algorithm>
#include <cmath>

namespace whitted::detail {

namespace {

/// Twice the signed area of the 2D triangle a, b, c (positive when counter-clockwise).
double cross2(const Vec2& a, const Vec2& b, const Vec2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/// True when p lies inside the counter-clockwise triangle a, b, c or on its border.
bool inside_or_on(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
    return cross2(a, b, p) >= 0.0 && cross2(b, c, p) >= 0.0 && cross2(c, a, p) >= 0.0;
}

/// The corners that are not convex, filed in a uniform grid: only they can lie
/// inside an ear, and the grid finds those near a candidate ear quickly.
class CornerGrid {
  public:
    CornerGrid(const std::vector<Vec2>& points, std::size_t expected) {
        low_ = high_ = points[0];
        for (const Vec2& p : points) {
            low_ = glm::min(low_, p);
            high_ = glm::max(high_, p);
        }
        side_ = std::clamp<std::size_t>(static_cast<std::size_t>(std::sqrt(static_cast<double>(expected))), 1, 1024);
        cells_.resize(side_ * side_);
    }

    void insert(std::size_t corner, const Vec2& p) { cells_[cell_x(p.x) + side_ * cell_y(p.y)].push_back(corner); }

    /// Calls keep(corner) for every filed corner in the cells the box touches; entries for which it returns false are dropped.
    template <class Keep> void visit(const Vec2& box_low, const Vec2& box_high, Keep keep) {
        for (std::size_t y = cell_y(box_low.y); y <= cell_y(box_high.y); ++y) {
            for (std::size_t x = cell_x(box_low.x); x <= cell_x(box_high.x); ++x) {
                std::vector<std::size_t>& cell = cells_[x + side_ * y];
                std::size_t kept = 0;
                for (const std::size_t corner : cell)
                    if (keep(corner)) cell[kept++] = corner;
                cell.resize(kept);
            }
        }
    }

  private:
    std::size_t cell(double value, double low, double high) const {
        const double t = high > low ? (value - low) / (high - low) : 0.0;
        return std::min(side_ - 1, static_cast<std::size_t>(std::max(0.0, t * static_cast<double>(side_))));
    }
    std::size_t cell_x(double x) const { return cell(x, low_.x, high_.x); }
    std::size_t cell_y(double y) const { return cell(y, low_.y, high_.y); }

    Vec2 low_, high_;
    std::size_t side_ = 1;
    std::vector<std::vector<std::size_t>> cells_;
};

/// Ear clipping over a circular doubly linked list of the projected vertices.
class EarClipper {
  public:
    explicit EarClipper(std::vector<Vec2> points) : points_(std::move(points)), grid_(points_, points_.size()) {
        const std::size_t n = points_.size();
        prev_.resize(n);
        next_.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            prev_[i] = (i + n - 1) % n;
            next_[i] = (i + 1) % n;
        }
        alive_.assign(n, true);
        filed_.assign(n, false);
        remaining_ = n;
        for (std::size_t i = 0; i < n; ++i) file_if_not_convex(i);
    }

    std::vector<TriangleIndices> run() {
        std::vector<TriangleIndices> triangles;
        triangles.reserve(remaining_);
        std::size_t corner = 0;
        std::size_t stalled = 0;      // corners visited since the last change
        bool clip_any_convex = false; // set after a lap without an ear: the polygon intersects itself
        while (remaining_ > 3) {
            const std::size_t a = prev_[corner], c = next_[corner];
            const double turn = turn_at(corner);
            if (turn == 0.0) { // collinear or duplicate: drop it, no area is lost
                corner = remove(corner);
                stalled = 0;
            } else if (turn > 0.0 && (clip_any_convex || is_ear(a, corner, c))) {
                triangles.push_back({a, corner, c});
                corner = next_[remove(corner)]; // moving on past c avoids growing a fan of slivers around a
                stalled = 0;
            } else if (stalled > remaining_ && !clip_any_convex) {
                // A full lap without an ear (self-intersection or rounding): from now on clip any
                // convex corner, without searching for ears again (that would cost a lap per clip).
                clip_any_convex = true;
                stalled = 0;
            } else if (stalled > remaining_) {
                break; // no convex corner left: what remains has no area
            } else {
                corner = next_[corner];
                ++stalled;
            }
        }
        if (remaining_ == 3 && turn_at(corner) > 0.0) triangles.push_back({prev_[corner], corner, next_[corner]});
        return triangles;
    }

  private:
    /// The turn at a corner: > 0 convex, < 0 reflex, 0 when (nearly) collinear.
    double turn_at(std::size_t i) const {
        const Vec2& a = points_[prev_[i]];
        const Vec2& b = points_[i];
        const Vec2& c = points_[next_[i]];
        const double turn = cross2(a, b, c);
        const double scale = glm::length(b - a) * glm::length(c - b);
        return std::abs(turn) <= 1e-12 * scale ? 0.0 : turn;
    }

    void file_if_not_convex(std::size_t i) {
        if (!filed_[i] && turn_at(i) <= 0.0) {
            filed_[i] = true;
            grid_.insert(i, points_[i]);
        }
    }

    /// True when no other corner lies in the triangle a, b, c (only corners that are not convex can).
    bool is_ear(std::size_t a, std::size_t b, std::size_t c) {
        const Vec2 &pa = points_[a], &pb = points_[b], &pc = points_[c];
        bool ear = true;
        grid_.visit(glm::min(pa, glm::min(pb, pc)), glm::max(pa, glm::max(pb, pc)), [&](std::size_t i) {
            if (!alive_[i] || turn_at(i) > 0.0) { // gone or convex now: forget it
                filed_[i] = false;
                return false;
            }
            if (!ear || i == a || i == b || i == c) return true;
            const Vec2& p = points_[i];
            if (p != pa && p != pb && p != pc && inside_or_on(p, pa, pb, pc)) ear = false;
            return true;
        });
        return ear;
    }

    /// Unlinks a corner and returns its successor.
    std::size_t remove(std::size_t i) {
        const std::size_t a = prev_[i], c = next_[i];
        next_[a] = c;
        prev_[c] = a;
        alive_[i] = false;
        --remaining_;
        file_if_not_convex(a);
        file_if_not_convex(c);
        return c;
    }

    std::vector<Vec2> points_;
    CornerGrid grid_;
    std::vector<std::size_t> prev_, next_;
    std::vector<bool> alive_, filed_;
    std::size_t remaining_ = 0;
};

} // namespace

Vec3 newell_normal(std::span<const Point3> vertices) {
    Vec3 normal(0.0);
    if (vertices.empty()) return normal;
    const Point3 origin = vertices[0]; // relative coordinates keep far-away polygons precise
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const Vec3 a = vertices[i] - origin;
        const Vec3 b = vertices[(i + 1) % vertices.size()] - origin;
        normal.x += (a.y - b.y) * (a.z + b.z);
        normal.y += (a.z - b.z) * (a.x + b.x);
        normal.z += (a.x - b.x) * (a.y + b.y);
    }
    return normal;
}

std::vector<TriangleIndices> triangulate_polygon(std::span<const Point3> vertices) {
    if (vertices.size() < 3) return {};
    const Vec3 normal = newell_normal(vertices);
    Vec3 low = vertices[0], high = vertices[0];
    for (const Point3& p : vertices) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    const double extent = max_abs_component(high - low);
    if (!(glm::length(normal) > 1e-12 * extent * extent)) return {};
    if (vertices.size() == 3) return {{0, 1, 2}}; // keeps the corners in the order they were written

    // Project on the plane of the two axes other than the normal's dominant one, in
    // cyclic order (x,y), (y,z) or (z,x); swap them when needed so the polygon runs counter-clockwise.
    const Vec3 magnitude = glm::abs(normal);
    const int axis = magnitude.x >= magnitude.y && magnitude.x >= magnitude.z ? 0 : (magnitude.y >= magnitude.z ? 1 : 2);
    int u = (axis + 1) % 3, v = (axis + 2) % 3;
    if (normal[axis] < 0.0) std::swap(u, v);
    std::vector<Vec2> points;
    points.reserve(vertices.size());
    for (const Point3& p : vertices) points.emplace_back(p[u] - vertices[0][u], p[v] - vertices[0][v]);

    return EarClipper(std::move(points)).run();
}

} // namespace whitted::detail
