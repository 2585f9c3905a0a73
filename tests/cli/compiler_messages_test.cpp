// The errors `whitted explore` shows when a lab does not compile (framework/app/explore/compiler_messages.hpp),
// read from output as GCC, Clang and MSVC write it (the lines are theirs, from a lab with a missing ';').
#include "explore/compiler_messages.hpp"

#include <gtest/gtest.h>

using namespace whitted;

namespace {
void expect_error(const CompilerError& error, const std::string& file, int line, int column, const std::string& message) {
    EXPECT_EQ(error.file, file);
    EXPECT_EQ(error.line, line);
    EXPECT_EQ(error.column, column);
    EXPECT_EQ(error.message, message);
}
} // namespace

TEST(CompilerErrors, GccLinesGiveFileLineColumnAndMessage) {
    const std::string output = "[ 50%] Building CXX object CMakeFiles/student_05_refraction.dir/labs/05_refraction.cpp.o\n"
                               "/home/ana/course/labs/05_refraction.cpp: In function 'whitted::Vec3 refracted_direction()':\n"
                               "/home/ana/course/labs/05_refraction.cpp:42:10: error: expected ';' before '}' token\n"
                               "   42 |     return t\n"
                               "      |          ^\n"
                               "/home/ana/course/labs/05_refraction.cpp:40:5: note: to match this '{'\n"
                               "/home/ana/course/labs/05_refraction.cpp:57:1: fatal error: no return statement\n"
                               "gmake[2]: *** [CMakeFiles/x.dir/build.make:76: x.o] Error 1\n";
    const std::vector<CompilerError> errors = compiler_errors(output);
    ASSERT_EQ(errors.size(), 2u);
    expect_error(errors[0], "/home/ana/course/labs/05_refraction.cpp", 42, 10, "expected ';' before '}' token");
    expect_error(errors[1], "/home/ana/course/labs/05_refraction.cpp", 57, 1, "no return statement");
}

TEST(CompilerErrors, MsvcLinesWithBackslashesAndCarriageReturns) {
    const std::string output =
        "  05_refraction.cpp\r\n"
        "C:\\Users\\Zoë\\course\\labs\\05_refraction.cpp(42,10): error C2143: syntax error: missing ';' before '}'\r\n"
        "C:\\Users\\Zoë\\course\\labs\\05_refraction.cpp(7): warning C4100: 'wo': unreferenced parameter\r\n"
        "C:\\Users\\Zoë\\course\\labs\\06_fresnel.cpp(13): fatal error C1075: '{': no matching token found\r\n";
    const std::vector<CompilerError> errors = compiler_errors(output);
    ASSERT_EQ(errors.size(), 2u);
    expect_error(errors[0], "C:\\Users\\Zoë\\course\\labs\\05_refraction.cpp", 42, 10, "syntax error: missing ';' before '}'");
    expect_error(errors[1], "C:\\Users\\Zoë\\course\\labs\\06_fresnel.cpp", 13, 0, "'{': no matching token found");
}

TEST(CompilerErrors, WarningsNotesAndOtherLinesAreNotErrors) {
    EXPECT_TRUE(compiler_errors("labs/01_ray_casting.cpp:3:1: warning: unused variable 'x'\n"
                                "labs/01_ray_casting.cpp:3:1: note: declared here\n"
                                "error: this line names no file\n"
                                "[100%] Built target whitted\n")
                    .empty());
}

TEST(CompilerErrors, AtMostTheLimitAndNoOverflowOnAHugeLineNumber) {
    std::string output;
    for (int i = 1; i <= 30; ++i) output += "a.cpp:" + std::to_string(i) + ":1: error: e\n";
    EXPECT_EQ(compiler_errors(output).size(), 20u);
    EXPECT_EQ(compiler_errors(output, 3).size(), 3u);
    EXPECT_TRUE(compiler_errors("a.cpp:99999999999999999999: error: e\n").empty()); // not a line number; no throw
}

TEST(BuildErrors, TheLinkersLinesWhenNoCompilerErrorHasALine) {
    const std::string linked = "/usr/bin/ld: CMakeFiles/w.dir/labs/05_refraction.cpp.o: in function `call_it()':\n"
                               "05_refraction.cpp:(.text+0x1): undefined reference to `not_defined_anywhere()'\n"
                               "collect2: error: ld returned 1 exit status\n"
                               "[100%] Built target whitted_framework\n";
    const std::vector<CompilerError> errors = build_errors(linked);
    ASSERT_EQ(errors.size(), 2u);
    expect_error(errors[0], "", 0, 0, "05_refraction.cpp:(.text+0x1): undefined reference to `not_defined_anywhere()'");
    expect_error(errors[1], "", 0, 0, "collect2: error: ld returned 1 exit status");
    // With a compiler error that has its line, that one alone.
    EXPECT_EQ(build_errors("a.cpp:3:1: error: e\ncollect2: error: ld returned 1\n").size(), 1u);
}

// MSBuild (Visual Studio's generator) adds the project to each error line and repeats the errors in its summary.
TEST(CompilerErrors, MsbuildsProjectSuffixAndSummaryAreLeftOut) {
    const std::string project = " [C:\\Users\\Zoe\\labs\\build\\whitted_labs.vcxproj]\r\n";
    const std::string error = "C:\\Users\\Zoe\\labs\\05_refraction.cpp(42,10): error C2143: syntax error: missing ';' before '}'";
    const std::string output = "  05_refraction.cpp\r\n" + error + project + "\r\nBuild FAILED.\r\n\r\n" +
                               "\"C:\\Users\\Zoe\\labs\\build\\ALL_BUILD.vcxproj\" (default target) (1) ->\r\n" + "  " +
                               error + project + "\r\n    0 Warning(s)\r\n    1 Error(s)\r\n";
    const std::vector<CompilerError> errors = build_errors(output);
    ASSERT_EQ(errors.size(), 1u);
    expect_error(errors[0], "C:\\Users\\Zoe\\labs\\05_refraction.cpp", 42, 10, "syntax error: missing ';' before '}'");
}

TEST(BuildErrors, MsvcsLinkerLinesOnceWithoutTheProjectOrTheCount) {
    const std::string link = "05_refraction.obj : error LNK2019: unresolved external symbol \"not_defined_anywhere\"";
    const std::string project = " [C:\\course [2]\\build\\whitted.vcxproj]\r\n"; // " [" in the path too
    const std::string output =
        link + project + "Build FAILED.\r\n  " + link + project + "    0 Warning(s)\r\n    1 Error(s)\r\n";
    const std::vector<CompilerError> errors = build_errors(output);
    ASSERT_EQ(errors.size(), 1u);
    expect_error(errors[0], "", 0, 0, link);
}
