// whitted-bench's parts that do not run programs: summaries over runs, the
// level lists of the command line, POV-Ray's statistics, number formats.
#include "bench_options.hpp"
#include "reports.hpp"
#include "tool_runs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace whitted::bench;

namespace {

std::string level_error(const std::string& generator, const std::string& text) {
    try {
        parse_levels(generator, text);
    } catch (const std::invalid_argument& error) {
        return error.what();
    }
    return "no error";
}

} // namespace

TEST(BenchSummary, MedianOfOddAndEvenCountsWithMinAndMax) {
    const Summary odd = summarize({0.3, 0.1, 0.2});
    EXPECT_DOUBLE_EQ(odd.median, 0.2);
    EXPECT_DOUBLE_EQ(odd.min, 0.1);
    EXPECT_DOUBLE_EQ(odd.max, 0.3);
    EXPECT_DOUBLE_EQ(summarize({4.0, 1.0, 3.0, 2.0}).median, 2.5);
    EXPECT_FALSE(summarize({}).valid());
    EXPECT_DOUBLE_EQ(summarize({NAN, 1.0}).median, 1.0);
}

TEST(BenchSummary, RaysPerSecondAndRatiosComeFromTheSamples) {
    Series fast, slow;
    fast.attempted = slow.attempted = true;
    fast.samples = {{0.01, 0.5, 1'000'000, 10}, {0.01, 1.0, 1'000'000, 12}, {0.01, 0.25, 1'000'000, 11}};
    slow.samples = {{0.2, 2.0, 0, 50}};
    EXPECT_DOUBLE_EQ(summarize(fast, Metric::rays_per_second).median, 2e6);
    EXPECT_DOUBLE_EQ(summarize(fast, Metric::peak_megabytes).max, 12.0);
    EXPECT_DOUBLE_EQ(ratio(fast, slow, Metric::render), 0.25);
    slow.failure = "POV-Ray on x exited with code 1";
    EXPECT_TRUE(std::isnan(ratio(fast, slow, Metric::render)));
    EXPECT_FALSE(summarize(slow, Metric::render).valid());
}

TEST(BenchCommandLine, LevelListsAreCheckedAndDeduplicated) {
    EXPECT_EQ(parse_levels("sphereflake", "4,5,6"), (std::vector<int>{4, 5, 6}));
    EXPECT_EQ(parse_levels("sphereflake", "4,4"), (std::vector<int>{4}));
    EXPECT_TRUE(parse_levels("tetra", "none").empty());
    EXPECT_EQ(level_error("sphereflake", "8"), "sphereflake level must be 0 to 7, found 8");
    EXPECT_EQ(level_error("tetra", "0"), "tetra level must be 1 to 9, found 0");
    EXPECT_EQ(level_error("sphereflake", "4,x"), "expected sphereflake levels like 4,5,6 (or none), found '4,x'");
    EXPECT_EQ(level_error("sphereflake", "4.5"), "expected sphereflake levels like 4,5,6 (or none), found '4.5'");
}

TEST(BenchPovray, TraceParseAndBoundingTimesAreReadFromItsStatistics) {
    const std::string output =
        "Parser Time\n  Parse Time:       0 hours  0 minutes  0 seconds (0.031 seconds)\n"
        "  Bounding Time:    0 hours  0 minutes  0 seconds (0.004 seconds)\n"
        "Rendered 262144 of 262144 pixels (100%)\n"
        "Render Time:\n  Photon Time:      No photons\n"
        "  Trace Time:       0 hours  0 minutes  1 seconds (1.480 seconds)\n"
        "              using 2 thread(s) with 2.900 CPU-seconds total\nPOV-Ray finished\n";
    const std::optional<Sample> sample = parse_povray_output(output);
    ASSERT_TRUE(sample);
    EXPECT_DOUBLE_EQ(sample->render_seconds, 1.48);
    EXPECT_NEAR(sample->load_build_seconds, 0.035, 1e-12);
    EXPECT_FALSE(parse_povray_output("Parse Error: Cannot open input file x.pov.\n"));
    EXPECT_FALSE(parse_povray_output("  Trace Time:       No trace\n"));
}

TEST(BenchFormats, SecondsKeepThreeDigitsAndCountsGetCommas) {
    EXPECT_EQ(format_seconds(0.0000830), "0.0000830");
    EXPECT_EQ(format_seconds(0.0105), "0.0105");
    EXPECT_EQ(format_seconds(0.387), "0.387");
    EXPECT_EQ(format_seconds(12.34), "12.3");
    EXPECT_EQ(format_seconds(1234.0), "1234");
    EXPECT_EQ(format_seconds(NAN), "–");
    EXPECT_EQ(format_count(12), "12");
    EXPECT_EQ(format_count(7381), "7,381");
    EXPECT_EQ(format_count(597871), "597,871");
    EXPECT_EQ(format_count(5380840), "5,380,840");
}
