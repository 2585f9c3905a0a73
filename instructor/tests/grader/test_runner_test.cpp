// Each GoogleTest test runs as its own pair of processes (a checker and a
// worker) and ends with the right status; run together, only clean passes count. fake_lab plays the checker (its
// tests end in every way a test can); misbehaving_child plays the worker.
#include "grader/test_runner.hpp"
#include "grader/text.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <unistd.h>

using namespace whitted::grade;

namespace {

class TestRunnerTest : public ::testing::Test {
protected:
    void SetUp() override {
        folder = std::filesystem::temp_directory_path() / ("test_runner_test_" + std::to_string(getpid()));
        program = TestProgram{"02_shadows", FAKE_LAB, {MISBEHAVING_CHILD, "exit", "0"}, folder, {}, {{folder.string() + "/", ""}}, {}};
        program.limits.wall_seconds = 1.0;
    }
    void TearDown() override { std::filesystem::remove_all(folder); }

    std::filesystem::path folder;
    TestProgram program;
};

} // namespace

TEST_F(TestRunnerTest, ListsEveryTestInOrder) {
    std::string problem;
    const std::vector<std::string> names = list_tests(program, problem);
    EXPECT_EQ(problem, "");
    const std::vector<std::string> expected = {"Fake.Passes", "Fake.GivesAWrongAnswer", "Fake.FailsEveryInput", "Fake.CallsAStub",
                                               "Fake.ThrowsSomethingElse", "Fake.Segfaults", "Fake.Loops", "Fake.StubThrowsInAThread",
                                               "Fake.WorkerDiesDuringBoxEntry", "FakeImage.IsTwoPercentOff", "HiddenFake.Passes"};
    EXPECT_EQ(names, expected);
}

TEST_F(TestRunnerTest, ListingAProgramThatDoesNotStartSaysSo) {
    program.checker = "/no/such/check_program";
    std::string problem;
    EXPECT_TRUE(list_tests(program, problem).empty());
    EXPECT_NE(problem.find("could not start"), std::string::npos) << problem;
}

TEST_F(TestRunnerTest, EveryEndingHasItsStatus) {
    const std::map<std::string, Status> expected = {
        {"Fake.Passes", Status::passed},           {"Fake.GivesAWrongAnswer", Status::failed},
        {"Fake.CallsAStub", Status::not_implemented}, {"Fake.ThrowsSomethingElse", Status::exception},
        {"Fake.Segfaults", Status::crash},         {"Fake.Loops", Status::timeout},
        {"Fake.StubThrowsInAThread", Status::not_implemented}, {"HiddenFake.Passes", Status::passed}};
    for (const auto& [name, status] : expected) {
        const TestOutcome outcome = run_test(program, name);
        EXPECT_EQ(status_name(outcome.status), status_name(status)) << name << ": " << outcome.message << "\n" << outcome.output;
    }
}

TEST_F(TestRunnerTest, MessagesSayWhatHappened) {
    EXPECT_EQ(run_test(program, "Fake.CallsAStub").message, "labs/02_shadows.cpp:14: spawn_ray() is not implemented yet");
    EXPECT_EQ(run_test(program, "Fake.StubThrowsInAThread").message,
              "labs/05_refraction.cpp:20: refracted_direction() is not implemented yet");
    EXPECT_EQ(run_test(program, "Fake.ThrowsSomethingElse").message, "exception: the scene has no camera");
    EXPECT_EQ(run_test(program, "Fake.Segfaults").message.rfind("killed by SIGSEGV", 0), 0u);
    EXPECT_EQ(run_test(program, "Fake.Loops").message, "did not finish within 1 s and was killed");
    const TestOutcome wrong = run_test(program, "Fake.GivesAWrongAnswer");
    EXPECT_EQ(wrong.message, "Expected equality of these values:");
    EXPECT_NE(wrong.output.find("arithmetic is broken"), std::string::npos) << wrong.output;
    EXPECT_EQ(wrong.output.find(" ms)"), std::string::npos) << "no durations: " << wrong.output;
}

// A mistake that fails every input alike shows its first 40 lines, and what the student's code printed its
// first 20, each then with one line saying how many more there were.
TEST_F(TestRunnerTest, AFailingTestShowsTheFirstLinesOfItsReportAndOfWhatTheCodePrinted) {
    program.worker = {MISBEHAVING_CHILD, "lines", "100"};
    const TestOutcome outcome = run_test(program, "Fake.FailsEveryInput");
    EXPECT_EQ(outcome.status, Status::failed);
    const std::vector<std::string> lines = split_lines(outcome.output);
    ASSERT_EQ(lines.size(), 40u + 1u + 1u + 20u + 1u) << outcome.output;
    EXPECT_EQ(lines[0].find("Failure"), std::string::npos) << "GoogleTest's report, file:line first: " << lines[0];
    EXPECT_TRUE(lines[40].starts_with("\u2026 29") && lines[40].ends_with(" more lines like these")) << lines[40];
    EXPECT_EQ(lines[41], "--- what your code printed ---");
    EXPECT_EQ(lines[42], "line 1");
    EXPECT_EQ(lines[61], "line 20");
    EXPECT_EQ(lines[62], "\u2026 80 more lines like these");
}

TEST_F(TestRunnerTest, ImageNumbersAndPicturesAreCollected) {
    const TestOutcome outcome = run_test(program, "FakeImage.IsTwoPercentOff");
    EXPECT_EQ(outcome.status, Status::failed);
    ASSERT_TRUE(outcome.image.has_value());
    EXPECT_DOUBLE_EQ(outcome.image->failing_fraction, 0.02);
    EXPECT_EQ(outcome.image->worst_x, 3);
    EXPECT_EQ(outcome.pictures, folder / "FakeImage.IsTwoPercentOff");
}

// The worker's ending comes before the checker's verdict: a test the checker
// passed does not pass when the student's code crashed, hung or lingered.
TEST_F(TestRunnerTest, TheWorkersEndingComesFirst) {
    program.worker = {MISBEHAVING_CHILD, "segfault"};
    TestOutcome outcome = run_test(program, "Fake.Passes");
    EXPECT_EQ(outcome.status, Status::crash);
    EXPECT_EQ(outcome.message.rfind("your code was killed by SIGSEGV", 0), 0u) << outcome.message;

    program.worker = {MISBEHAVING_CHILD, "exit", "1"};
    outcome = run_test(program, "Fake.Passes");
    EXPECT_EQ(outcome.status, Status::crash);
    EXPECT_EQ(outcome.message, "your code ended the program (exit code 1) before the test was over");

    program.worker = {MISBEHAVING_CHILD, "loop"};
    EXPECT_EQ(run_test(program, "Fake.Loops").status, Status::timeout);

    program.worker = {MISBEHAVING_CHILD, "sleep"};
    program.linger_seconds = 0.2;
    outcome = run_test(program, "Fake.Passes");
    EXPECT_EQ(outcome.status, Status::crash);
    EXPECT_NE(outcome.message.find("went on running after the test was over"), std::string::npos) << outcome.message;
}

// The checker names the call to the worker that was in progress when the worker died; the crash's message says it.
TEST_F(TestRunnerTest, ACrashNamesTheLabFunctionThatWasRunning) {
    program.worker = {MISBEHAVING_CHILD, "segfault"};
    const TestOutcome outcome = run_test(program, "Fake.WorkerDiesDuringBoxEntry");
    EXPECT_EQ(outcome.status, Status::crash);
    EXPECT_EQ(outcome.message.rfind("your code crashed in box_entry() (labs/10_bvh.cpp): killed by SIGSEGV", 0), 0u)
        << outcome.message;
    // The checker's words for the closed link repeat nothing the student needs; the worker printed nothing.
    EXPECT_EQ(outcome.output.find("link closed it"), std::string::npos) << outcome.output;
    EXPECT_EQ(outcome.output.find("what your code printed"), std::string::npos) << outcome.output;
}

// A lab's tests run together first; only the passes of a run that ended
// cleanly count, and the grader runs every other test on its own.
TEST_F(TestRunnerTest, TogetherOnlyTheTestsThatPassedCount) {
    const std::vector<std::string> names = {"Fake.Passes", "Fake.GivesAWrongAnswer", "Fake.CallsAStub", "Fake.ThrowsSomethingElse",
                                            "FakeImage.IsTwoPercentOff", "HiddenFake.Passes"};
    EXPECT_EQ(passed_together(program, names, 10.0), (std::set<std::string>{"Fake.Passes", "HiddenFake.Passes"}));
    EXPECT_TRUE(passed_together(program, {}, 10.0).empty());
}

TEST_F(TestRunnerTest, TogetherARunThatDidNotEndCleanlyCountsForNothing) {
    EXPECT_TRUE(passed_together(program, {"Fake.Passes", "Fake.Segfaults"}, 10.0).empty()) << "the checker crashed";
    EXPECT_TRUE(passed_together(program, {"Fake.Passes", "Fake.Loops"}, 0.5).empty()) << "a test hung";
    EXPECT_TRUE(passed_together(program, {"Fake.Passes", "Fake.NoSuchTest"}, 10.0).empty()) << "a test did not run";
    EXPECT_TRUE(passed_together(program, {"Fake.Passes", "-Fake.Passes"}, 10.0).empty()) << "not a plain name";
    program.worker = {MISBEHAVING_CHILD, "segfault"};
    EXPECT_TRUE(passed_together(program, {"Fake.Passes"}, 10.0).empty()) << "the worker crashed";
    program.worker = {MISBEHAVING_CHILD, "exit", "1"};
    EXPECT_TRUE(passed_together(program, {"Fake.Passes"}, 10.0).empty()) << "the worker exited early";
    program.worker = {MISBEHAVING_CHILD, "sleep"};
    program.linger_seconds = 0.2;
    EXPECT_TRUE(passed_together(program, {"Fake.Passes"}, 10.0).empty()) << "the worker went on running";
}

TEST_F(TestRunnerTest, FolderNamesStayInTheirFolder) {
    EXPECT_EQ(folder_name("Suite.Test/3"), "Suite.Test_3");
    EXPECT_EQ(folder_name(".."), "_..");
    EXPECT_EQ(folder_name("."), "_.");
    EXPECT_EQ(folder_name(""), "_");
}
