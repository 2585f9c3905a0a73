// A dense bumpy torus written as one P3F `mesh`: the stand-in for a scanned
// model (a dragon or a statue) when a lab needs a hundred thousand triangles.
//
// Why this geometry: a torus has no poles, so every triangle of its grid has an
// area; bumps of several frequencies make its silhouette and shading busy like
// a scan's, and its triangles are small and many, as a scan's are. Level L has
// a grid of n x n quads with n = 7 2^L, so 2 n^2 triangles: level 5 is 100,352.
#include "whitted/generators.hpp"

#include <cmath>
#include <cstdio>
#include <ostream>
#include <stdexcept>
#include <string>

namespace whitted {
namespace {

int grid_size(int level) { return 7 << level; }

/// The point of the torus at angles (u, v): around the ring and around the tube.
Point3 torus_point(double u, double v) {
    const double bumps = 0.06 * std::sin(7.0 * u) * std::sin(5.0 * v) + 0.025 * std::sin(23.0 * u + 3.0 * v) +
                         0.012 * std::cos(41.0 * v - 11.0 * u);
    const double tube = 0.42 + bumps;
    const double ring = 1.0 + tube * std::cos(v);
    return Point3(ring * std::cos(u), tube * std::sin(v), ring * std::sin(u));
}

void line(std::ostream& out, const char* format, double a, double b, double c) {
    char text[96];
    std::snprintf(text, sizeof text, format, a, b, c);
    out << text;
}

} // namespace

std::size_t torus_triangle_count(int level) {
    const auto n = static_cast<std::size_t>(grid_size(level));
    return 2 * n * n;
}

void write_torus_p3f(int level, std::ostream& out) {
    const std::string error = generator_level_error("torus", level, kMinTorusLevel, kMaxTorusLevel);
    if (!error.empty()) throw std::invalid_argument(error);
    const int n = grid_size(level);
    out << "# A bumpy torus, level " << level << ": " << torus_triangle_count(level)
        << " triangles in one mesh (whitted generate torus)\n"
        << "accel 2\nspp 0\n"
        << "v\nfrom 0 2.6 -3.2\nat 0 -0.1 0\nup 0 1 0\nangle 40\nhither 0.01\nresolution 800 600\n"
        << "bclr 0.12 0.14 0.2\nambient 0.15 0.15 0.15\n"
        << "l 4 6 -3  0.8 0.8 0.75\nl -5 3 -2  0.3 0.35 0.45\n"
        << "f 0.55 0.5 0.45  0.8  1 1 1 0.1  30 0 1\npl 0 -0.6 0  1 -0.6 0  0 -0.6 1\n"
        << "f 0.8 0.55 0.3  0.85  1 1 1 0.25  60 0 1\n"
        << "mesh " << n * n << ' ' << 2 * n * n << '\n';
    const double step = 2.0 * kPi / n;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const Point3 p = torus_point(i * step, j * step);
            line(out, "%.6f %.6f %.6f\n", p.x, p.y, p.z);
        }
    // Vertex (i, j) is number i n + j + 1; each quad's two triangles face outwards.
    const auto vertex = [n](int i, int j) { return static_cast<double>((i % n) * n + (j % n) + 1); };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            line(out, "%.0f %.0f %.0f\n", vertex(i, j), vertex(i, j + 1), vertex(i + 1, j + 1));
            line(out, "%.0f %.0f %.0f\n", vertex(i, j), vertex(i + 1, j + 1), vertex(i + 1, j));
        }
}

} // namespace whitted
