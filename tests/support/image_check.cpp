#include "image_check.hpp"
#include "image_pictures.hpp"

#include "whitted/image_compare.hpp"
#include "whitted/render.hpp"
#include "whitted/scene_loader.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>

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

// The folder named by WHITTED_TEST_OUTPUT (set by `whitted grade`), if any.
std::optional<std::filesystem::path> grader_folder() {
    const char* folder = std::getenv("WHITTED_TEST_OUTPUT");
    if (!folder || !*folder) return std::nullopt;
    return std::filesystem::path(folder);
}

// yours.png, reference.png and (for images of one size) diff.png and heat.png.
void write_pictures(const Image& rendered, const Image& reference, const std::filesystem::path& folder) {
    std::filesystem::create_directories(folder);
    const Image shown = with_broken_pixels_marked(rendered);
    write_image(shown, folder / "yours.png");
    write_image(reference, folder / "reference.png");
    if (rendered.width == reference.width && rendered.height == reference.height) {
        write_image(difference_picture(shown, reference), folder / "diff.png");
        write_image(heat_picture(reference, rendered), folder / "heat.png");
    }
}

} // namespace

void expect_matches_reference(const ImageCheck& check) {
    // The grader runs a lab's tests together first, and an image test's pictures and numbers belong to one test.
    if (const char* together = std::getenv("WHITTED_TOGETHER"); together && std::string(together) == "1") {
        ADD_FAILURE() << "an image test runs on its own";
        return;
    }
    // The grader shows the reference even when the render below throws or crashes.
    const std::optional<std::filesystem::path> graded = grader_folder();
    const std::filesystem::path reference_file = source_path(check.reference);
    if (graded && std::filesystem::is_regular_file(reference_file)) {
        std::filesystem::create_directories(*graded);
        std::filesystem::copy_file(reference_file, *graded / "reference.png",
                                   std::filesystem::copy_options::overwrite_existing);
        if (const char* only = std::getenv("WHITTED_REFERENCE_ONLY"); only && std::string(only) == "1")
            GTEST_SKIP() << "only the reference picture was asked for";
    }
    LoadedScene loaded = load_scene(source_path(check.scene));
    loaded.data.camera = loaded.data.camera.with_resolution(check.width, check.height);
    RenderSettings settings;
    settings.stage = check.stage;
    settings.max_depth = loaded.data.max_depth;
    settings.samples_per_pixel = loaded.data.samples_per_pixel;
    const Scene scene(std::move(loaded.data), nullptr, check.stage >= stage_number(Stage::bvh) ? BvhChoice::lab : BvhChoice::framework);
    Image rendered = render(scene, settings, 1).image;

    if (const char* update = std::getenv("WHITTED_UPDATE_REFERENCES"); update && std::string(update) == "1") {
        std::filesystem::create_directories(reference_file.parent_path());
        write_image(rendered, reference_file);
        GTEST_SKIP() << "wrote the reference " << reference_file;
    }
    const Image reference = read_image(reference_file);
    const ImageDifference difference = compare_images(reference, rendered);
    // For the grader: the pictures and the numbers, pass or fail.
    if (graded) {
        write_pictures(rendered, reference, *graded);
        write_gate_numbers(difference, check.scene, check.stage, *graded / "image.json");
    }
    if (difference.passed) return;

    const std::filesystem::path folder = graded.value_or(output_folder());
    if (!graded) write_pictures(rendered, reference, folder);
    const std::size_t broken = count_non_finite(rendered);
    ADD_FAILURE() << check.scene << " at stage " << check.stage << " differs from " << check.reference << ": "
                  << difference.summary() << (broken ? " (NaN or infinite pixels are magenta)" : "")
                  << "\n  pictures: " << folder.string() << "/{yours,reference,diff,heat}.png";
}

} // namespace whitted::testing_helpers
