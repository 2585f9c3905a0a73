// `whitted render`: render an NFF or P3F scene to an image.
#include "commands.hpp"
#include "exit_codes.hpp"
#include "progress.hpp"
#include "image_options.hpp"
#include "platform.hpp"
#include "stage_choice.hpp"
#include "whitted/image_pictures.hpp"
#include "whitted/lab_status.hpp"
#include "whitted/engine/leaf_kernels.hpp"
#include "whitted/passes.hpp"
#include "whitted/render.hpp"
#include "whitted/scene_loader.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cctype>
#include <fstream>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

namespace whitted {
namespace {

struct RenderOptions {
    std::string scene;
    std::string output;
    std::optional<int> width, height, max_depth;
    std::optional<int> samples; // --spp: samples per pixel (default: the scene's)
    std::optional<std::string> acceleration; // --accel none|grid|bvh (default: the scene's)
    double min_weight = RenderSettings{}.min_weight;
    int threads = 0;
    std::optional<int> stage; // default: the highest stage whose labs are all done
    bool stats = false;
    std::string stats_json; // --stats-json FILE: timings and ray counts for scripts (make bench)
    bool quiet = false;
    bool srgb = false;
    std::optional<Pass> pass; // --pass NAME: a diagnostic picture instead of the colour
};

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void print_stats(const RenderResult& result) {
    const RayStats& s = result.stats;
    std::printf("rays: %llu eye, %llu shadow, %llu reflected, %llu refracted; %llu in all\n",
                static_cast<unsigned long long>(s.eye), static_cast<unsigned long long>(s.shadow),
                static_cast<unsigned long long>(s.reflected), static_cast<unsigned long long>(s.refracted),
                static_cast<unsigned long long>(s.total()));
    std::printf("speed: %.2f million rays per second\n", s.total() / std::max(result.seconds, 1e-9) / 1e6);
}

struct StatsRecord {
    const std::string& scene;
    int width, height;
    const RenderSettings& settings;
    const RenderResult& result;
    double parse_seconds, build_seconds;
    const Scene& built;
};

// One JSON object with the render's timings, ray counts and sizes (for scripts).
bool write_stats_json(const StatsRecord& r, const std::string& path) {
    const RayStats& s = r.result.stats;
    const nlohmann::json json = {
        {"scene", r.scene},
        {"width", r.width},
        {"height", r.height},
        {"stage", r.settings.stage},
        {"max_depth", r.settings.max_depth},
        {"min_weight", r.settings.min_weight},
        {"samples_per_pixel", r.settings.samples_per_pixel},
        {"threads", r.result.threads},
        {"parse_seconds", r.parse_seconds},
        {"build_seconds", r.build_seconds},
        {"render_seconds", r.result.seconds},
        {"rays", {{"eye", s.eye}, {"shadow", s.shadow}, {"reflected", s.reflected}, {"refracted", s.refracted}, {"total", s.total()}}},
        {"primitives", r.built.primitives().size()},
        {"acceleration_bytes", r.built.acceleration_bytes()},
        {"acceleration", std::array{"none", "grid", "bvh"}[static_cast<int>(r.built.acceleration())]},
    };
    std::ofstream out(path);
    // A path that is not UTF-8 is written with replacement characters rather than as invalid JSON.
    out << json.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    return static_cast<bool>(out.flush());
}

int run_render(const RenderOptions& options) {
    const auto load_start = std::chrono::steady_clock::now();
    LoadedScene loaded = load_scene(options.scene);
    for (const std::string& warning : loaded.warnings) std::fprintf(stderr, "%s\n", warning.c_str());
    auto [width, height] = output_size(loaded.data.camera, options.width, options.height);
    if (const std::string problem = check_output_size(width, height); !problem.empty()) {
        std::fprintf(stderr, "whitted: %s\n", problem.c_str());
        return exit_code::bad_input;
    }
    loaded.data.camera = loaded.data.camera.with_resolution(width, height);
    // Scene errors come first: they are the user's to fix whatever the labs' state.
    const std::optional<int> stage = choose_stage(options.stage, options.pass);
    if (!stage) return exit_code::bad_input; // labs not done yet
    RenderSettings settings;
    settings.stage = *stage;
    settings.max_depth = options.max_depth.value_or(loaded.data.max_depth);
    settings.min_weight = options.min_weight;
    settings.samples_per_pixel = options.samples.value_or(loaded.data.samples_per_pixel);
    if (options.acceleration)
        loaded.data.acceleration = *options.acceleration == "none"   ? Acceleration::none
                                   : *options.acceleration == "grid" ? Acceleration::grid
                                                                     : Acceleration::bvh;
    if (settings.samples_per_pixel > 0 && settings.stage < stage_number(Stage::anti_aliasing) && !options.pass)
        std::fprintf(stderr, "note: %d samples per pixel need lab 7 (anti-aliasing); stage %d traces one ray through "
                             "each pixel centre\n", settings.samples_per_pixel, settings.stage);
    if (!loaded.data.area_lights.empty() && settings.stage < stage_number(Stage::soft_shadows))
        std::fprintf(stderr, "note: area lights need lab 8 (soft shadows); stage %d lights with a point at the centre "
                             "of each\n", settings.stage);
    if (loaded.data.camera.aperture > 0.0 && settings.stage < stage_number(Stage::depth_of_field) && !options.pass)
        std::fprintf(stderr, "note: the camera's aperture needs lab 9 (depth of field); stage %d renders it as a "
                             "pinhole, everything sharp\n", settings.stage);
    const double parse_seconds = seconds_since(load_start);
    const auto build_start = std::chrono::steady_clock::now();
    // From lab 10 on, a student build walks its own BVH (the reference renderer always walks the framework's).
    const BvhChoice bvh = settings.stage >= stage_number(Stage::bvh) ? BvhChoice::lab : BvhChoice::framework;
    const Scene scene(std::move(loaded.data), linked_leaf_kernels(), bvh);
    const double build_seconds = seconds_since(build_start);
    const double load_seconds = seconds_since(load_start);

    ProgressBar bar(stderr, !options.quiet && is_terminal(stderr));
    const auto show_progress = [&](double done) { bar.update(done); };
    std::string pass_summary;
    RenderResult result;
    if (options.pass) {
        PassResult pass = render_pass(scene, settings, *options.pass, options.threads, show_progress);
        result = std::move(pass.render);
        pass_summary = std::move(pass.summary);
    } else {
        result = render(scene, settings, options.threads, show_progress);
    }
    bar.finish();

    const std::string stem = std::filesystem::path(options.scene).stem().string();
    const std::string output = !options.output.empty() ? options.output
                               : options.pass ? stem + "_" + std::string(pass_info(*options.pass).name) + ".png"
                                              : stem + ".png";
    // A NaN or infinite colour is a bug in the shading code: show it, loudly.
    // (Marked on a copy, and only then: copying a big image costs a page fault per 4 KiB.)
    const std::size_t broken = count_non_finite(result.image);
    const Encoding encoding = options.srgb ? Encoding::srgb : Encoding::linear;
    if (broken == 0) write_image(result.image, output, encoding);
    else write_image(with_broken_pixels_marked(result.image), output, encoding);
    if (!options.quiet) {
        std::printf("wrote %s (%dx%d, stage %d%s%s): rendered in %.3f s, scene loaded and built in %.3f s\n",
                    std::filesystem::absolute(output).lexically_normal().string().c_str(), width, height, *stage,
                    options.pass ? ", pass " : "", options.pass ? std::string(pass_info(*options.pass).name).c_str() : "",
                    result.seconds, load_seconds);
        if (options.pass) {
            std::printf("%s: %s\n", std::string(pass_info(*options.pass).name).c_str(),
                        std::string(pass_info(*options.pass).legend).c_str());
            if (!pass_summary.empty()) std::printf("%s\n", pass_summary.c_str());
        }
    }
    if (options.stats) print_stats(result);
    if (!options.stats_json.empty()) {
        StatsRecord record{options.scene, width, height, settings, result, parse_seconds, build_seconds, scene};
        if (!write_stats_json(record, options.stats_json)) {
            std::fprintf(stderr, "whitted: cannot write %s\n", options.stats_json.c_str());
            return exit_code::bad_input;
        }
    }
    if (result.stats.pixels_cut_short > 0) {
        std::fprintf(stderr,
                     "warning: %llu pixels reached the limit of %u rays per pixel and were cut short; "
                     "lower --max-depth or raise --min-weight\n",
                     static_cast<unsigned long long>(result.stats.pixels_cut_short), settings.max_rays_per_pixel);
    }
    if (broken > 0) {
        std::fprintf(stderr, "error: %zu pixels were NaN or infinite; they are magenta in %s\n", broken, output.c_str());
        return exit_code::bad_input; // the labs' code gave them
    }
    return exit_code::success;
}


} // namespace

Command add_render_command(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* render_command = app.add_subcommand("render", "Render a scene file (.nff or .p3f) to an image.");
    render_command->add_option("scene", options->scene, "Scene file (.nff or .p3f)")->required();
    render_command->add_option("-o,--output", options->output,
                               "Image to write: .png, .ppm or .pfm (default: the scene's name with .png)")
        ->check(CLI::Validator(check_output_path, "IMAGE"));
    render_command->add_option("--width", options->width, "Image width in pixels (default: the scene file's)")
        ->check(CLI::Range(1, 16384));
    render_command->add_option("--height", options->height, "Image height in pixels (default: the scene file's)")
        ->check(CLI::Range(1, 16384));
    render_command->add_option("--max-depth", options->max_depth,
                               "Deepest ray in the ray tree; the eye ray is depth 1 (default: the scene's, else 5)")
        ->check(CLI::Range(1, 100));
    render_command->add_option("--min-weight", options->min_weight,
                               "Skip secondary rays whose accumulated weight is below this (Whitted's adaptive "
                               "depth control; 0 = trace every ray down to the maximum depth; default 1/1024)")
        ->check(min_weight_validator());
    render_command->add_option("--spp", options->samples,
                               "Samples per pixel: 0 = one ray through each pixel centre (Whitted); N > 0 = the "
                               "average of N jittered samples (lab 7, anti-aliasing) (default: the scene's spp, else 0)")
        ->check(CLI::Range(0, 65536));
    render_command->add_option("--accel", options->acceleration,
                               "Acceleration structure: none = test every primitive with every ray; bvh = a bounding "
                               "volume hierarchy (the framework's, or from stage 10 your lab 10's); grid = a uniform grid "
                               "(default: the scene's accel, else bvh)")
        ->check(CLI::IsMember({"none", "grid", "bvh"}));
    render_command->add_option("--threads", options->threads, "Rendering threads; 0 = one per core (default 0)")
        ->check(CLI::Range(0, 1024));
    add_stage_option(*render_command, options->stage);
    render_command->add_flag("--stats", options->stats, "Print how many rays of each kind were cast, and rays per second");
    render_command->add_option("--stats-json", options->stats_json,
                               "Also write the timings (parse, build, render), ray counts and sizes as JSON to FILE")
        ->type_name("FILE")
        ->check(CLI::Validator(
            [](const std::string& path) -> std::string {
                const std::filesystem::path folder = std::filesystem::path(path).parent_path();
                if (!folder.empty() && !std::filesystem::is_directory(folder)) return "no such folder: " + folder.string();
                return {};
            },
            "FILE"));
    std::string pass_names;
    for (const PassInfo& info : all_passes()) pass_names += (pass_names.empty() ? "" : "|") + std::string(info.name);
    CLI::Option* pass_option = render_command
        ->add_option_function<std::string>(
            "--pass", [options](const std::string& name) { options->pass = find_pass(name); },
            "Draw a diagnostic picture instead of the colour: normal, depth, albedo, shadow (is_lit), reflectance, "
            "fresnel, ray-depth, object-id or cost (intersection tests); the command prints how to read it "
            "(default name: SCENE_PASS.png)")
        ->type_name("PASS")
        ->check(CLI::Validator(
            [pass_names](const std::string& name) -> std::string {
                return find_pass(name) ? "" : "expected one of " + pass_names + ", found " + name;
            },
            "PASS"));
    render_command->add_flag("-q,--quiet", options->quiet, "No progress bar and no summary line");
    render_command->add_flag("--srgb", options->srgb, "Write sRGB-encoded 8-bit values (default: linear, as in the course)")
        ->excludes(pass_option); // a pass's values are meant to be read as they are
    render_command->footer("Exit code: 0 image written, 2 cannot render what was given (a bad option, a missing or "
                           "malformed scene file, an image that cannot be written, labs not done yet or giving NaN "
                           "pixels), 3 whitted itself failed.");

    return Command{render_command, [options] { return run_render(*options); }};
}

} // namespace whitted
