// A random triangle soup: triangles of every size and orientation, many of them
// slivers, crowded into a few clusters of different densities, with empty space
// between them; written as NFF.
//
// Why: the SPD scenes are regular (a fractal, a tessellated teapot, a height
// field), and an acceleration structure tuned on them may fail on what scanned
// or hand-modelled scenes look like. This scene is none of them: the benchmark
// measures it without being tuned to it. The numbers come from SplitMix64 with a
// fixed seed and are turned into doubles by hand, not by a standard library's
// distributions, and written with nine digits, so the file is the same wherever
// sin, cos, cbrt and exp2 round alike (a last-bit difference between maths
// libraries would almost never show in nine digits).
#include "whitted/generators.hpp"

#include "nff_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <ostream>
#include <stdexcept>

namespace whitted {
namespace {

constexpr int kClusters = 6;

// SplitMix64 (Steele, Lea and Flood): a tiny generator with well-mixed output.
struct SplitMix64 {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, 1): the top 53 bits.
    double uniform() { return static_cast<double>(next() >> 11) * 0x1p-53; }
    /// Uniform in [low, high).
    double between(double low, double high) { return low + (high - low) * uniform(); }
    /// A direction, uniform on the unit sphere.
    Vec3 direction() {
        const double z = between(-1.0, 1.0), phi = between(0.0, 2.0 * kPi);
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        return {r * std::cos(phi), r * std::sin(phi), z};
    }
};

void check_level(int level) {
    const std::string error = generator_level_error("soup", level, kMinSoupLevel, kMaxSoupLevel);
    if (!error.empty()) throw std::invalid_argument(error);
}

} // namespace

std::size_t soup_triangle_count(int level) { return std::size_t{1000} << (2 * (level - 1)); }

void for_each_soup_triangle(int level, const std::function<void(const std::array<Point3, 3>&)>& visit) {
    check_level(level);
    SplitMix64 random{0x5eed5011b0ccull};
    // Clusters of different sizes inside [-10, 10]^3; each takes a share of the triangles that
    // does not follow its size, so some are dense and some sparse.
    std::array<Point3, kClusters> centre;
    std::array<double, kClusters> radius, share;
    double total = 0.0;
    for (int c = 0; c < kClusters; ++c) {
        for (int axis = 0; axis < 3; ++axis) centre[c][axis] = random.between(-7.0, 7.0);
        radius[c] = random.between(0.5, 3.0);
        share[c] = random.between(0.2, 1.0);
        total += share[c];
    }
    const std::size_t count = soup_triangle_count(level);
    std::size_t made = 0;
    for (int c = 0; c < kClusters; ++c) {
        const std::size_t in_cluster =
            c + 1 == kClusters ? count - made : static_cast<std::size_t>(static_cast<double>(count) * share[c] / total);
        // Triangle sizes shrink as the soup grows, so that a level covers about the same volume.
        const double size = radius[c] * 2.0 / std::cbrt(static_cast<double>(in_cluster) + 1.0);
        for (std::size_t i = 0; i < in_cluster; ++i) {
            // One draw a statement: the order of two calls inside one expression is the compiler's choice.
            const Vec3 way = random.direction();
            const Point3 middle = centre[c] + random.between(0.0, radius[c]) * way;
            const double edge = size * std::exp2(random.between(-2.0, 1.0)); // a spread of 8 in size
            std::array<Point3, 3> corners;
            if (random.uniform() < 0.2) { // a sliver: long and thin
                const Vec3 along = random.direction(), across = random.direction();
                corners = {middle - 2.0 * edge * along, middle + 2.0 * edge * along, middle + 0.05 * edge * across};
            } else {
                for (Point3& corner : corners) corner = middle + edge * random.direction();
            }
            visit(corners);
        }
        made += in_cluster;
    }
}

void write_soup_nff(int level, std::ostream& out) {
    check_level(level);
    nff::comment(out, "Random triangle soup, level " + std::to_string(level) + ": " +
                          std::to_string(soup_triangle_count(level)) + " triangles in " + std::to_string(kClusters) +
                          " clusters (whitted generate soup)");
    nff::background(out, {0.08, 0.1, 0.2});
    nff::view(out, {.from = {0.0, -32.0, 9.0}, .at = {0.0, 0.0, 0.0}, .up = {0.0, 0.0, 1.0}, .angle = 40.0});
    nff::light(out, {-20.0, -25.0, 30.0});
    nff::light(out, {25.0, -10.0, 15.0});
    nff::fill(out, {{0.75, 0.7, 0.6}, 0.7, 0.3, 30.0, 0.0, 1.0});
    for_each_soup_triangle(level, [&](const std::array<Point3, 3>& corners) { nff::polygon(out, corners); });
}

} // namespace whitted
