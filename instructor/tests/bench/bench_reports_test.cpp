// whitted-bench's reports from made-up results: the table's cells, ratios and
// gaps, the scale section, the targets, the SVG chart and results.json.
#include "reports.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace whitted::bench;

namespace {

Series series(std::vector<double> render_seconds, std::uint64_t rays = 0, std::size_t primitives = 0,
              std::size_t bytes = 0) {
    Series s;
    s.attempted = true;
    for (double seconds : render_seconds) s.samples.push_back({0.001, seconds, rays, 20.0});
    s.primitives = primitives;
    s.acceleration_bytes = bytes;
    return s;
}

SceneResult flake(int level, double whitted, double povray, double embree) {
    SceneResult r;
    r.name = "flake" + std::to_string(level);
    r.generator = "sphereflake";
    r.level = level;
    const std::size_t n = level == 4 ? 7383 : 66432;
    r.of(Tool::whitted) = series({whitted, whitted * 1.1, whitted * 0.9}, 1'500'000, n, n * 48);
    r.of(Tool::povray) = series({povray});
    r.of(Tool::embree) = series({embree}, 1'490'000, n);
    return r;
}

std::vector<SceneResult> sample_results() {
    std::vector<SceneResult> results{flake(4, 0.08, 0.48, 0.086), flake(5, 0.1, 0.6, 0.1)};
    SceneResult teapot;
    teapot.name = "teapot6";
    teapot.of(Tool::whitted) = series({0.05}, 900'000, 2330, 90'000);
    teapot.of(Tool::embree).attempted = true;
    teapot.of(Tool::embree).failure = "Embree on teapot6 exited with code 3";
    results.push_back(teapot);
    return results;
}

} // namespace

TEST(BenchReports, TableShowsMediansRangesRatiosAndGaps) {
    const std::string table = results_table(sample_results());
    EXPECT_NE(table.find("| flake4 | 7,383 | 0.00100 | 0.0800 (0.0720–0.0880) |"), std::string::npos) << table;
    EXPECT_NE(table.find("| 0.480 | 0.17× | 0.0860 | 0.93× | 1,500,000 | 1,490,000 |"), std::string::npos) << table;
    // teapot6: no POV-Ray run leaves its cells empty; the failed Embree says so.
    EXPECT_NE(table.find("| teapot6 (failed) | 2,330 |"), std::string::npos) << table;
    EXPECT_NE(table.find("|  |  | failed | – | 900,000 | failed |"), std::string::npos) << table;
}

TEST(BenchReports, RaysOnlyColumnsAppearWhenMeasured) {
    std::vector<SceneResult> results = sample_results();
    EXPECT_EQ(results_table(results).find("rays only"), std::string::npos);
    results[0].of(Tool::whitted_rays) = series({0.0946}, 1'490'000, 7383);
    const std::string table = results_table(results);
    EXPECT_NE(table.find("| whitted rays only s | rays only ÷ Embree |"), std::string::npos) << table;
    // flake4: Embree 0.086 s, whitted's queries on the same rays 0.0946 s: 1.10×.
    EXPECT_NE(table.find("| 1,500,000 | 1,490,000 | 0.0946 | 1.10× |"), std::string::npos) << table;
}

TEST(BenchReports, ReportListsFailuresScaleAndTargets) {
    const std::string report = markdown_report(sample_results(), BenchSettings{});
    EXPECT_NE(report.find("- Embree on teapot6 exited with code 3"), std::string::npos);
    EXPECT_NE(report.find("## Scale"), std::string::npos);
    EXPECT_NE(report.find("| flake4 | whitted render ÷ POV-Ray trace | 0.17× | ≤ 0.20× | yes |"), std::string::npos) << report;
    EXPECT_NE(report.find("| teapot6 | whitted render | 0.0500 s | ≤ 0.0450 s | **no** |"), std::string::npos) << report;
}

TEST(BenchReports, ScaleComparesRenderGrowthWithLogGrowth) {
    const std::string scale = scale_table(sample_results());
    EXPECT_NE(scale.find("| 4 | 7,383 |"), std::string::npos) << scale;
    EXPECT_NE(scale.find("| 1.25× | 1.25× | 1.00 | 48 |"), std::string::npos) << scale; // ln 66432 / ln 7383 = 1.246
    EXPECT_EQ(scale_table({flake(4, 0.08, 0.48, 0.086)}), "");
}

TEST(BenchReports, TargetsAreOnlyCheckedAtTheirSettings) {
    EXPECT_FALSE(check_targets(sample_results(), BenchSettings{}).empty());
    BenchSettings small;
    small.size = 64;
    EXPECT_TRUE(check_targets(sample_results(), small).empty());
}

TEST(BenchReports, ChartIsAnSvgWithLegendBarsAndValues) {
    const std::string svg = svg_chart(sample_results(), BenchSettings{});
    EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
    for (const char* text : {"whitted render", "POV-Ray trace", "Embree (rays only)", "0.0800 s", "0.480 s", ">skipped<",
                             ">failed<", "seconds per image (log scale)", ">0.1<", "</svg>"})
        EXPECT_NE(svg.find(text), std::string::npos) << text;
    EXPECT_NE(terminal_chart(sample_results()).find("POV-Ray  ███"), std::string::npos);
}

TEST(BenchReports, JsonHasEveryRunAndNullForMissingNumbers) {
    const nlohmann::json json = nlohmann::json::parse(results_json(sample_results(), BenchSettings{}));
    EXPECT_EQ(json["settings"]["size"], 512);
    EXPECT_EQ(json["scenes"].size(), 3u);
    EXPECT_EQ(json["scenes"][0]["whitted"]["runs"].size(), 3u);
    EXPECT_DOUBLE_EQ(json["scenes"][0]["whitted"]["render_seconds"]["median"].get<double>(), 0.08);
    EXPECT_TRUE(json["scenes"][2]["whitted_over_povray"].is_null());
    EXPECT_FALSE(json["scenes"][2].contains("povray"));
    EXPECT_EQ(json["scenes"][2]["embree"]["failure"], "Embree on teapot6 exited with code 3");
    EXPECT_TRUE(json["failed"].get<bool>());
}

namespace {

// A baseline written by hand in results.json's shape (not by results_json, the code whose output it stands for).
std::string baseline_json(double flake4_load, double flake4_over_embree, double teapot_render, int size = 512) {
    return R"({"settings": {"size": )" + std::to_string(size) + R"(, "threads": 2, "max_depth": 5},
      "scenes": [
        {"name": "flake4", "whitted_over_embree": )" + std::to_string(flake4_over_embree) + R"(,
         "whitted": {"load_build_seconds": {"median": )" + std::to_string(flake4_load) + R"(},
                     "render_seconds": {"median": 0.08}}},
        {"name": "teapot6", "whitted_over_embree": null,
         "whitted": {"load_build_seconds": {"median": 0.001},
                     "render_seconds": {"median": )" + std::to_string(teapot_render) + R"(}}},
        {"name": "gone", "whitted": {}}]})";
}

// sample_results(): flake4 loads in 0.001 s, renders in 0.08 s at 0.93x Embree; teapot6 renders in 0.05 s, no Embree.
std::vector<SceneResult> slow_flake4_load() {
    std::vector<SceneResult> results = sample_results();
    for (Sample& s : results[0].of(Tool::whitted).samples) s.load_build_seconds = 0.040;
    return results;
}

} // namespace

TEST(BenchReports, BaselineWithinItsMarginsFlagsNothing) {
    // flake4: load 0.001 vs 0.0009 (only 0.1 ms slower), ratio 0.93 vs 0.85 (1.09x); teapot6 0.05 vs 0.045 (1.11x).
    const BaselineCheck check = check_baseline(sample_results(), BenchSettings{}, baseline_json(0.0009, 0.85, 0.045));
    EXPECT_TRUE(check.regressions.empty());
    EXPECT_EQ(check.compared, 2); // flake4 and teapot6; flake5 is not in the baseline, "gone" not measured
    EXPECT_NE(baseline_section(check, "b.json").find("No regression on the 2 scenes compared."), std::string::npos);
}

TEST(BenchReports, BaselineFlagsSlowerLoadsRatiosAndRenders) {
    // flake4: load 0.040 vs 0.030 (1.33x, 10 ms), render ratio 0.93 vs 0.70 (1.33x); teapot6 0.05 vs 0.035 s (1.43x).
    const BaselineCheck check = check_baseline(slow_flake4_load(), BenchSettings{}, baseline_json(0.030, 0.70, 0.035));
    ASSERT_EQ(check.regressions.size(), 3u);
    EXPECT_EQ(check.regressions[0].scene, "flake4");
    EXPECT_EQ(check.regressions[0].what, "load + build");
    EXPECT_EQ(check.regressions[0].change, "0.03 s → 0.04 s (1.33×)");
    EXPECT_EQ(check.regressions[1].what, "render ÷ Embree");
    EXPECT_EQ(check.regressions[2].scene, "teapot6");
    EXPECT_EQ(check.regressions[2].what, "render");
    const std::string section = baseline_section(check, "b.json");
    EXPECT_NE(section.find("| flake4 | load + build | 0.03 s → 0.04 s (1.33×) |"), std::string::npos) << section;
}

TEST(BenchReports, BaselineRenderWithEmbreeIsJudgedByTheRatioNotTheTime) {
    // The machine was slower today: flake4's render took longer, but so did Embree's (same ratio): no regression.
    std::vector<SceneResult> results = sample_results();
    for (Sample& s : results[0].of(Tool::whitted).samples) s.render_seconds *= 2.0;
    for (Sample& s : results[0].of(Tool::embree).samples) s.render_seconds *= 2.0;
    const BaselineCheck check = check_baseline(results, BenchSettings{}, baseline_json(0.001, 0.93, 0.05));
    EXPECT_TRUE(check.regressions.empty());
}

TEST(BenchReports, BaselineRatioOfAFewMillisecondsIsLeftAlone) {
    // flake4 ten times smaller: 0.008 s at 0.93x Embree's 0.0086 s. Against a ratio of 0.70 (1.33x) that is
    // 0.008 - 0.70 x 0.0086 = 2 ms more: noise, as in a time. At 0.20 (4.65x) it is 6.3 ms more: flagged.
    std::vector<SceneResult> results = sample_results();
    for (Tool tool : {Tool::whitted, Tool::embree})
        for (Sample& s : results[0].of(tool).samples) s.render_seconds /= 10.0;
    EXPECT_TRUE(check_baseline(results, BenchSettings{}, baseline_json(0.001, 0.70, 0.05)).regressions.empty());
    const BaselineCheck check = check_baseline(results, BenchSettings{}, baseline_json(0.001, 0.20, 0.05));
    ASSERT_EQ(check.regressions.size(), 1u);
    EXPECT_EQ(check.regressions[0].what, "render ÷ Embree");
}

TEST(BenchReports, BaselineOfOtherSettingsOrNotJsonIsNotCompared) {
    const BaselineCheck check = check_baseline(slow_flake4_load(), BenchSettings{}, baseline_json(0.001, 0.5, 0.01, 256));
    EXPECT_TRUE(check.regressions.empty());
    EXPECT_NE(check.note.find("other settings"), std::string::npos);
    EXPECT_THROW(check_baseline(sample_results(), BenchSettings{}, "{not json"), std::invalid_argument);
}
