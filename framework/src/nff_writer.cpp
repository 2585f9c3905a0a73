// Writing NFF text for the scene generators (see nff_writer.hpp).
#include "nff_writer.hpp"

#include <cstdio>
#include <ostream>

namespace whitted::nff {
namespace {

std::string triple(const Vec3& v) { return number(v.x) + ' ' + number(v.y) + ' ' + number(v.z); }

} // namespace

std::string number(double x) {
    if (x == 0.0) x = 0.0; // no "-0"
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", x);
    return text;
}

void comment(std::ostream& out, const std::string& text) { out << "# " << text << '\n'; }

void background(std::ostream& out, const Color& colour) { out << "b " << triple(colour) << '\n'; }

void view(std::ostream& out, const View& v) {
    out << "v\nfrom " << triple(v.from) << "\nat " << triple(v.at) << "\nup " << triple(v.up) << "\nangle "
        << number(v.angle) << "\nhither " << number(v.hither) << "\nresolution " << v.width << ' ' << v.height << '\n';
}

void light(std::ostream& out, const Point3& position) { out << "l " << triple(position) << '\n'; }

void fill(std::ostream& out, const Fill& f) {
    out << "f " << triple(f.colour) << ' ' << number(f.kd) << ' ' << number(f.ks) << ' ' << number(f.shine) << ' '
        << number(f.t) << ' ' << number(f.ior) << '\n';
}

void polygon(std::ostream& out, std::span<const Point3> corners) {
    out << "p " << corners.size() << '\n';
    for (const Point3& corner : corners) out << triple(corner) << '\n';
}

void sphere(std::ostream& out, const Point3& centre, double radius) {
    out << "s " << triple(centre) << ' ' << number(radius) << '\n';
}

} // namespace whitted::nff
