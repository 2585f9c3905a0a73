#include "image_check.hpp"

#include "whitted/image_compare.hpp"
#include "whitted/render.hpp"
#include "whitted/scene_loader.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

namespace whitted::testing_helpers {
namespace {

std::filesystem::path source_path(const std::string& relative) {
    return std::filesystem::path(WHITTED_SOURCE_DIR) / relative;
}

// The folder for this test's pictures: <build>/test-output/<suite>.<name>.
std::filesystem::path output_folder() {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string name = std::string(info->test_suite_name()) + "." + info->name();
    return std::filesystem::path(WHITTED_BINARY_DIR) / "test-output" / name;
}

Image difference_picture(const Image& a, const Image& b) {
    Image diff(a.width, a.height);
    for (std::size_t i = 0; i < diff.pixels.size(); ++i) {
        const Color d = glm::abs(a.pixels[i] - b.pixels[i]) * 16.0;
        diff.pixels[i] = is_finite(d) ? d : Color(1.0, 0.0, 1.0);
    }
    return diff;
}

} // namespace

void expect_matches_reference(const ImageCheck& check) {
    LoadedScene loaded = load_scene(source_path(check.scene));
    loaded.data.camera = loaded.data.camera.with_resolution(check.width, check.height);
    RenderSettings settings;
    settings.stage = check.stage;
    settings.max_depth = loaded.data.max_depth;
    const Scene scene(std::move(loaded.data));
    Image rendered = render(scene, settings, 2).image;

    const std::filesystem::path reference_file = source_path(check.reference);
    if (const char* update = std::getenv("WHITTED_UPDATE_REFERENCES"); update && std::string(update) == "1") {
        std::filesystem::create_directories(reference_file.parent_path());
        write_image(rendered, reference_file);
        GTEST_SKIP() << "wrote the reference " << reference_file;
    }
    const Image reference = read_image(reference_file);
    const ImageDifference difference = compare_images(reference, rendered);
    if (difference.passed) return;

    const std::filesystem::path folder = output_folder();
    std::filesystem::create_directories(folder);
    const std::size_t broken = count_non_finite(rendered);
    Image shown = rendered;
    for (Color& c : shown.pixels)
        if (!is_finite(c)) c = Color(1.0, 0.0, 1.0); // NaN and infinity show as magenta
    write_image(shown, folder / "yours.png");
    write_image(reference, folder / "reference.png");
    if (difference.same_size) write_image(difference_picture(shown, reference), folder / "diff.png");
    ADD_FAILURE() << check.scene << " at stage " << check.stage << " differs from " << check.reference << ": "
                  << difference.summary() << (broken ? " (NaN or infinite pixels are magenta)" : "")
                  << "\n  pictures: " << folder.string() << "/{yours,reference,diff}.png";
}

} // namespace whitted::testing_helpers
