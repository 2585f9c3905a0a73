// Surface materials and lights: what the scene file's `f`, `l`, `b` lines say.
//
// Why: the labs read material coefficients by name (`diffuse`, `specular`,
// `transmittance`), never through index arrays. One material serves every
// shape that follows its `f` line in the scene file.
#pragma once

#include "whitted/math.hpp"

#include <cstdint>
#include <optional>

namespace whitted {

/// A 3D checkerboard that replaces a material's diffuse colour: cubes of side
/// `size` alternate between `color_a` and `color_b`.
struct Checker {
    Color color_a{1.0};
    Color color_b{0.0};
    double size = 1.0; // > 0
};

struct Material {
    Color color{1.0};           // diffuse colour C (NFF `f r g b`, P3F `Rd Gd Bd`)
    double diffuse = 1.0;       // Kd: weight of the Lambert term
    Color specular_color{1.0};  // colour of highlights and mirror reflections (white in NFF)
    double specular = 0.0;      // Ks: weight of the highlight and of the mirror reflection
    double shininess = 1.0;     // Phong / Blinn-Phong exponent n
    double transmittance = 0.0; // T: weight of the refracted ray (0 = opaque)
    double ior = 1.0;           // index of refraction of the inside (the outside is air, 1)
    std::optional<Checker> checker; // when set, replaces `color`

    /// The diffuse colour C at a point (the checker pattern when there is one).
    Color color_at(const Point3& p) const;
};

/// A point light with an RGB intensity.
struct PointLight {
    Point3 position;
    Color color{1.0};
};

/// A light with a size (the `arealight` extension): the parallelogram of points
/// center + s edge_u + t edge_v, s and t from -1/2 to 1/2, shining in every
/// direction like a point light. Each pixel sample shares its colour out
/// between `samples` points on it (lab 8), which gives soft shadows.
struct AreaLight {
    Point3 center;
    Color color{1.0};
    Vec3 edge_u{1.0, 0.0, 0.0};
    Vec3 edge_v{0.0, 0.0, 1.0};
    int samples = 1;              // points a pixel sample takes on the light, >= 1
    std::uint32_t first_number = 0; // its points use sample numbers first_number, first_number + 1, ... (set by the scene)
};

} // namespace whitted
