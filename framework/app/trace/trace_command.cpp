// `whitted trace SCENE --pixel X Y`: the ray tree of one pixel.
#include "commands.hpp"
#include "exit_codes.hpp"
#include "image_options.hpp"
#include "stage_choice.hpp"
#include "trace/ray_tree_report.hpp"
#include "whitted/image_pictures.hpp"
#include "whitted/lab_table.hpp"
#include "whitted/engine/leaf_kernels.hpp"
#include "whitted/passes.hpp"
#include "whitted/render.hpp"
#include "whitted/scene_loader.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

namespace whitted {
namespace {

struct TraceOptions {
    std::string scene;
    std::vector<int> pixel; // column, row from the top
    std::optional<int> width, height, max_depth, stage, samples, sample; // samples: --spp; sample: --sample
    double min_weight = RenderSettings{}.min_weight;
    std::string json;    // FILE, or - for the standard output instead of the text
    std::string picture; // FILE: the tree drawn over the scene
    int threads = 0;
};

bool write_json(const nlohmann::json& json, const std::string& path) {
    const std::string text = json.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
    if (path == "-") return static_cast<bool>(std::cout << text << std::flush);
    std::ofstream out(path);
    out << text;
    return static_cast<bool>(out.flush());
}

int run_trace(const TraceOptions& options) {
    LoadedScene loaded = load_scene(options.scene);
    for (const std::string& warning : loaded.warnings) std::fprintf(stderr, "%s\n", warning.c_str());
    const auto [width, height] = output_size(loaded.data.camera, options.width, options.height);
    if (const std::string problem = check_output_size(width, height); !problem.empty()) {
        std::fprintf(stderr, "whitted: %s\n", problem.c_str());
        return exit_code::bad_input;
    }
    const int x = options.pixel[0], y = options.pixel[1];
    if (x < 0 || y < 0 || x >= width || y >= height) {
        std::fprintf(stderr,
                     "whitted: pixel (%d, %d) is outside the %dx%d image; columns go from 0 to %d (left to right), "
                     "rows from 0 to %d (top to bottom)\n",
                     x, y, width, height, width - 1, height - 1);
        return exit_code::bad_input;
    }
    loaded.data.camera = loaded.data.camera.with_resolution(width, height);
    const std::optional<int> stage = choose_stage(options.stage);
    if (!stage) return exit_code::bad_input; // labs not done yet
    RenderSettings settings;
    settings.stage = *stage;
    settings.max_depth = options.max_depth.value_or(loaded.data.max_depth);
    settings.min_weight = options.min_weight;
    settings.samples_per_pixel = options.samples.value_or(loaded.data.samples_per_pixel);
    const int samples = traced_samples(settings);
    if (options.sample && samples == 0) {
        std::fprintf(stderr, "whitted: --sample %d: %s, so there are no samples to pick\n", *options.sample,
                     settings.samples_per_pixel == 0 ? "the scene traces one ray through each pixel's centre (no spp; --spp N asks for N samples)"
                                                     : "below stage 7 (lab 7, anti-aliasing) each pixel is one ray through its centre");
        return exit_code::bad_input;
    }
    if (options.sample && *options.sample >= samples) {
        std::fprintf(stderr, "whitted: --sample %d: each pixel has %d samples here, numbered 0 to %d\n", *options.sample,
                     samples, samples - 1);
        return exit_code::bad_input;
    }

    std::optional<SceneData> side_data;
    if (!options.picture.empty()) side_data = loaded.data;
    // The scene as `whitted render` builds it: from lab 10 on, walked with the lab's BVH.
    const BvhChoice bvh = settings.stage >= stage_number(Stage::bvh) ? BvhChoice::lab : BvhChoice::framework;
    const Scene scene(std::move(loaded.data), linked_leaf_kernels(), bvh);

    TracedPixel traced = trace_pixel_tree(scene, settings, x, y, height, options.sample.value_or(0));
    const RayTree& tree = traced.tree;
    const TraceContext context{scene, settings, options.scene, x, y, width, height, traced.sample};
    if (options.json == "-") {
        if (!write_json(ray_tree_json(tree, context), "-")) return exit_code::bad_input;
    } else {
        std::fputs(ray_tree_text(tree, context).c_str(), stdout);
        if (!options.json.empty() && !write_json(ray_tree_json(tree, context), options.json)) {
            std::fprintf(stderr, "whitted: cannot write %s\n", options.json.c_str());
            return exit_code::bad_input;
        }
    }
    if (side_data) {
        // Small images are drawn larger, so that rays and the ring around the pixel can be seen.
        const int scale = std::clamp(480 / std::max(width, height), 1, 8);
        Image eye_view;
        if (scale == 1) {
            eye_view = render(scene, settings, options.threads).image;
        } else {
            SceneData eye_data = *side_data;
            eye_data.camera = eye_data.camera.with_resolution(width * scale, height * scale);
            eye_view = render(Scene(std::move(eye_data), linked_leaf_kernels(), bvh), settings, options.threads).image;
        }
        side_data->camera = side_camera_for(tree, scene.camera(), width * scale, height * scale);
        const Scene side_scene(std::move(*side_data), linked_leaf_kernels());
        const Image side_view = render_pass(side_scene, settings, Pass::normal, options.threads).render.image;
        write_image(ray_tree_picture(tree, context, eye_view, side_view, side_scene.camera()), options.picture);
        if (options.json != "-")
            std::printf("\nwrote %s: left, your render (dimmed) with the pixel ringed in magenta; right, the same rays "
                        "seen from the side, the shapes in grey. White: eye ray, cyan: reflected, green: refracted, "
                        "dashed yellow: shadow feeler that reaches its light, red: blocked feeler (a red x where it "
                        "is blocked).\n",
                        options.picture.c_str());
    }
    return exit_code::success;
}

} // namespace

Command add_trace_command(CLI::App& app) {
    auto options = std::make_shared<TraceOptions>();
    CLI::App* command = app.add_subcommand(
        "trace", "Show the ray tree of one pixel: every ray, what it hit, what it added to the colour, with the "
                 "mirror law and Snell's law checked beside each secondary ray.");
    command->add_option("scene", options->scene, "Scene file (.nff or .p3f)")->required();
    command->add_option("--pixel", options->pixel, "The pixel: column X from the left, row Y from the top (0, 0 is the top-left corner, as in image viewers)")
        ->expected(2)
        ->type_name("X Y")
        ->required();
    command->add_option("--width", options->width, "Image width in pixels, as for render (default: the scene file's)")
        ->check(CLI::Range(1, 16384));
    command->add_option("--height", options->height, "Image height in pixels, as for render (default: the scene file's)")
        ->check(CLI::Range(1, 16384));
    command->add_option("--max-depth", options->max_depth, "Deepest ray in the ray tree (default: the scene's, else 5)")
        ->check(CLI::Range(1, 100));
    command->add_option("--min-weight", options->min_weight, "As for render (default 1/1024)")->check(min_weight_validator());
    command->add_option("--spp", options->samples, "Samples per pixel, as for render (default: the scene's spp, else 0)")
        ->check(CLI::Range(0, 65536));
    command->add_option("--sample", options->sample,
                        "On a pixel of several samples (spp, lab 7), which one to show: 0 to spp - 1 (default 0); "
                        "the pixel's value, the average of them all, is shown too")
        ->type_name("K")
        ->check(CLI::NonNegativeNumber);
    add_stage_option(*command, options->stage);
    command->add_option("--json", options->json, "Also write the tree as JSON to FILE; - writes only the JSON, to the standard output")
        ->type_name("FILE")
        ->check(writable_file_validator());
    command->add_option("--picture", options->picture, "Also draw the rays over the scene and from the side into this image (.png, .ppm or .pfm)")
        ->type_name("IMAGE")
        ->check(CLI::Validator(check_output_path, "IMAGE"));
    command->add_option("--threads", options->threads, "Threads for the picture's renders; 0 = one per core")->check(CLI::Range(0, 1024));
    command->footer("Exit code: 0 tree printed, 2 cannot trace what was given (a bad option, a missing or malformed "
                    "scene file, a file that cannot be written, labs not done yet), 3 whitted itself failed.");
    return Command{command, [options] { return run_trace(*options); }};
}

} // namespace whitted
