// `whitted diff A B`: compare two images with the grader's image gate.
#include "commands.hpp"
#include "exit_codes.hpp"
#include "image_options.hpp"
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
    std::string output;    // heat map
    std::string amplified; // |difference| x 16
};

std::string colour_text(const Color& c) {
    if (!is_finite(c)) return "NaN or infinite";
    char text[64];
    std::snprintf(text, sizeof text, "%d %d %d", to_byte(c.r, Encoding::linear), to_byte(c.g, Encoding::linear),
                  to_byte(c.b, Encoding::linear));
    return text;
}

// The numbers of the gate, one per line, each with its limit.
void print_report(const DiffOptions& options, const Image& reference, const Image& test, const ImageDifference& d) {
    const ImageGate gate;
    std::printf("%zu of %zu pixels off by more than %.0f/255 (%.3f %%): the gate allows %.0f %%%s\n", d.failing_pixels,
                d.pixel_count, 255.0 * gate.pixel_tolerance, 100.0 * d.failing_fraction,
                100.0 * gate.max_failing_fraction, d.failing_fraction <= gate.max_failing_fraction ? "" : "  <- too many");
    std::printf("mean error %.2f/255: the gate allows %.0f/255%s\n", 255.0 * d.mean_error, 255.0 * gate.max_mean_error,
                d.mean_error <= gate.max_mean_error ? "" : "  <- too large");
    if (d.max_error > 0.0)
        std::printf("largest error %.0f/255 at pixel (%d, %d) (column, row from the top): %s in %s, %s in %s\n",
                    255.0 * d.max_error, d.worst_x, d.worst_y, colour_text(reference.at(d.worst_x, d.worst_y)).c_str(),
                    options.reference.c_str(), colour_text(test.at(d.worst_x, d.worst_y)).c_str(), options.test.c_str());
    std::printf("PSNR %.1f dB (for information; the gate does not use it)\n", d.psnr);
    if (d.non_finite_pixels > 0)
        std::printf("%zu NaN or infinite pixels: any one fails the gate  <- a bug\n", d.non_finite_pixels);
    std::printf("%s\n", d.passed ? "pass: the images match" : "FAIL: the images differ");
}

// Exit 0 when the images match, 1 when they differ, 2 when they cannot be compared (as diff and cmp do).
int run_diff(const DiffOptions& options) {
    try {
        const Image reference = read_image(options.reference);
        const Image test = read_image(options.test);
        const ImageDifference difference = compare_images(reference, test);
        if (!difference.same_size) {
            const bool any_picture = !options.output.empty() || !options.amplified.empty();
            std::printf("the images have different sizes: %dx%d and %dx%d%s\n", reference.width, reference.height,
                        test.width, test.height, any_picture ? " (no difference image written)" : "");
            return exit_code::negative;
        }
        print_report(options, reference, test, difference);
        if (!options.output.empty()) {
            write_image(heat_picture(reference, test), options.output);
            std::printf("wrote %s: each pixel's largest error, black 0, dark blue up to 4/255 (within the tolerance), "
                        "green 5, yellow 16, red 64, white 255; magenta NaN\n",
                        options.output.c_str());
        }
        if (!options.amplified.empty()) {
            write_image(difference_picture(test, reference), options.amplified);
            std::printf("wrote %s: |image - reference|, 16 times brighter\n", options.amplified.c_str());
        }
        return difference.passed ? exit_code::success : exit_code::negative;
    } catch (const ImageError& error) {
        std::fprintf(stderr, "%s\n", error.what());
        return exit_code::bad_input;
    }
}

} // namespace

Command add_diff_command(CLI::App& app) {
    auto options = std::make_shared<DiffOptions>();
    CLI::App* command = app.add_subcommand(
        "diff", "Compare two images with the image gate of the tests and the grader.");
    command->footer("Exit code: 0 the images match, 1 they differ (in size or in the gate's numbers), 2 an image "
                    "cannot be read or written (or a bad option), 3 whitted itself failed.");
    command->add_option("reference", options->reference, "The expected image (.png, .ppm or .pfm)")->required();
    command->add_option("image", options->test, "The image to check")->required();
    command->add_option("-o,--output", options->output,
                        "Write a heat map of each pixel's error to this image (.png, .ppm or .pfm)")
        ->type_name("IMAGE")
        ->check(CLI::Validator(check_output_path, "IMAGE"));
    command->add_option("--amplified", options->amplified,
                        "Write |image - reference|, 16 times brighter, to this image")
        ->type_name("IMAGE")
        ->check(CLI::Validator(check_output_path, "IMAGE"));
    return Command{command, [options] { return run_diff(*options); }};
}

} // namespace whitted
