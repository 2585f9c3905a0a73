// The progress of a class's grading (`whitted grade-all`) on stderr: on a
// terminal one line redrawn, `[12/200] 6%  ana: 87.5/100  elapsed 1m40s  ETA 26m`;
// elsewhere (a log, CI) one plain line per finished student; nothing when quiet.
#pragma once

#include "grader/class_grades.hpp"

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>

namespace whitted::grade {

/// "45s", "1m40s", "2h05m".
std::string format_duration(double seconds);

class ClassProgress {
  public:
    /// Progress of `total` gradings run `parallel` at a time on `stream`;
    /// `terminal` redraws one line, `quiet` prints nothing.
    ClassProgress(std::FILE* stream, std::size_t total, int parallel, bool terminal, bool quiet);

    /// Reports a finished student's grade, which took `seconds`.
    void finished(const StudentGrade& grade, double seconds);

    /// Redraws the line on a terminal when a second has passed (the elapsed time moves on).
    void tick();

    /// Erases the redrawn line, before the closing summary.
    void clear();

  private:
    void draw();

    std::FILE* stream_;
    std::size_t total_;
    int parallel_;
    bool terminal_;
    bool quiet_;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    std::chrono::steady_clock::time_point last_draw_{};
    std::chrono::steady_clock::time_point last_finish_{};
    std::size_t done_ = 0;
    double busy_seconds_ = 0; // the finished gradings' times summed
    std::string last_;        // "ana: 87.5/100"
    bool drawn_ = false;
};

} // namespace whitted::grade
