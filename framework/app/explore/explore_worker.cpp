#include "explore/explore_worker.hpp"

#include <chrono>
#include <fstream>
#include <sstream>
#include <system_error>

namespace whitted {
namespace {

// The whole of file `path`, if it can be read; deleted afterwards.
std::optional<std::string> take_file(const std::filesystem::path& path) {
    std::optional<std::string> content;
    if (std::ifstream in{path, std::ios::binary}) {
        std::ostringstream text;
        text << in.rdbuf();
        content = std::move(text).str();
    }
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
    return content;
}

} // namespace

ExploreWorker::ExploreWorker(std::string scene, std::filesystem::path scratch, int threads)
    : scene_(std::move(scene)), scratch_(std::move(scratch)), threads_(threads) {}

WorkerRun ExploreWorker::run(std::vector<std::string> argv, const std::string& png, const std::string& json,
                             const KeepGoing& keep_going) const {
    const auto start = std::chrono::steady_clock::now();
    const std::string id = std::to_string(++runs_);
    const std::filesystem::path output = scratch_ / ("output-" + id + ".txt");
    const std::filesystem::path png_file = scratch_ / ("picture-" + id + ".png");
    const std::filesystem::path json_file = scratch_ / ("data-" + id + ".json");
    if (!png.empty()) argv.insert(argv.end(), {png, png_file.string()});
    if (!json.empty()) argv.insert(argv.end(), {json, json_file.string()});
    WorkerRun result;
    try {
        ChildProcess child(argv, output);
        for (;;) {
            if (std::optional<ChildExit> done = child.wait_for(std::chrono::milliseconds(50))) {
                result.exit = *done;
                break;
            }
            if (!keep_going()) child.stop();
        }
    } catch (const ChildStartError& error) {
        result.exit = ChildExit{-1, false, error.what()};
    }
    result.output = take_file(output).value_or("");
    if (!png.empty()) result.png = take_file(png_file);
    if (!json.empty())
        if (std::optional<std::string> text = take_file(json_file))
            result.json = nlohmann::json::parse(*text, nullptr, /*allow_exceptions=*/false);
    if (result.json && result.json->is_discarded()) result.json.reset();
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

WorkerRun ExploreWorker::render(const std::filesystem::path& program, const RenderJob& job,
                                const KeepGoing& keep_going) const {
    std::vector<std::string> argv{program.string(), "render", scene_, "--quiet", "--threads", std::to_string(threads_)};
    if (job.stage) argv.insert(argv.end(), {"--stage", std::to_string(*job.stage)});
    if (job.size)
        argv.insert(argv.end(), {"--width", std::to_string(job.size->first), "--height", std::to_string(job.size->second)});
    if (!job.pass.empty()) argv.insert(argv.end(), {"--pass", job.pass});
    return run(std::move(argv), "-o", "--stats-json", keep_going);
}

WorkerRun ExploreWorker::trace(const std::filesystem::path& program, int x, int y, std::optional<int> sample, int stage,
                               const KeepGoing& keep_going) const {
    std::vector<std::string> argv{program.string(), "trace", scene_, "--pixel", std::to_string(x), std::to_string(y),
                                  "--stage", std::to_string(stage), "--threads", std::to_string(threads_)};
    if (sample) argv.insert(argv.end(), {"--sample", std::to_string(*sample)});
    return run(std::move(argv), "--picture", "--json", keep_going);
}

WorkerRun ExploreWorker::build(const LiveBuild& build) const {
    std::vector<std::string> argv{build.cmake.string(), "--build", build.build_dir.string(), "--target", build.worker_target};
    if (!build.config.empty()) argv.insert(argv.end(), {"--config", build.config});
    return run(std::move(argv), "", "", [] { return true; });
}

KeepGoing for_at_most(double seconds) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    return [deadline] { return std::chrono::steady_clock::now() < deadline; };
}

} // namespace whitted
