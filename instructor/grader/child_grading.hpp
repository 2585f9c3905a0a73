// One student's `whitted grade` run as a child process (`whitted grade-all`):
// started in a process group of its own with its output in a log file, and
// read back, once it ended, as the student's grade.
//
// Why: a class is graded one submission after another by the same grader; a
// child process per student keeps one grading's crash, hang or failure from
// touching the others, and every grading keeps all of grade's fences.
#pragma once

#include "grader/class_grades.hpp"

#include <filesystem>
#include <string>
#include <sys/types.h>
#include <vector>

namespace whitted::grade {

/// Makes `out` ready for a grading: a new private folder with grade's marker,
/// or one grade wrote before (its results.json removed, so that an old one
/// never counts); throws std::runtime_error when it is someone else's.
void prepare_grading_folder(const std::filesystem::path& out);

/// Starts `program grade SUBMISSION --out OUT -q OPTIONS...` in a process
/// group of its own, stdin from /dev/null, stdout and stderr to OUT/grade.log,
/// with TMPDIR set to `temporary` (where it stages its kit).
/// Returns its process id; throws std::runtime_error when it cannot start.
pid_t start_grading(const std::filesystem::path& program, const std::filesystem::path& submission, const std::filesystem::path& out,
                    const std::vector<std::string>& options, const std::filesystem::path& temporary);

/// The student's grade from how the child ended (waitpid's status), OUT/results.json and OUT/grade.log.
StudentGrade finished_grading(const std::string& student, int wait_status, const std::filesystem::path& out);

/// Kills a child grading's whole process group and reaps the child.
void kill_grading(pid_t pid);

} // namespace whitted::grade
