// results.json: the settings, every scene with every program's raw samples and
// summaries, the ratios and the target checks (see reports.hpp).
//
// Why: scripts and later comparisons (did a change make flake6 faster?) need
// the numbers, not a table; the raw samples let them recompute anything.
// NaN is not JSON, so a missing number is written as null.
#include "reports.hpp"

#include <nlohmann/json.hpp>

namespace whitted::bench {
namespace {

using Json = nlohmann::ordered_json;

Json number(double value) { return value == value ? Json(value) : Json(nullptr); }

Json summary(const Series& series, Metric metric) {
    const Summary s = summarize(series, metric);
    return Json{{"median", number(s.median)}, {"min", number(s.min)}, {"max", number(s.max)}};
}

Json series_json(const Series& series) {
    Json runs = Json::array();
    for (const Sample& s : series.samples)
        runs.push_back({{"load_build_seconds", s.load_build_seconds},
                        {"render_seconds", s.render_seconds},
                        {"rays", s.rays},
                        {"peak_megabytes", s.peak_megabytes}});
    Json json{{"ok", series.ok()}, {"failure", series.failure.empty() ? Json(nullptr) : Json(series.failure)}};
    json["load_build_seconds"] = summary(series, Metric::load_build);
    json["render_seconds"] = summary(series, Metric::render);
    json["rays_per_second"] = summary(series, Metric::rays_per_second);
    json["peak_megabytes"] = summary(series, Metric::peak_megabytes);
    json["rays"] = series.ok() ? Json(series.samples.back().rays) : Json(nullptr);
    json["primitives"] = series.primitives;
    json["acceleration_bytes"] = series.acceleration_bytes;
    json["runs"] = runs;
    return json;
}

} // namespace

std::string results_json(const std::vector<SceneResult>& results, const BenchSettings& s) {
    Json json;
    json["settings"] = {{"size", s.size}, {"threads", s.threads}, {"max_depth", s.depth},
                        {"runs", s.runs}, {"warmup", s.warmup}, {"min_weight", 0}};
    Json scenes = Json::array();
    bool failed = false;
    for (const SceneResult& r : results) {
        Json scene{{"name", r.name}, {"path", r.path.string()}, {"failed", r.failed()}};
        scene["generator"] = r.generator.empty() ? Json(nullptr) : Json{{"name", r.generator}, {"level", r.level}};
        const Series& w = r.of(Tool::whitted);
        scene["bytes_per_primitive"] = number(bytes_per_primitive(w));
        scene["whitted_over_povray"] = number(ratio(w, r.of(Tool::povray), Metric::render));
        scene["whitted_over_embree"] = number(ratio(w, r.of(Tool::embree), Metric::render));
        scene["whitted_rays_over_embree"] = number(ratio(r.of(Tool::whitted_rays), r.of(Tool::embree), Metric::render));
        for (Tool tool : kTools)
            if (r.of(tool).attempted) scene[std::string(tool_key(tool))] = series_json(r.of(tool));
        scenes.push_back(scene);
        failed |= r.failed();
    }
    json["scenes"] = scenes;
    Json targets = Json::array();
    for (const TargetCheck& t : check_targets(results, s))
        targets.push_back({{"scene", t.scene}, {"target", t.what}, {"measured", t.measured}, {"limit", t.limit}, {"met", t.met()}});
    json["targets"] = targets;
    json["failed"] = failed;
    return json.dump(2) + "\n";
}

} // namespace whitted::bench
