#include "progress.hpp"

#include <string>

namespace whitted {

ProgressBar::ProgressBar(std::FILE* stream, bool enabled)
    : stream_(stream), enabled_(enabled), start_(std::chrono::steady_clock::now()) {}

void ProgressBar::update(double fraction_done) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (drawn_ && fraction_done < 1.0 && now - last_draw_ < std::chrono::milliseconds(100)) return;
    last_draw_ = now;
    drawn_ = true;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(fraction_done * kWidth);
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const std::string bar = std::string(filled, '#') + std::string(kWidth - filled, '.');
    if (fraction_done >= 0.05) { // earlier estimates rest on too few tiles
        const double eta = elapsed * (1.0 - fraction_done) / fraction_done;
        std::fprintf(stream_, "\r[%s] %3d%%  ETA %5.1f s ", bar.c_str(), static_cast<int>(fraction_done * 100), eta);
    } else {
        std::fprintf(stream_, "\r[%s] %3d%%", bar.c_str(), 0);
    }
    std::fflush(stream_);
}

void ProgressBar::finish() {
    if (!enabled_ || !drawn_) return;
    std::fprintf(stream_, "\r%60s\r", "");
    std::fflush(stream_);
}

} // namespace whitted
