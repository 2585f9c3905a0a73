// A one-line progress bar with an ETA, drawn on a terminal only.
#pragma once

#include <chrono>
#include <cstdio>

namespace whitted {

class ProgressBar {
  public:
    /// A bar on `stream`; it draws nothing unless `enabled` (a terminal, not --quiet).
    ProgressBar(std::FILE* stream, bool enabled);

    /// Redraws the bar for the fraction done (0..1), at most ten times a second.
    void update(double fraction_done);

    /// Erases the bar.
    void finish();

  private:
    std::FILE* stream_;
    bool enabled_;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point last_draw_{};
    bool drawn_ = false;
};

} // namespace whitted
