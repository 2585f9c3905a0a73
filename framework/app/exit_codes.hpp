// The exit codes of every `whitted` command: one convention, as diff, cmp and grep use theirs.
#pragma once

namespace whitted::exit_code {

/// The command did what was asked: the picture or file was written; diff: the images match; grade: full marks.
inline constexpr int success = 0;

/// The command ran and the answer is no: diff: the images differ; grade: points were lost. Nothing else returns 1.
inline constexpr int negative = 1;

/// The command could not do what was asked because of what it was given: a bad or missing option, a scene file
/// or image that is missing, unreadable or malformed, an output that cannot be written, labs not done yet.
inline constexpr int bad_input = 2;

/// The tool itself failed: the grader could not grade, an unexpected error, or a crash (whitted/crash_report.hpp).
inline constexpr int tool_failure = 3;

} // namespace whitted::exit_code
