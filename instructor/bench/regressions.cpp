// Comparing a benchmark with the last committed figures (see reports.hpp).
//
// Why these rules: this shared machine's speed drifts by about ±20 % over a
// day, so a raw time is compared with a margin above that drift, and a render
// is compared through its ratio to Embree when both runs have one (Embree ran
// in the same minutes, so the drift cancels). Times of a few milliseconds are
// left alone, in a ratio too (a ratio to a 10 ms Embree run moves by a third
// from one run to the next): their noise is larger than any margin.
#include "reports.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <stdexcept>

namespace whitted::bench {
namespace {

using Json = nlohmann::json;

double number_at(const Json& json, std::initializer_list<const char*> path) {
    const Json* node = &json;
    for (const char* key : path) {
        if (!node->is_object() || !node->contains(key)) return std::nan("");
        node = &(*node)[key];
    }
    return node->is_number() ? node->get<double>() : std::nan("");
}

std::string format_change(double now, double before, const char* format) {
    return format_number(before, format) + " → " + format_number(now, format) + " (" +
           format_number(now / before, "%.2f×") + ")";
}

} // namespace

BaselineCheck check_baseline(const std::vector<SceneResult>& results, const BenchSettings& settings,
                             const std::string& baseline_text) {
    BaselineCheck check;
    Json baseline;
    try {
        baseline = Json::parse(baseline_text);
    } catch (const Json::exception& error) {
        throw std::invalid_argument(std::string("the baseline is not a results.json: ") + error.what());
    }
    const Json& was = baseline.value("settings", Json::object());
    if (was.value("size", -1) != settings.size || was.value("threads", -1) != settings.threads ||
        was.value("max_depth", -1) != settings.depth) {
        check.note = "the baseline was measured with other settings (size, threads or depth): not compared";
        return check;
    }
    const Json scenes = baseline.value("scenes", Json::array()); // kept: by_name points into it
    std::map<std::string, const Json*> by_name;
    for (const Json& scene : scenes)
        if (scene.is_object() && scene.contains("name") && scene["name"].is_string())
            by_name[scene["name"].get<std::string>()] = &scene;
    for (const SceneResult& result : results) {
        // A time is flagged past the margin and the floor alike.
        const auto flag_time = [&](const char* what, double now, double before) {
            if (now > kRegressionMargin * before && now - before > kRegressionFloorSeconds)
                check.regressions.push_back({result.name, what, format_change(now, before, "%.3g s")});
        };
        const auto found = by_name.find(result.name);
        const Series& whitted = result.of(Tool::whitted);
        if (found == by_name.end() || !whitted.ok()) continue;
        const Json& before = *found->second;
        ++check.compared;
        flag_time("load + build", summarize(whitted, Metric::load_build).median,
                  number_at(before, {"whitted", "load_build_seconds", "median"}));
        const double ratio_now = ratio(whitted, result.of(Tool::embree), Metric::render);
        const double ratio_before = number_at(before, {"whitted_over_embree"});
        if (!std::isnan(ratio_now) && !std::isnan(ratio_before)) {
            // The floor too: the time whitted took beyond what the baseline's ratio gives today's Embree.
            const double render_now = summarize(whitted, Metric::render).median;
            const double extra = render_now - ratio_before * summarize(result.of(Tool::embree), Metric::render).median;
            if (ratio_now > kRatioMargin * ratio_before && extra > kRegressionFloorSeconds)
                check.regressions.push_back(
                    {result.name, "render ÷ Embree", format_change(ratio_now, ratio_before, "%.2f×")});
            continue;
        }
        flag_time("render", summarize(whitted, Metric::render).median,
                  number_at(before, {"whitted", "render_seconds", "median"}));
    }
    if (check.compared == 0) check.note = "no scene of this benchmark is in the baseline: nothing compared";
    return check;
}

std::string baseline_section(const BaselineCheck& check, const std::string& baseline_name) {
    std::string text = "## Against the last committed figures\n\n";
    text += "Baseline: `" + baseline_name + "`. A load or render time is flagged when it is over " +
            format_number(kRegressionMargin, "%.2f×") + " the baseline's and " +
            format_number(kRegressionFloorSeconds * 1000.0, "%.0f") + " ms slower; a render with an Embree ratio in " +
            "both runs when that ratio grew over " + format_number(kRatioMargin, "%.2f×") + " and the render took " +
            format_number(kRegressionFloorSeconds * 1000.0, "%.0f") + " ms more than the old ratio gives.\n\n";
    if (!check.note.empty()) return text + check.note + ".\n";
    if (check.regressions.empty())
        return text + "No regression on the " + std::to_string(check.compared) + " scenes compared.\n";
    text += "| scene | what | baseline → now |\n| --- | --- | --- |\n";
    for (const Regression& r : check.regressions) text += "| " + r.scene + " | " + r.what + " | " + r.change + " |\n";
    return text;
}

} // namespace whitted::bench
