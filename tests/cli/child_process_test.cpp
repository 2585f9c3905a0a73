// ChildProcess (framework/app/child_process.hpp) with child_process_probe, built beside this test: how a child
// ended (its exit code, a crash, stopped), its output and its arguments as they were given, a program not there.
#include "child_process.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <sstream>

using namespace whitted;
using namespace std::chrono_literals;

namespace {

// The probe's command line with these arguments: its path (beside this test's own executable), after the
// emulator that runs this test where there is one that a program started from here needs too (qemu-user).
std::vector<std::string> probe(const std::vector<std::string>& arguments) {
#ifdef _WIN32
    const char* name = "child_process_probe.exe";
#else
    const char* name = "child_process_probe";
#endif
    std::vector<std::string> argv = {PROBE_EMULATOR};
    argv.push_back((own_executable().parent_path() / name).string());
    argv.insert(argv.end(), arguments.begin(), arguments.end());
    return argv;
}

// A file for the running test's child's output, beside this test's executable (CTest may run tests side by side).
std::filesystem::path output_file() {
    const std::filesystem::path folder = own_executable().parent_path() / "child_process_output";
    std::filesystem::create_directories(folder);
    return folder / (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".txt");
}

std::string text_of(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), {}};
}

TEST(OwnExecutable, IsThisTestsProgram) {
    const std::filesystem::path self = own_executable();
    EXPECT_TRUE(self.is_absolute()) << self;
    EXPECT_NE(self.filename().string().find("child_process_tests"), std::string::npos) << self;
    EXPECT_TRUE(std::filesystem::is_regular_file(self)) << self;
}

TEST(ChildProcess, ReportsExitCodeZero) {
    const ChildExit exit = ChildProcess(probe({}), output_file()).wait();
    EXPECT_TRUE(exit.success());
    EXPECT_EQ(exit.code, 0);
    EXPECT_FALSE(exit.crashed);
    EXPECT_EQ(exit.reason, "exit code 0");
}

TEST(ChildProcess, ReportsExitCodeSeven) {
    const ChildExit exit = ChildProcess(probe({"exit", "7"}), output_file()).wait();
    EXPECT_FALSE(exit.success());
    EXPECT_EQ(exit.code, 7);
    EXPECT_FALSE(exit.crashed);
    EXPECT_EQ(exit.reason, "exit code 7");
}

TEST(ChildProcess, WritesStandardOutputAndErrorToTheFile) {
    const std::filesystem::path output = output_file();
    EXPECT_TRUE(ChildProcess(probe({"out", "to standard output", "err", "to standard error"}), output).wait().success());
    const std::string text = text_of(output);
    EXPECT_NE(text.find("to standard output"), std::string::npos) << text;
    EXPECT_NE(text.find("to standard error"), std::string::npos) << text;
}

TEST(ChildProcess, EmptiesTheOutputFileFirst) {
    const std::filesystem::path output = output_file();
    std::ofstream(output) << "left from before, longer than what follows";
    EXPECT_TRUE(ChildProcess(probe({"out", "new"}), output).wait().success());
    EXPECT_EQ(text_of(output), "new");
}

TEST(ChildProcess, PassesArgumentsUnchanged) {
    // Spaces, quotes, backslashes (before a quote and at the end), a tab, letters beyond ASCII, nothing at all.
    for (const std::string argument : {"a b \"c\" d\\ \xC3\xA9", "back\\\\\"slash\\", "tab\there", "\\\\server\\share\\",
                                       "\"", "", "plain"}) {
        const std::filesystem::path output = output_file();
        EXPECT_TRUE(ChildProcess(probe({"out", argument, "out", "|"}), output).wait().success());
        EXPECT_EQ(text_of(output), argument + "|");
    }
}

TEST(ChildProcess, ReportsACrash) {
    const ChildExit exit = ChildProcess(probe({"crash"}), output_file()).wait();
    EXPECT_TRUE(exit.crashed);
    EXPECT_FALSE(exit.success());
    EXPECT_EQ(exit.reason.rfind("crashed: ", 0), 0u) << exit.reason;
#ifdef _WIN32
    EXPECT_EQ(exit.reason, "crashed: access violation (exception 0xC0000005)");
#else
    EXPECT_NE(exit.reason.find("(signal "), std::string::npos) << exit.reason;
#endif
}

TEST(ChildProcess, LooksWithoutWaitingWhileTheChildRuns) {
    ChildProcess child(probe({"sleep"}), output_file());
    EXPECT_EQ(child.wait_for(0ms), std::nullopt);
    EXPECT_EQ(child.wait_for(20ms), std::nullopt);
}

TEST(ChildProcess, StopsASleepingChildAtOnce) {
    ChildProcess child(probe({"sleep"}), output_file());
    const auto start = std::chrono::steady_clock::now();
    child.stop();
    const std::optional<ChildExit> exit = child.wait_for(1s);
    ASSERT_TRUE(exit.has_value()) << "still running a second after stop()";
    EXPECT_LT(std::chrono::steady_clock::now() - start, 1s);
    EXPECT_EQ(exit->reason, "stopped");
    EXPECT_FALSE(exit->success());
    EXPECT_EQ(child.wait().reason, "stopped"); // the same answer again
}

TEST(ChildProcess, DestroyedWhileRunningStopsTheChild) {
    const auto start = std::chrono::steady_clock::now();
    {
        ChildProcess child(probe({"sleep"}), output_file());
        ChildProcess moved = std::move(child); // the moved-from one owns nothing
    }
    EXPECT_LT(std::chrono::steady_clock::now() - start, 10s); // not the probe's minute of sleep
}

TEST(ChildProcess, MissingProgramThrows) {
    const std::filesystem::path missing = own_executable().parent_path() / "no_such_program";
    EXPECT_THROW(ChildProcess({missing.string()}, output_file()), ChildStartError);
    EXPECT_THROW(ChildProcess({missing.string() + ".exe", "out", "x"}, output_file()), ChildStartError);
    EXPECT_THROW(ChildProcess({}, output_file()), ChildStartError);
}

TEST(ChildProcess, UnwritableOutputThrows) {
    const std::filesystem::path nowhere = own_executable().parent_path() / "no_such_folder" / "output.txt";
    EXPECT_THROW(ChildProcess(probe({}), nowhere), ChildStartError);
}

TEST(RunChild, RunsToTheEnd) {
    const std::filesystem::path output = output_file();
    const ChildExit exit = run_child(probe({"out", "ran", "exit", "3"}), output);
    EXPECT_EQ(exit.code, 3);
    EXPECT_EQ(exit.reason, "exit code 3");
    EXPECT_EQ(text_of(output), "ran");
}

} // namespace
