// Writing NFF text: numbers with nine significant digits, and the few entities
// the generators need (view, background, light, material, polygon, sphere).
//
// Why: generated scenes must survive the trip through text unchanged enough for
// exact tests (a child touching its parent to 1e-9), and every generator writes
// the same entities; one writer keeps the format in one place.
#pragma once

#include "whitted/math.hpp"

#include <iosfwd>
#include <span>
#include <string>

namespace whitted::nff {

/// The viewpoint of an NFF `v` entity.
struct View {
    Point3 from, at;
    Vec3 up;
    double angle = 45.0; // degrees, between the centres of the top and bottom pixel rows
    double hither = 0.01;
    int width = 512, height = 512;
};

/// An NFF `f` material: colour, Kd, Ks, Shine, T, ior.
struct Fill {
    Color colour;
    double kd, ks, shine, t, ior;
};

/// `x` with nine significant digits (%.9g): enough for single precision round trips and exact tests.
std::string number(double x);

/// Writes a `#` comment line.
void comment(std::ostream& out, const std::string& text);

/// Writes the `b` background line.
void background(std::ostream& out, const Color& colour);

/// Writes the `v` block.
void view(std::ostream& out, const View& v);

/// Writes an `l` light without a colour (SPD style: the loader shares the intensity out).
void light(std::ostream& out, const Point3& position);

/// Writes an `f` material line.
void fill(std::ostream& out, const Fill& f);

/// Writes a `p` polygon, one vertex a line.
void polygon(std::ostream& out, std::span<const Point3> corners);

/// Writes an `s` sphere line.
void sphere(std::ostream& out, const Point3& centre, double radius);

} // namespace whitted::nff
