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

int run_diff(const DiffOptions& options) {
    const Image reference = read_image(options.reference);
    const Image test = read_image(options.test);
    const ImageDifference difference = compare_images(reference, test);
    std::printf("%s\n", difference.summary().c_str());
    if (!options.output.empty() && difference.same_size) write_image(difference_picture(test, reference), options.output);
    return difference.passed ? 0 : 1;
}

} // namespace

Command add_diff_command(CLI::App& app) {
    auto options = std::make_shared<DiffOptions>();
    CLI::App* command = app.add_subcommand(
        "diff", "Compare two images with the image gate of the tests and the grader; exit 0 when they match.");
    command->add_option("reference", options->reference, "The expected image (.png, .ppm or .pfm)")->required();
    command->add_option("image", options->test, "The image to check")->required();
    command->add_option("-o,--output", options->output, "Write the difference, 16 times brighter, to this image");
    return Command{command, [options] { return run_diff(*options); }};
}

} // namespace whitted
