#include "fuzz_checks.hpp"

#include "image_format.hpp"
#include "whitted/engine/leaf_kernels.hpp"
#include "whitted/render.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <string>

namespace whitted::fuzz {

namespace {

// Renders stay tiny so that each input takes milliseconds: a few pixels, few primitives, short ray trees.
constexpr int kWidth = 8;
constexpr int kHeight = 6;
constexpr std::size_t kMostPrimitivesRendered = 2000;
constexpr std::uint32_t kMostRaysPerPixel = 64;

/// A message must be one printable line that starts with the input's name.
void check_message(const std::string& message, std::string_view prefix) {
    if (message.rfind(prefix, 0) != 0) broken("message does not start with '" + std::string(prefix) + "': " + message);
    for (const char c : message) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte > 0x7e) broken("message has a byte that is not printable ASCII: " + message);
    }
}

RenderResult render_tiny(const SceneData& data, const LeafKernels* kernels) {
    SceneData copy = data;
    copy.camera = copy.camera.with_resolution(kWidth, kHeight);
    const Scene scene(std::move(copy), kernels);
    RenderSettings settings;
    settings.max_depth = data.max_depth;
    settings.max_rays_per_pixel = kMostRaysPerPixel;
    return render(scene, settings, 1);
}

/// The accepted scene renders without a NaN pixel, alike through both intersection paths.
void check_render(const SceneData& data) {
    if (data.primitives.size() > kMostPrimitivesRendered) return;
    const RenderResult labs = render_tiny(data, nullptr);
    if (count_non_finite(labs.image) != 0) broken("the render has a NaN or infinite pixel");
    if (const LeafKernels* kernels = linked_leaf_kernels()) {
        const RenderResult fast = render_tiny(data, kernels);
        if (std::memcmp(fast.image.pixels.data(), labs.image.pixels.data(), labs.image.pixels.size() * sizeof(Color)) != 0)
            broken("the fast leaf kernels and the labs' code render different images");
    }
}

} // namespace

void broken(std::string_view what) {
    std::fprintf(stderr, "fuzz property broken: %.*s\n", static_cast<int>(what.size()), what.data());
    std::abort();
}

void check_scene_input(const std::uint8_t* data, std::size_t size, Dialect dialect) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const std::string name = dialect == Dialect::nff ? "fuzz.nff" : "fuzz.p3f";
    try {
        const LoadedScene loaded = parse_scene(text, dialect, name);
        for (const std::string& warning : loaded.warnings) check_message(warning, name + ":");
        check_render(loaded.data);
    } catch (const SceneError& error) {
        check_message(error.what(), name + ":");
    } catch (const std::exception& error) {
        broken(std::string("an exception that is not a SceneError: ") + error.what());
    }
}

void check_image_input(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    // The format from the first bytes, so that any saved image file is a useful seed as it is.
    detail::ImageFormat format = detail::ImageFormat::png;
    std::string name = "fuzz.png";
    if (bytes.starts_with("PF") || bytes.starts_with("Pf")) {
        format = detail::ImageFormat::pfm;
        name = "fuzz.pfm";
    } else if (bytes.starts_with("P")) {
        format = detail::ImageFormat::ppm;
        name = "fuzz.ppm";
    }
    constexpr std::size_t kMostPixels = std::size_t{1} << 20;
    try {
        const Image image = detail::decode_image(bytes, format, name, kMostPixels);
        if (image.width < 1 || image.height < 1 ||
            image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) ||
            image.pixels.size() > kMostPixels)
            broken("the image's size and pixel count disagree");
        if (count_non_finite(image) != 0) broken("a decoded pixel is NaN or infinite");
        if (format != detail::ImageFormat::pfm)
            for (const Color& pixel : image.pixels)
                for (int k = 0; k < 3; ++k)
                    if (pixel[k] < 0.0 || pixel[k] > 1.0) broken("an 8- or 16-bit sample outside [0, 1]");
    } catch (const ImageError& error) {
        check_message(error.what(), name + ": ");
    } catch (const std::exception& error) {
        broken(std::string("an exception that is not an ImageError: ") + error.what());
    }
}

} // namespace whitted::fuzz
