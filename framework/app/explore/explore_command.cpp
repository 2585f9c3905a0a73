// `whitted explore SCENE [--stage K] [--port N]`: the scene rendered with the student's labs, on a page
// served on this machine only, where a click on a pixel shows its ray tree.
#include "commands.hpp"
#include "exit_codes.hpp"
#include "explore/explore_page.hpp"
#include "explore/explore_server.hpp"
#include "image_options.hpp"
#include "stage_choice.hpp"
#include "trace/ray_tree_report.hpp"
#include "whitted/engine/leaf_kernels.hpp"
#include "whitted/image_pictures.hpp"
#include "whitted/lab_table.hpp"
#include "whitted/render.hpp"
#include "whitted/scene_loader.hpp"

#include <chrono>
#include <cstdio>
#include <memory>
#include <thread>

namespace whitted {
namespace {

struct ExploreOptions {
    std::string scene;
    std::optional<int> stage;
    int port = 0;
    int threads = 0;
};

int run_explore(const ExploreOptions& options) {
    LoadedScene loaded = load_scene(options.scene);
    for (const std::string& warning : loaded.warnings) std::fprintf(stderr, "%s\n", warning.c_str());
    // Plain variables, not a structured binding: the lambdas below capture them (Apple clang cannot capture a binding).
    const std::pair<int, int> size = output_size(loaded.data.camera, std::nullopt, std::nullopt);
    const int width = size.first, height = size.second;
    if (const std::string problem = check_output_size(width, height); !problem.empty()) {
        std::fprintf(stderr, "whitted: %s\n", problem.c_str());
        return exit_code::bad_input;
    }
    loaded.data.camera = loaded.data.camera.with_resolution(width, height);
    const std::optional<int> stage = choose_stage(options.stage);
    if (!stage) return exit_code::bad_input; // labs not done yet: choose_stage said which
    RenderSettings settings;
    settings.stage = *stage;
    settings.max_depth = loaded.data.max_depth;
    settings.samples_per_pixel = loaded.data.samples_per_pixel;
    // The scene as `whitted render` builds it: from lab 10 on, walked with the lab's BVH.
    const BvhChoice bvh = settings.stage >= stage_number(Stage::bvh) ? BvhChoice::lab : BvhChoice::framework;
    const Scene scene(std::move(loaded.data), linked_leaf_kernels(), bvh);
    std::fprintf(stderr, "whitted explore: rendering %s at stage %d\n", options.scene.c_str(), settings.stage);
    const Image picture = render(scene, settings, options.threads).image;
    const std::string png = png_bytes(count_non_finite(picture) == 0 ? picture : with_broken_pixels_marked(picture));

    ExploreContent content;
    content.page = explore_page();
    content.scene = [&] {
        return nlohmann::json{{"scene", options.scene}, {"stage", settings.stage}, {"width", width}, {"height", height},
                              {"samples", traced_samples(settings)}};
    };
    content.picture_png = [&] { return png; };
    content.tree = [&](int x, int y, int sample) {
        if (x < 0 || y < 0 || x >= width || y >= height)
            throw ExploreRequestError("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                                      std::to_string(width) + "x" + std::to_string(height) + " picture");
        const int samples = traced_samples(settings);
        if (sample < 0 || sample >= std::max(samples, 1))
            throw ExploreRequestError("sample " + std::to_string(sample) + ": this pixel has " +
                                      (samples > 0 ? std::to_string(samples) + " samples, 0 to " + std::to_string(samples - 1)
                                                   : std::string("one ray through its centre (sample 0)")));
        const TracedPixel traced = trace_pixel_tree(scene, settings, x, y, height, sample);
        return ray_tree_json(traced.tree, TraceContext{scene, settings, options.scene, x, y, width, height, traced.sample});
    };
    ExploreServer server(std::move(content), random_token());
    try {
        server.start(options.port);
    } catch (const std::runtime_error& error) {
        std::fprintf(stderr, "whitted explore: %s\n", error.what());
        return exit_code::bad_input;
    }
    std::printf("whitted explore: open %s in your browser (this machine only; Ctrl-C stops)\n", server.url().c_str());
    std::fflush(stdout);
    for (;;) std::this_thread::sleep_for(std::chrono::hours(1)); // until Ctrl-C ends the program
}

} // namespace

Command add_explore_command(CLI::App& app) {
    auto options = std::make_shared<ExploreOptions>();
    CLI::App* command = app.add_subcommand(
        "explore", "Render a scene with your labs and show it on a page in your browser, served on this machine only: "
                   "a click on a pixel shows its ray tree.");
    command->add_option("scene", options->scene, "Scene file (.nff or .p3f)")->required();
    add_stage_option(*command, options->stage);
    command->add_option("--port", options->port, "Port on 127.0.0.1 to serve the page on (default 0: a free one)")
        ->check(CLI::Range(0, 65535));
    command->add_option("--threads", options->threads, "Threads for rendering; 0 = one per core")->check(CLI::Range(0, 1024));
    command->footer("Example: whitted explore scenes/05_refraction.p3f\n"
                    "Exit code: 2 cannot serve what was given (a bad option, a missing or malformed scene file, labs not "
                    "done yet, a port in use), 3 whitted itself failed.");
    return Command{command, [options] { return run_explore(*options); }};
}

} // namespace whitted
