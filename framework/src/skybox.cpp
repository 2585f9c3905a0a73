#include "whitted/skybox.hpp"

#include "image_format.hpp"
#include "whitted/image.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <thread>
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

namespace {

// The file of a face in the folder: STEM.jpg, .jpeg or .png; throws ImageError naming STEM.jpg if there is none.
std::filesystem::path face_file(const std::filesystem::path& folder, std::string_view name) {
    const std::string stem(name);
    for (const char* extension : {".jpg", ".jpeg", ".png"}) {
        std::error_code error;
        if (std::filesystem::exists(folder / (stem + extension), error)) return folder / (stem + extension);
    }
    throw ImageError((folder / (stem + ".jpg")).string() + ": no such file (the skybox face '" + stem + "' must be " +
                     stem + ".jpg, " + stem + ".jpeg or " + stem + ".png)");
}

// A face file's picture as the lookup stores it: its rows bottom first.
SkyboxFace read_face(const std::filesystem::path& file) {
    const detail::Rgb8Image picture = detail::read_rgb8(file);
    SkyboxFace face{picture.width, picture.height, std::vector<std::uint8_t>(picture.rgb.size())};
    const std::size_t row = static_cast<std::size_t>(picture.width) * 3;
    for (int y = 0; y < picture.height; ++y)
        std::memcpy(face.rgb.data() + row * static_cast<std::size_t>(picture.height - 1 - y),
                    picture.rgb.data() + row * static_cast<std::size_t>(y), row);
    return face;
}

} // namespace

Skybox Skybox::load(const std::filesystem::path& folder) {
    std::error_code folder_error;
    if (!std::filesystem::is_directory(folder, folder_error))
        throw ImageError(folder.string() + ": no such folder (it should hold the six skybox faces right, left, top, "
                                           "bottom, front and back, as .jpg or .png)");
    std::array<std::filesystem::path, 6> files;
    for (std::size_t f = 0; f < files.size(); ++f) files[f] = face_file(folder, kCubeFaceNames[f]);
    // The six faces decode at once, a thread each up to the CPUs there are: the course's 2048 x 2048 JPEG faces
    // take most of a scene's loading time. An error is reported for the first face in CubeFace order that has one,
    // whichever thread saw it first.
    std::array<SkyboxFace, 6> faces;
    std::array<std::exception_ptr, 6> errors;
    std::atomic<std::size_t> next{0};
    const auto decode = [&] {
        for (std::size_t f = next++; f < files.size(); f = next++) {
            try {
                faces[f] = read_face(files[f]);
            } catch (...) {
                errors[f] = std::current_exception();
            }
        }
    };
    const std::size_t helpers = std::min<std::size_t>(files.size(), std::max(1u, std::thread::hardware_concurrency())) - 1;
    std::vector<std::thread> threads;
    try {
        for (std::size_t t = 0; t < helpers; ++t) threads.emplace_back(decode);
    } catch (const std::system_error&) {
        // No thread to be had (a process limit): the threads there are, this one among them, decode the rest.
    }
    decode();
    for (std::thread& thread : threads) thread.join();
    for (const std::exception_ptr& error : errors)
        if (error) std::rethrow_exception(error);
    return Skybox(std::move(faces));
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
