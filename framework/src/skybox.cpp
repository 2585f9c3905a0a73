#include "whitted/skybox.hpp"

#include "whitted/image.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <system_error>

namespace whitted {

CubePoint cube_point(const Vec3& d) {
    const Vec3 a = glm::abs(d);
    // The largest component picks the face: x when |x| > |y|, else y; then z when |z| beats that.
    CubeFace face = a.x > a.y ? (d.x >= 0.0 ? CubeFace::left : CubeFace::right)
                              : (d.y >= 0.0 ? CubeFace::top : CubeFace::bottom);
    double major = a.x > a.y ? a.x : a.y;
    if (a.z > major) {
        face = d.z >= 0.0 ? CubeFace::front : CubeFace::back;
        major = a.z;
    }
    if (!(major > 0.0) || !std::isfinite(major)) return CubePoint{}; // no direction: the front face's centre
    double sc = 0.0, tc = 0.0;
    switch (face) {
    case CubeFace::right: sc = -d.z, tc = d.y; break;
    case CubeFace::left: sc = d.z, tc = d.y; break;
    case CubeFace::top: sc = -d.x, tc = -d.z; break;
    case CubeFace::bottom: sc = -d.x, tc = d.z; break;
    case CubeFace::front: sc = -d.x, tc = d.y; break;
    case CubeFace::back: sc = d.x, tc = d.y; break;
    }
    return CubePoint{face, (sc / major + 1.0) / 2.0, (tc / major + 1.0) / 2.0};
}

Skybox::Skybox(const std::array<Image, 6>& faces) {
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const Image& image = faces[f];
        SkyboxFace& face = faces_[f];
        face.width = image.width;
        face.height = image.height;
        face.rgb.resize(static_cast<std::size_t>(image.width) * image.height * 3);
        std::size_t at = 0;
        for (int y = image.height - 1; y >= 0; --y) // images are stored top row first
            for (int x = 0; x < image.width; ++x)
                for (int k = 0; k < 3; ++k) face.rgb[at++] = to_byte(image.at(x, y)[k], Encoding::linear);
    }
}

Skybox::Skybox(std::array<SkyboxFace, 6> faces) : faces_(std::move(faces)) {
    for (const SkyboxFace& face : faces_)
        if (face.width < 1 || face.height < 1 ||
            face.rgb.size() != static_cast<std::size_t>(face.width) * static_cast<std::size_t>(face.height) * 3)
            throw std::invalid_argument("Skybox: a face's size does not match its values");
}

Skybox Skybox::load(const std::filesystem::path& folder) {
    std::error_code folder_error;
    if (!std::filesystem::is_directory(folder, folder_error))
        throw ImageError(folder.string() + ": no such folder (it should hold the six skybox faces right, left, top, "
                                           "bottom, front and back, as .jpg or .png)");
    std::array<Image, 6> faces;
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const std::string stem(kCubeFaceNames[f]);
        std::filesystem::path found;
        std::error_code error;
        for (const char* extension : {".jpg", ".jpeg", ".png"}) {
            if (std::filesystem::exists(folder / (stem + extension), error)) {
                found = folder / (stem + extension);
                break;
            }
        }
        if (found.empty())
            throw ImageError((folder / (stem + ".jpg")).string() + ": no such file (the skybox face '" + stem +
                             "' must be " + stem + ".jpg, " + stem + ".jpeg or " + stem + ".png)");
        faces[f] = read_image(found);
    }
    return Skybox(faces);
}

Color Skybox::lookup(const Vec3& direction) const {
    const CubePoint point = cube_point(direction);
    const SkyboxFace& face = faces_[static_cast<std::size_t>(point.face)];
    // The texel that contains (s, t); s = 1 and t = 1 belong to the last column and row.
    const int x = std::clamp(static_cast<int>(point.s * face.width), 0, face.width - 1);
    const int y = std::clamp(static_cast<int>(point.t * face.height), 0, face.height - 1);
    const std::size_t at = (static_cast<std::size_t>(y) * face.width + x) * 3;
    return Color(face.rgb[at], face.rgb[at + 1], face.rgb[at + 2]) / 255.0;
}

} // namespace whitted
