// results.json follows Gradescope's format and is the same bytes every time;
// report.html is self-contained.
#include "grader/html_report.hpp"
#include "grader/results_json.hpp"
#include "grader/text.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace whitted::grade;

namespace {

GradingResult sample() {
    GradingResult result;
    LabResult lab;
    lab.lab = "02_shadows";
    lab.title = "Lab 2: shadows";
    TestOutcome passed;
    passed.name = "SpawnRay.Grazing";
    passed.status = Status::passed;
    TestOutcome stub;
    stub.name = "HiddenShading.Lambert";
    stub.status = Status::not_implemented;
    stub.message = "labs/02_shadows.cpp:14: spawn_ray() is not implemented yet";
    lab.tests = {{passed, "unit", 333, 333}, {stub, "hidden", 167, 0}};
    lab.score_cents = 333;
    lab.max_cents = 500;
    result.labs.push_back(lab);
    result.score_cents = 333;
    result.max_cents = 500;
    return result;
}

} // namespace

TEST(ResultsJson, HasGradescopesFieldsAndHidesHiddenTests) {
    const nlohmann::json json = nlohmann::json::parse(results_json(sample()));
    EXPECT_EQ(json["score"], 3.33);
    EXPECT_EQ(json["visibility"], "visible");
    EXPECT_EQ(json["stdout_visibility"], "hidden");
    ASSERT_EQ(json["tests"].size(), 2u);
    const nlohmann::json& hidden = json["tests"][1];
    EXPECT_EQ(hidden["name"], "Lab 2: shadows: HiddenShading.Lambert");
    EXPECT_EQ(hidden["number"], "1.2");
    EXPECT_EQ(hidden["score"], 0.0);
    EXPECT_EQ(hidden["max_score"], 1.67);
    EXPECT_EQ(hidden["status"], "failed");
    EXPECT_EQ(hidden["visibility"], "hidden");
    EXPECT_EQ(json["tests"][0]["visibility"], "visible");
    EXPECT_EQ(hidden["output"], "failed\nThe details of hidden tests are not shown.\n");
    EXPECT_EQ(hidden["extra_data"]["status"], "failed");
    EXPECT_FALSE(json.contains("execution_time"));
}

// The student's code chooses how a test ends (crash, timeout, exception, not
// implemented, wrong answer) and may choose from a hidden test's inputs: a
// student sees only passed or failed of a hidden test, in every place.
TEST(ResultsJson, AHiddenTestShowsOnlyPassedOrFailed) {
    for (const Status status : {Status::failed, Status::not_implemented, Status::exception, Status::crash, Status::timeout}) {
        GradingResult result = sample();
        result.labs[0].tests[1].outcome.status = status;
        const nlohmann::json json = nlohmann::json::parse(results_json(result));
        const std::string name(status_name(status));
        EXPECT_EQ(json["tests"][1]["extra_data"]["status"], "failed") << name;
        EXPECT_EQ(json["tests"][1]["tags"][2], "failed") << name;
        EXPECT_EQ(json["tests"][1]["output"], "failed\nThe details of hidden tests are not shown.\n") << name;
        EXPECT_EQ(status_counts(result.labs[0], Audience::student), "1/2 passed (1 failed)") << name;
        EXPECT_EQ(json["output"].get<std::string>().find(std::string(status_label(status))), 
                  status == Status::failed ? json["output"].get<std::string>().find("failed") : std::string::npos) << name;
        const std::string html = html_report(result);
        EXPECT_NE(html.find("<span class=\"badge failed\">failed</span><b>HiddenShading.Lambert"), std::string::npos) << name;
        EXPECT_EQ(status_counts(result.labs[0], Audience::instructor), "1/2 passed (1 " + std::string(status_label(status)) + ")");
    }
    GradingResult skipped = sample();
    skipped.labs[0].tests[1].outcome.status = Status::skipped; // decided by the visible tests: shown as it is
    EXPECT_EQ(status_counts(skipped.labs[0], Audience::student), "1/2 passed (1 skipped)");
}

TEST(ResultsJson, SameResultGivesTheSameBytes) { EXPECT_EQ(results_json(sample()), results_json(sample())); }

TEST(ResultsJson, AGraderFailureStillWritesValidJsonWithScoreZero) {
    const nlohmann::json json = nlohmann::json::parse(results_json(GradingResult{}, {GradingProblem::Kind::grader, "configuring failed"}));
    EXPECT_EQ(json["score"], 0.0);
    EXPECT_NE(json["output"].get<std::string>().find("configuring failed"), std::string::npos);
    EXPECT_NE(json["output"].get<std::string>().find("not your fault"), std::string::npos);
}

TEST(ResultsJson, ASubmissionThatCannotBeGradedSaysWhyToTheStudent) {
    const nlohmann::json json =
        nlohmann::json::parse(results_json(sample(), {GradingProblem::Kind::submission, "lab files in 2 places"}));
    EXPECT_EQ(json["score"], 0.0);
    const std::string output = json["output"].get<std::string>();
    EXPECT_EQ(output.rfind("Your submission was not graded: lab files in 2 places\n", 0), 0u) << output;
    EXPECT_EQ(output.find("not your fault"), std::string::npos) << output;
}

// Gradescope shows a test marked after_due_date or after_published only then; visible tests stay visible.
TEST(ResultsJson, HiddenTestsTakeTheVisibilityAsked) {
    for (const char* visibility : kVisibilities) {
        const nlohmann::json json = nlohmann::json::parse(results_json(sample(), {}, visibility));
        int hidden = 0;
        for (const nlohmann::json& test : json["tests"]) {
            const bool is_hidden_test = test["name"].get<std::string>().find("Hidden") != std::string::npos;
            EXPECT_EQ(test["visibility"], is_hidden_test ? visibility : "visible") << test["name"];
            hidden += is_hidden_test;
        }
        EXPECT_GT(hidden, 0) << "the sample has a hidden test";
    }
}

// A missing lab file (or one that does not compile) is said once, at the top, not in each of the lab's tests.
TEST(ResultsJson, ALabThatDidNotRunSaysWhyOnce) {
    GradingResult result;
    LabResult lab;
    lab.lab = "03_blinn_phong";
    lab.title = "Lab 3: Blinn-Phong";
    lab.problem = "the submission has no labs/03_blinn_phong.cpp";
    for (const char* name : {"BlinnPhong.One", "BlinnPhong.Two", "HiddenBlinnPhong.Three"}) {
        TestOutcome missing;
        missing.name = name;
        missing.status = Status::missing;
        missing.message = lab.problem;
        lab.tests.push_back({missing, "unit", 0, 100});
    }
    lab.max_cents = 300;
    result.labs.push_back(lab);
    result.max_cents = 300;
    const std::string text = results_json(result);
    const nlohmann::json json = nlohmann::json::parse(text);
    const std::string top = json["output"];
    EXPECT_NE(top.find("03_blinn_phong: the submission has no labs/03_blinn_phong.cpp\n"), std::string::npos) << top;
    std::size_t said = 0;
    for (std::size_t at = text.find("has no labs/03_blinn_phong.cpp"); at != std::string::npos; at = text.find("has no labs/03", at + 1)) ++said;
    EXPECT_EQ(said, 1u) << text;
    EXPECT_EQ(json["tests"][0]["output"], "missing: not run; why is said once for 03_blinn_phong, at the top\n");
}

TEST(HtmlReport, ListsFailuresFirstAndLoadsNothingFromOutside) {
    const std::string html = html_report(sample());
    EXPECT_LT(html.find("HiddenShading.Lambert"), html.find("SpawnRay.Grazing"));
    EXPECT_EQ(html.find("http"), std::string::npos);
    EXPECT_NE(html.find("3.33 / 5.00"), std::string::npos);
}

// A hidden test's pictures would show the student its secret scene and reference.
// Bytes that are not UTF-8 (printed by the student's code, or in a compiler's
// message) must not stop results.json from being written.
TEST(ResultsJson, OutputThatIsNotUtf8StillGivesValidJson) {
    GradingResult result = sample();
    result.labs[0].tests[1].outcome.output = "printed \xff\xfe by the student";
    result.labs[0].problem = "labs/02_shadows.cpp does not compile";
    result.labs[0].compile_errors = "error: \xff";
    const std::string text = results_json(result);
    EXPECT_FALSE(nlohmann::json::parse(text, nullptr, false).is_discarded()) << text;
}

// JSON escapes C0 itself; DEL and the C1 controls are escaped too (the same text once parsed), so that results.json
// shown on a terminal cannot drive it.
TEST(ResultsJson, NoControlCharacterIsWrittenRaw) {
    GradingResult result = sample();
    const std::string printed = "\x1b]0;title\x07 \x7f \xc2\x9b" "2J \xc2\x9d" "52;c;x \xc2\xa0 \xc3\xa9";
    result.labs[0].tests[1].outcome.name = "SpawnRay.Printed";
    result.labs[0].tests[1].outcome.output = printed;
    const std::string text = results_json(result);
    for (const std::string raw : {"\x1b", "\x07", "\x7f", "\xc2\x9b", "\xc2\x9d"}) EXPECT_EQ(text.find(raw), std::string::npos) << text;
    EXPECT_NE(text.find("\\u001b]0;title\\u0007 \\u007f \\u009b2J \\u009d52;c;x \xc2\xa0 \xc3\xa9"), std::string::npos) << text;
    const std::string output = nlohmann::json::parse(text)["tests"][1]["output"];
    EXPECT_NE(output.find(printed), std::string::npos) << output;
}

// What the student's code printed may hold control characters and bytes that are not UTF-8: the page shows them as
// escapes, so it stays valid UTF-8 and the student sees that something odd was printed.
TEST(HtmlReport, ShowsControlCharactersAndBadBytesAsEscapes) {
    GradingResult result = sample();
    result.labs[0].tests[1].outcome.name = "SpawnRay.Printed";
    result.labs[0].tests[1].outcome.output = "\x1b]0;title\x07 <b> \xff\xc2\x9b";
    const std::string html = html_report(result);
    EXPECT_NE(html.find("\\x1b]0;title\\x07 &lt;b&gt; \\xff\\u009b"), std::string::npos);
    for (const std::string raw : {"\x1b", "\x07", "\xff", "\xc2\x9b"}) EXPECT_EQ(html.find(raw), std::string::npos);
}

TEST(HtmlReport, ShowsNothingOfAHiddenTestButItsStatus) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / ("reports_test_" + std::to_string(getpid()));
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "yours.png") << "not really a PNG";
    GradingResult result = sample();
    result.labs[0].tests[0].outcome.pictures = folder;
    result.labs[0].tests[1].outcome.pictures = folder;
    result.labs[0].tests[1].outcome.output = "expected (0.0989, 0.2227) SECRET-INPUTS";
    result.labs[0].tests[1].outcome.image = ImageNumbers{};
    const std::string html = html_report(result);
    std::filesystem::remove_all(folder);
    std::size_t pictures = 0;
    for (std::size_t at = html.find("<img"); at != std::string::npos; at = html.find("<img", at + 1)) ++pictures;
    EXPECT_EQ(pictures, 1u) << "only the visible test's yours.png";
    EXPECT_NE(html.find("The details of hidden tests are not shown."), std::string::npos);
    EXPECT_EQ(html.find("SECRET-INPUTS"), std::string::npos) << "a hidden test's output";
    EXPECT_EQ(html.find("spawn_ray() is not implemented"), std::string::npos) << "a hidden test's message";
    EXPECT_EQ(html.find("image gate"), std::string::npos) << "a hidden test's image numbers";
}

TEST(Text, PathsBecomeRelativeLongestFirst) {
    EXPECT_EQ(replace_paths("/tmp/out/labs/x.cpp:3 and /tmp/out/build/y and /src/tests/z",
                            {{"/tmp/out/", ""}, {"/tmp/out/labs/", "labs/"}, {"/src/", ""}}),
              "labs/x.cpp:3 and build/y and tests/z");
    EXPECT_EQ(format_points(1234), "12.34");
    EXPECT_EQ(format_points(5), "0.05");
    EXPECT_EQ(trim_text("a\nb\nc\n", 2), "a\nb\n[... 1 more lines]\n");
}

TEST(Text, FirstLinesSaysHowManyMoreThereWere) {
    EXPECT_EQ(first_lines("a\nb\nc\nd\n", 2), "a\nb\n\u2026 2 more lines like these\n");
    EXPECT_EQ(first_lines("a\nb", 2), "a\nb") << "nothing cut, nothing said";
    EXPECT_EQ(first_lines("", 2), "");
}
