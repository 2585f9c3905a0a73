// whitted-skybox-faces DIR [--size N]: six N x N JPEG faces (right.jpg ... back.jpg) of a made-up sky, for timing
// how fast a scene with the course's skybox loads (instructor/scripts/skybox-load.sh).
//
// Why: the course's skyboxes are six 2048 x 2048 JPEGs of about 1 MB each, and loading them was most of the
// time a course scene took to open. The course's own pictures are not ours to ship, so these stand in: a sky
// gradient with rolling hills and fine noise, which compress (quality 90) to about the size of a photograph,
// and so cost the decoder about as much. The same bytes every run (a fixed seed).
#include "whitted/skybox.hpp"

#include <CLI/CLI.hpp>
#include <stb_image_write.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

// Face f's pixels: a gradient from the horizon up, hills below it, and a little noise everywhere.
std::vector<unsigned char> face_pixels(int f, int size) {
    std::vector<unsigned char> rgb(static_cast<std::size_t>(size) * static_cast<std::size_t>(size) * 3);
    std::uint32_t state = 2463534242u + static_cast<std::uint32_t>(f);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const double u = static_cast<double>(x) / size, v = static_cast<double>(y) / size;
            const double hill = 0.62 + 0.05 * std::sin(11.0 * u + f) + 0.02 * std::sin(47.0 * u + 3.0 * f);
            const bool ground = v > hill;
            for (int k = 0; k < 3; ++k) {
                state ^= state << 13, state ^= state >> 17, state ^= state << 5; // xorshift32
                const double noise = static_cast<double>(state % 29) - 14.0;
                const double sky = 90.0 + 120.0 * v + 25.0 * k;
                const double land = 60.0 + 40.0 * std::sin(90.0 * u * (k + 1)) * std::cos(70.0 * v);
                const double value = (ground ? land : sky) + noise;
                rgb[(static_cast<std::size_t>(y) * size + x) * 3 + k] =
                    static_cast<unsigned char>(value < 0.0 ? 0.0 : value > 255.0 ? 255.0 : value);
            }
        }
    }
    return rgb;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"Six JPEG faces of a made-up sky, for timing skybox loading."};
    std::string folder;
    int size = 2048;
    app.add_option("folder", folder, "Folder to write right.jpg, left.jpg, top.jpg, bottom.jpg, front.jpg, back.jpg to")->required();
    app.add_option("--size", size, "Width and height of each face")->check(CLI::Range(1, 8192));
    CLI11_PARSE(app, argc, argv);
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    for (int f = 0; f < 6; ++f) {
        const std::vector<unsigned char> rgb = face_pixels(f, size);
        std::string jpeg;
        const auto append = [](void* to, void* data, int bytes) {
            static_cast<std::string*>(to)->append(static_cast<const char*>(data), static_cast<std::size_t>(bytes));
        };
        const std::filesystem::path file = std::filesystem::path(folder) / (std::string(whitted::kCubeFaceNames[f]) + ".jpg");
        std::ofstream out(file, std::ios::binary);
        if (stbi_write_jpg_to_func(append, &jpeg, size, size, 3, rgb.data(), 90) == 0 || !(out << jpeg)) {
            std::fprintf(stderr, "whitted-skybox-faces: cannot write %s\n", file.string().c_str());
            return 2;
        }
    }
    return 0;
}
