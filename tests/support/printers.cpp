#include "printers.hpp"

#include "scene_tokens.hpp"

#include <initializer_list>
#include <ostream>
#include <string>
#include <variant>

namespace {

using whitted::detail::format_number; // the shortest text that reads back as the same double

/// "(x, y, ...)", built by appending (GCC 12 warns, wrongly, of an overlap in "(" + a string).
std::string coordinates(std::initializer_list<double> values) {
    std::string text = "(";
    for (const double value : values) {
        if (text.size() > 1) text += ", ";
        text += format_number(value);
    }
    text += ')';
    return text;
}

std::string coordinates(const glm::dvec2& v) { return coordinates({v.x, v.y}); }

std::string coordinates(const glm::dvec3& v) { return coordinates({v.x, v.y, v.z}); }

} // namespace

namespace glm {

void PrintTo(const dvec2& v, std::ostream* os) { *os << coordinates(v); }

void PrintTo(const dvec3& v, std::ostream* os) { *os << coordinates(v); }

} // namespace glm

namespace whitted {

void PrintTo(const Ray& ray, std::ostream* os) {
    *os << "Ray{origin " << coordinates(ray.origin) << ", direction " << coordinates(ray.direction) << "}";
}

void PrintTo(const Hit& hit, std::ostream* os) {
    *os << "Hit{t " << format_number(hit.t) << ", point " << coordinates(hit.point) << ", normal " << coordinates(hit.normal)
        << ", geometric_normal " << coordinates(hit.geometric_normal) << (hit.front_face ? ", front face" : ", back face")
        << ", uv " << coordinates(hit.uv) << ", primitive " << hit.primitive << ", material " << hit.material << "}";
}

void PrintTo(const Interval& interval, std::ostream* os) {
    *os << "Interval{min " << format_number(interval.min) << ", max " << format_number(interval.max) << "}";
}

void PrintTo(const Aabb& box, std::ostream* os) { *os << "Aabb{min " << coordinates(box.min) << ", max " << coordinates(box.max) << "}"; }

void PrintTo(const PointLight& light, std::ostream* os) {
    *os << "PointLight{position " << coordinates(light.position) << ", color " << coordinates(light.color) << "}";
}

void PrintTo(const AreaLight& light, std::ostream* os) {
    *os << "AreaLight{center " << coordinates(light.center) << ", color " << coordinates(light.color) << ", edge_u " << coordinates(light.edge_u)
        << ", edge_v " << coordinates(light.edge_v) << ", samples " << light.samples << ", first_number " << light.first_number << "}";
}

void PrintTo(const Camera& camera, std::ostream* os) {
    *os << "Camera{eye " << coordinates(camera.eye) << ", at " << coordinates(camera.at) << ", up " << coordinates(camera.up) << ", fovy "
        << format_number(camera.fovy) << ", res " << camera.res_x << " x " << camera.res_y << ", aperture "
        << format_number(camera.aperture) << ", focal_ratio " << format_number(camera.focal_ratio) << "; df "
        << format_number(camera.df) << ", w " << format_number(camera.w) << ", h " << format_number(camera.h) << ", xe "
        << coordinates(camera.xe) << ", ye " << coordinates(camera.ye) << ", ze " << coordinates(camera.ze) << "}";
}

void PrintTo(const BvhNode& node, std::ostream* os) {
    *os << "BvhNode{bounds ";
    PrintTo(node.bounds, os);
    *os << ", first " << node.first << ", count " << node.count << (node.count > 0 ? " (a leaf)}" : " (an inner node)}");
}

void PrintTo(const BvhTree& tree, std::ostream* os) {
    *os << "BvhTree{" << tree.nodes.size() << " nodes, " << tree.order.size() << " indices in order";
    if (!tree.nodes.empty()) {
        *os << ", root ";
        PrintTo(tree.nodes.front(), os);
    }
    *os << "}";
}

void PrintTo(const PixelSample& sample, std::ostream* os) {
    *os << "PixelSample{x " << sample.x << ", y " << sample.y << ", index " << sample.index << "}";
}

void PrintTo(const Sphere& sphere, std::ostream* os) {
    *os << "Sphere{center " << coordinates(sphere.center) << ", radius " << format_number(sphere.radius)
        << (sphere.inward ? ", inward}" : "}");
}

void PrintTo(const Plane& plane, std::ostream* os) {
    *os << "Plane{point " << coordinates(plane.point) << ", normal " << coordinates(plane.normal) << "}";
}

void PrintTo(const Triangle& triangle, std::ostream* os) {
    *os << "Triangle{p0 " << coordinates(triangle.p0) << ", p1 " << coordinates(triangle.p1) << ", p2 " << coordinates(triangle.p2) << "}";
}

void PrintTo(const Box& box, std::ostream* os) { *os << "Box{min " << coordinates(box.min) << ", max " << coordinates(box.max) << "}"; }

void PrintTo(const Cone& cone, std::ostream* os) {
    *os << "Cone{base " << coordinates(cone.base) << ", base_radius " << format_number(cone.base_radius) << ", apex "
        << coordinates(cone.apex) << ", apex_radius " << format_number(cone.apex_radius) << (cone.inward ? ", inward}" : "}");
}

void PrintTo(const Primitive& primitive, std::ostream* os) {
    *os << "Primitive{";
    std::visit([os](const auto& shape) { PrintTo(shape, os); }, primitive.shape);
    *os << ", material " << primitive.material << ", index " << primitive.index << "}";
}

} // namespace whitted
