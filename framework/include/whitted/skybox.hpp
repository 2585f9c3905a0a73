// A cube-map skybox: six pictures around the scene, seen by every ray that
// escapes (P3F `env DIR`).
//
// Why: a sky makes reflections and refractions readable (a mirror that shows a
// flat colour looks like a flat disc). The lookup follows the course's own
// convention, so its skybox folders look in our renders as they do in its
// template: the face is picked by the direction's largest component, and the
// other two components, divided by it, place the point on that face.
//
//   face    direction   s (left to right)   t (bottom to top)
//   left    +x          +z / |x|            +y / |x|
//   right   -x          -z / |x|            +y / |x|
//   top     +y          -x / |y|            -z / |y|
//   bottom  -y          -x / |y|            +z / |y|
//   front   +z          -x / |z|            +y / |z|
//   back    -z          +x / |z|            +y / |z|
//
// (each mapped from -1..1 to 0..1). So a camera looking along -z has "back" in
// front of it, "left" to its right: the names are those of a viewer facing +z.
// When two components are equally large, y wins over x, and x or y over z.
// The colour is that of the texel containing (s, t) (no filtering); 8-bit values
// v become v / 255, like every image the framework reads.
#pragma once

#include "whitted/image.hpp"
#include "whitted/math.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

namespace whitted {

/// The six faces, in the order the course lists their files.
enum class CubeFace : int { right, left, top, bottom, front, back };

/// The file stems of the faces, in CubeFace order: right.jpg, left.jpg, ...
inline constexpr std::array<std::string_view, 6> kCubeFaceNames = {"right", "left", "top", "bottom", "front", "back"};

/// Where a direction meets the cube: the face and (s, t) in [0, 1]^2, t from the bottom.
struct CubePoint {
    CubeFace face = CubeFace::front;
    double s = 0.5;
    double t = 0.5;
};

/// The point of the cube a (non-zero) direction points at (the table above).
CubePoint cube_point(const Vec3& direction);

/// One face as the lookup reads it: 8-bit RGB, row-major, bottom row first (t = 0).
struct SkyboxFace {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb; // width x height x 3 values
};

class Skybox {
  public:
    /// The faces as images, in CubeFace order (any sizes; colours clamped to 0..1 and kept as 8-bit values).
    explicit Skybox(const std::array<Image, 6>& faces);
    /// The faces as they are stored; each must hold width x height x 3 values, width and height >= 1.
    explicit Skybox(std::array<SkyboxFace, 6> faces);

    /// Reads DIR/right.jpg (or .jpeg, .png), left, top, bottom, front and back.
    /// Throws ImageError naming the file that is missing or unreadable.
    static Skybox load(const std::filesystem::path& folder);

    /// The colour of the sky in `direction` (need not be unit length; not zero).
    Color lookup(const Vec3& direction) const;

    /// The faces, in CubeFace order.
    const std::array<SkyboxFace, 6>& faces() const { return faces_; }

  private:
    std::array<SkyboxFace, 6> faces_;
};

} // namespace whitted
