// `whitted diff A B`: compare two images with the grader's image gate.
#include "commands.hpp"
#include "whitted/image_compare.hpp"
#include "whitted/image_pictures.hpp"

#include <cstdio>
#include <memory>
#include <string>

namespace whitted {
namespace {

struct DiffOptions {
    std::string reference;
    std::string test;
    std::string output;
};

// Exit 0 when the images match, 1 when they differ, 2 when they cannot be compared (as diff and cmp do).
int run_diff(const DiffOptions& options) {
    try {
        const Image reference = read_image(options.reference);
        const Image test = read_image(options.test);
        const ImageDifference difference = compare_images(reference, test);
        if (!difference.same_size) {
            std::printf("the images have different sizes: %dx%d and %dx%d%s\n", reference.width, reference.height,
                        test.width, test.height, options.output.empty() ? "" : " (no difference image written)");
            return 1;
        }
        std::printf("%s\n", difference.summary().c_str());
        if (!options.output.empty()) write_image(difference_picture(test, reference), options.output);
        return difference.passed ? 0 : 1;
    } catch (const ImageError& error) {
        std::fprintf(stderr, "%s\n", error.what());
        return 2;
    }
}

} // namespace

Command add_diff_command(CLI::App& app) {
    auto options = std::make_shared<DiffOptions>();
    CLI::App* command = app.add_subcommand(
        "diff", "Compare two images with the image gate of the tests and the grader; exit 0 when they match, 1 "
                "when they differ, 2 when one cannot be read or the difference cannot be written.");
    command->add_option("reference", options->reference, "The expected image (.png, .ppm or .pfm)")->required();
    command->add_option("image", options->test, "The image to check")->required();
    command->add_option("-o,--output", options->output, "Write the difference, 16 times brighter, to this image");
    return Command{command, [options] { return run_diff(*options); }};
}

} // namespace whitted
