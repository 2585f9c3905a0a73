// `whitted diff A B`: compare two images with the grader's image gate.
#include "commands.hpp"
#include "whitted/image_compare.hpp"

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
    if (!options.output.empty() && difference.same_size) {
        // The absolute difference, 16 times brighter; NaN and infinity in magenta.
        Image diff(test.width, test.height);
        for (std::size_t i = 0; i < diff.pixels.size(); ++i) {
            const Color d = glm::abs(test.pixels[i] - reference.pixels[i]) * 16.0;
            diff.pixels[i] = is_finite(d) ? d : Color(1.0, 0.0, 1.0);
        }
        write_image(diff, options.output);
    }
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
