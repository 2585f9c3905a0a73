// A class's CSV (`whitted grade-all`): points read back from the results.json
// grade writes, RFC 4180 quoting, rows sorted by name, the summary's failures.
#include "grader/class_grades.hpp"
#include "grader/results_json.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace whitted::grade;
namespace fs = std::filesystem;

namespace {

fs::path write_temporary(const std::string& name, const std::string& text) {
    const fs::path file = fs::temp_directory_path() / ("class_grades_test_" + std::to_string(getpid()) + "_" + name);
    std::ofstream(file, std::ios::binary) << text;
    return file;
}

StudentGrade graded(const std::string& student, long score, std::map<std::string, long> labs) {
    return {student, GradeStatus::graded, ResultsPoints{score, 10000, std::move(labs)}, ""};
}

} // namespace

TEST(ClassGrades, ReadsThePointsOfGradesResultsJson) {
    GradingResult result;
    for (const char* name : {"01_ray_casting", "integration"}) {
        LabResult lab;
        lab.lab = name;
        lab.title = name;
        TestOutcome passed;
        passed.name = "Suite.Passed";
        passed.status = Status::passed;
        TestOutcome failed = passed;
        failed.name = "Suite.Failed";
        failed.status = Status::failed;
        lab.tests = {{passed, "unit", 333, 333}, {failed, "unit", 167, 0}};
        result.labs.push_back(lab);
    }
    result.score_cents = 666;
    result.max_cents = 1000;
    const fs::path file = write_temporary("results.json", results_json(result));
    const ResultsPoints points = read_results_points(file);
    fs::remove(file);
    EXPECT_EQ(points.score_cents, 666);
    EXPECT_EQ(points.max_cents, 1000);
    EXPECT_EQ(points.labs, (std::map<std::string, long>{{"01_ray_casting", 333}, {"integration", 333}}));
}

TEST(ClassGrades, RefusesWhatIsNotAResultsJson) {
    const fs::path file = write_temporary("bad.json", "{\"score\": 1, \"tests\": [{\"score\": 1}]}");
    EXPECT_THROW(read_results_points(file), std::runtime_error);
    fs::remove(file);
    EXPECT_THROW(read_results_points(file), std::runtime_error); // now missing
}

TEST(ClassGrades, PointsWithoutTrailingZeros) {
    EXPECT_EQ(compact_points(10000), "100");
    EXPECT_EQ(compact_points(8750), "87.5");
    EXPECT_EQ(compact_points(1234), "12.34");
    EXPECT_EQ(compact_points(5), "0.05");
    EXPECT_EQ(compact_points(0), "0");
}

TEST(ClassGrades, QuotesFieldsAsRfc4180Says) {
    EXPECT_EQ(csv_field("ana"), "ana");
    EXPECT_EQ(csv_field("Doe, Jane"), "\"Doe, Jane\"");
    EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
    EXPECT_EQ(csv_field("two\nlines"), "\"two\nlines\"");
}

TEST(ClassGrades, CsvRowsSortedWithEmptyPointsForErrors) {
    std::vector<StudentGrade> grades = {graded("ben", 8750, {{"01_ray_casting", 8750}}),
                                        {"Doe, Jane", GradeStatus::error, std::nullopt, "killed by SIGKILL"},
                                        graded("ana", 10000, {{"01_ray_casting", 5000}, {"integration", 5000}})};
    EXPECT_EQ(class_csv(grades, {"01_ray_casting", "integration"}),
              "student,score,max_score,status,01_ray_casting,integration\n"
              "\"Doe, Jane\",,,error,,\n"
              "ana,100,100,graded,50,50\n"
              "ben,87.5,100,graded,87.5,\n");
}

TEST(ClassGrades, SummaryGivesMeanMedianAndFailures) {
    std::vector<StudentGrade> grades = {graded("a", 10000, {}), graded("b", 5000, {}), graded("c", 0, {}), graded("d", 2500, {}),
                                        {"e", GradeStatus::grader_failure, ResultsPoints{}, "the rubric is wrong"}};
    EXPECT_EQ(class_summary(grades), "graded 4 of 5 students: mean 43.75, median 37.5 of 100\n"
                                     "not graded (1):\n"
                                     "  e: grader failure: the rubric is wrong\n");
}

// A submission the student must fix is listed with its reason, apart from the grader's failures.
TEST(ClassGrades, ASubmissionNotGradedIsListedWithItsReason) {
    std::vector<StudentGrade> grades = {graded("a", 10000, {}),
                                        {"b", GradeStatus::not_graded, ResultsPoints{}, "lab files were found in 2 places"}};
    EXPECT_EQ(class_summary(grades), "graded 1 of 2 students: mean 100, median 100 of 100\n"
                                     "not graded (1):\n"
                                     "  b: not graded: lab files were found in 2 places\n");
    EXPECT_EQ(class_csv(grades, {}), "student,score,max_score,status\na,100,100,graded\nb,0,0,not_graded\n");
}
