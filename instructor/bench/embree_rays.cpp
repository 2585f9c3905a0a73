// `whitted-embree-rays SCENE`: shoots the ray traffic of `whitted render` (stage
// 6, --min-weight 0) into Embree 3 with no shading, and reports the times and
// ray counts in the same form as `whitted render --stats-json`.
//
// Why: the speed of the renderer only means something next to an upper bound.
// Embree is that bound: the same rays, traversed by hand-tuned SIMD kernels. The
// times are split as whitted splits them: parsing the scene file (our loader),
// building the acceleration structure (rtcCommitScene), and shooting the rays
// (wall clock of the whole image), so the benchmark driver treats both alike.
// With --engine whitted the same traffic goes into whitted's own Scene (the
// reference's BVH and leaf kernels) instead: traversal against traversal, with
// whitted's shading left out as Embree's is.
#include "embree_traffic.hpp"
#include "output_size.hpp"
#include "whitted/engine/leaf_kernels.hpp"
#include "whitted/scene_loader.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <fstream>
#include <map>
#include <memory>
#include <utility>
#include <optional>
#include <string>
#include <vector>

namespace {

struct Options {
    std::string scene;
    std::optional<int> width, height, max_depth;
    int threads = 0;
    int repeat = 1;
    std::string quality = "high";
    std::string engine = "embree";
    std::string json;
    bool eye_packets = false;
    bool quiet = false;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

int run(const Options& options) {
    const auto load_start = std::chrono::steady_clock::now();
    whitted::LoadedScene loaded = whitted::load_scene(options.scene);
    for (const std::string& warning : loaded.warnings)
        if (!options.quiet) std::fprintf(stderr, "%s\n", warning.c_str());
    whitted::SceneData& data = loaded.data;
    data.camera = whitted::bench::camera_at_size(data.camera, options.width, options.height);
    const int max_depth = options.max_depth.value_or(data.max_depth);
    const double parse_seconds = seconds_since(load_start);

    const std::map<std::string, RTCBuildQuality> qualities = {
        {"low", RTC_BUILD_QUALITY_LOW}, {"medium", RTC_BUILD_QUALITY_MEDIUM}, {"high", RTC_BUILD_QUALITY_HIGH}};
    whitted::bench::EmbreeSettings settings;
    settings.build_threads = options.threads;
    settings.quality = qualities.at(options.quality);
    // The engine the rays go to, and its name and build time for the report.
    const bool embree = options.engine == "embree";
    std::unique_ptr<const whitted::bench::RayQueries> queries;
    double build_seconds = 0.0;
    std::string renderer;
    if (embree) {
        auto embree_scene = std::make_unique<const whitted::bench::EmbreeScene>(data, settings);
        build_seconds = embree_scene->build_seconds();
        queries = std::move(embree_scene);
        renderer = whitted::bench::EmbreeScene::version() +
                   (options.eye_packets ? " rtcIntersect16 eye packets, rtcIntersect1/rtcOccluded1" : " rtcIntersect1/rtcOccluded1");
    } else {
        const auto build_start = std::chrono::steady_clock::now();
        queries = std::make_unique<const whitted::bench::SceneQueries>(data, whitted::linked_leaf_kernels());
        build_seconds = seconds_since(build_start);
        renderer = whitted::linked_leaf_kernels() ? "whitted Scene, reference leaf kernels" : "whitted Scene, labs' code";
    }
    const whitted::bench::RayQueries& scene = *queries;

    std::vector<double> runs;
    whitted::bench::TrafficResult result;
    for (int i = 0; i < options.repeat; ++i) {
        result = whitted::bench::shoot_ray_traffic(scene, data, max_depth, options.threads, options.eye_packets);
        runs.push_back(result.seconds);
    }
    const double render_seconds = median(runs);
    const whitted::bench::RayCounts& r = result.rays;
    if (!options.quiet) {
        std::printf("%s: %dx%d, max depth %d, %d threads, %s%s: parse %.3f s, build %.3f s, rays %.3f s%s\n",
                    options.scene.c_str(), data.camera.res_x, data.camera.res_y, max_depth, result.threads,
                    renderer.c_str(), embree ? (" (build quality " + options.quality + ")").c_str() : "", parse_seconds,
                    build_seconds, render_seconds, options.repeat > 1 ? " (median)" : "");
        std::printf("rays: %llu eye, %llu shadow, %llu reflected, %llu refracted; %llu in all; %.2f million rays per "
                    "second\n",
                    static_cast<unsigned long long>(r.eye), static_cast<unsigned long long>(r.shadow),
                    static_cast<unsigned long long>(r.reflected), static_cast<unsigned long long>(r.refracted),
                    static_cast<unsigned long long>(r.total()), r.total() / std::max(render_seconds, 1e-9) / 1e6);
    }
    if (!options.json.empty()) {
        nlohmann::ordered_json record = {
            {"scene", options.scene},
            {"width", data.camera.res_x},
            {"height", data.camera.res_y},
            {"stage", 6},
            {"max_depth", max_depth},
            {"min_weight", 0.0},
            {"threads", result.threads},
            {"parse_seconds", parse_seconds},
            {"build_seconds", build_seconds},
            {"render_seconds", render_seconds},
            {"rays",
             {{"eye", r.eye}, {"shadow", r.shadow}, {"reflected", r.reflected}, {"refracted", r.refracted},
              {"total", r.total()}}},
            {"primitives", data.primitives.size()},
            {"renderer", renderer},
            {"engine", options.engine},
            {"build_quality", options.quality},
            {"render_seconds_runs", runs}};
        std::ofstream out(options.json);
        out << record.dump(1) << "\n";
        out.close();
        if (!out) {
            std::fprintf(stderr, "whitted-embree-rays: cannot write %s\n", options.json.c_str());
            return 1;
        }
    }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"whitted-embree-rays: shoot whitted's ray traffic (stage 6, every ray to the maximum depth) into "
                 "Embree 3, without shading, and time it."};
    app.footer("Example: whitted-embree-rays balls4.nff --width 512 --height 512 --threads 2 --max-depth 5 --json e.json");
    Options options;
    app.add_option("scene", options.scene, "Scene file (.nff or .p3f)")->required();
    app.add_option("--width", options.width, "Image width in pixels (default: the scene file's)")->check(CLI::Range(1, 16384));
    app.add_option("--height", options.height, "Image height in pixels (default: the scene file's)")
        ->check(CLI::Range(1, 16384));
    app.add_option("--threads", options.threads, "Threads; 0 = one per core (default 0)")->check(CLI::Range(0, 1024));
    app.add_option("--max-depth", options.max_depth,
                   "Deepest ray in the ray tree; the eye ray is depth 1 (default: the scene's, else 5)")
        ->check(CLI::Range(1, 100));
    app.add_option("--repeat", options.repeat, "Shoot the image's rays this many times and report the median (default 1)")
        ->check(CLI::Range(1, 1000));
    app.add_option("--build-quality", options.quality, "Embree's BVH build quality: low, medium or high (default high)")
        ->check(CLI::IsMember({"low", "medium", "high"}));
    app.add_option("--engine", options.engine,
                   "Where the rays go: embree, or whitted (its own Scene, to compare traversal alone; default embree)")
        ->check(CLI::IsMember({"embree", "whitted"}));
    app.add_flag("--eye-packets", options.eye_packets,
                 "Shoot the eye rays of each 4x4 pixel block as one coherent rtcIntersect16 packet");
    app.add_option("--json", options.json, "Also write the timings and ray counts as JSON to FILE");
    app.add_flag("-q,--quiet", options.quiet, "Print nothing but errors");
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& help) {
        return app.exit(help);
    } catch (const CLI::ParseError& error) {
        std::fprintf(stderr, "whitted-embree-rays: %s\n", error.what());
        return 2;
    }
    try {
        return run(options);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "%s\n", error.what());
        return 1;
    }
}
