// Running whitted, the student build and the Embree harness (into Embree, or
// into whitted's own scene: the rays without shading): all of them write
// the JSON of `whitted render --stats-json` (parse, build and render seconds,
// ray counts, primitives, acceleration bytes), which becomes the sample.
//
// Why one file: the three differ only in the program and a few flags; the way
// their numbers are read, and checked, must be the same for the ratios to mean
// anything.
#include "tool_runs.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <system_error>

namespace whitted::bench {
namespace {

// The command line of one run; every program renders the same size, depth and threads.
std::vector<std::string> command(Tool tool, const RunPlan& plan, const std::filesystem::path& json) {
    const BenchSettings& s = plan.settings;
    const std::string size = std::to_string(s.size);
    if (tool == Tool::embree || tool == Tool::whitted_rays) {
        return {plan.tools.embree.string(), plan.scene.path.string(), "--width", size, "--height", size,
                "--threads", std::to_string(s.threads), "--max-depth", std::to_string(s.depth), "--json", json.string(),
                "--engine", tool == Tool::embree ? "embree" : "whitted"};
    }
    const std::filesystem::path program = tool == Tool::student ? plan.tools.student : plan.tools.whitted;
    const std::string image = plan.scene.name + (tool == Tool::student ? "-student" : "") + ".png";
    return {program.string(), "render", plan.scene.path.string(), "--width", size, "--height", size,
            "--threads", std::to_string(s.threads), "--max-depth", std::to_string(s.depth), "--min-weight", "0",
            "-q", "--stats-json", json.string(), "-o", (plan.out / "images" / image).string()};
}

Sample read_stats(const std::filesystem::path& json, const std::string& what, Series& series) {
    std::ifstream file(json);
    if (!file) throw RunFailure(what + " wrote no statistics to " + json.string());
    try {
        const nlohmann::json stats = nlohmann::json::parse(file);
        Sample sample;
        sample.load_build_seconds = stats.at("parse_seconds").get<double>() + stats.at("build_seconds").get<double>();
        sample.render_seconds = stats.at("render_seconds").get<double>();
        sample.rays = stats.at("rays").at("total").get<std::uint64_t>();
        series.primitives = stats.at("primitives").get<std::size_t>();
        series.acceleration_bytes = stats.value("acceleration_bytes", std::size_t{0});
        return sample;
    } catch (const nlohmann::json::exception& error) {
        throw RunFailure(what + " wrote unreadable statistics to " + json.string() + ": " + error.what());
    }
}

} // namespace

Sample run_stats_json_program(Tool tool, const RunPlan& plan, Series& series) {
    const std::filesystem::path json = plan.out / "runs" / (plan.scene.name + "-" + std::string(tool_key(tool)) + ".json");
    std::error_code ignored;
    std::filesystem::remove(json, ignored); // never read an earlier run's numbers
    const std::string what = std::string(tool_label(tool)) + " on " + plan.scene.name;
    Sample sample;
    run_program(command(tool, plan, json), {}, what, sample);
    const Sample stats = read_stats(json, what, series);
    sample.load_build_seconds = stats.load_build_seconds;
    sample.render_seconds = stats.render_seconds;
    sample.rays = stats.rays;
    return sample;
}

} // namespace whitted::bench
