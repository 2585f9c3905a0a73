#include "grader/class_progress.hpp"
#include "grader/text.hpp"

#include <algorithm>
#include <cmath>

namespace whitted::grade {
namespace {

// A student's name as the terminal may show it, cut to fit the line (where a character starts).
std::string short_name(const std::string& name) {
    const std::string shown = terminal_text(name);
    if (shown.size() <= 24) return shown;
    std::size_t cut = 23;
    while (cut > 0 && (static_cast<unsigned char>(shown[cut]) & 0xc0) == 0x80) --cut;
    return shown.substr(0, cut) + "~";
}

std::string outcome(const StudentGrade& grade) {
    if (grade.status == GradeStatus::graded && grade.points)
        return compact_points(grade.points->score_cents) + "/" + compact_points(grade.points->max_cents);
    return grade.status == GradeStatus::grader_failure ? "grader failure" : grade.status == GradeStatus::not_graded ? "not graded" : "error";
}

} // namespace

std::string format_duration(double seconds) {
    const long whole = std::lround(std::max(0.0, seconds));
    char text[32];
    if (whole < 60) std::snprintf(text, sizeof text, "%lds", whole);
    else if (whole < 3600) std::snprintf(text, sizeof text, "%ldm%02lds", whole / 60, whole % 60);
    else std::snprintf(text, sizeof text, "%ldh%02ldm", whole / 3600, whole / 60 % 60);
    return text;
}

ClassProgress::ClassProgress(std::FILE* stream, std::size_t total, int parallel, bool terminal, bool quiet)
    : stream_(stream), total_(total), parallel_(parallel), terminal_(terminal), quiet_(quiet) {}

void ClassProgress::finished(const StudentGrade& grade, double seconds) {
    ++done_;
    busy_seconds_ += seconds;
    last_finish_ = std::chrono::steady_clock::now();
    last_ = short_name(grade.student) + ": " + outcome(grade);
    if (quiet_) return;
    const std::string why = grade.status == GradeStatus::graded ? "" : ": " + grade.reason;
    // The student's name and the reason are the submission's: printed as the terminal may show them, the grader's own
    // control sequences (erasing and redrawing the line) apart.
    if (terminal_) {
        // A failure stays on the screen above the redrawn line.
        if (grade.status != GradeStatus::graded) {
            std::fputs("\r\033[K", stream_);
            print_line(stream_, grade.student + ": " + outcome(grade) + why);
        }
        draw();
        return;
    }
    char count[64], time[32];
    std::snprintf(count, sizeof count, "[%zu/%zu] ", done_, total_);
    std::snprintf(time, sizeof time, " (%.1f s)", seconds);
    print_line(stream_, count + grade.student + ": " + outcome(grade) + why + time);
    std::fflush(stream_);
}

void ClassProgress::tick() {
    if (quiet_ || !terminal_) return;
    if (drawn_ && std::chrono::steady_clock::now() - last_draw_ < std::chrono::seconds(1)) return;
    draw();
}

void ClassProgress::draw() {
    last_draw_ = std::chrono::steady_clock::now();
    drawn_ = true;
    const double elapsed = std::chrono::duration<double>(last_draw_ - start_).count();
    std::string line = "[";
    line += std::to_string(done_) + "/" + std::to_string(total_) + "] " + std::to_string(total_ ? done_ * 100 / total_ : 100) + "%";
    if (!last_.empty()) line += "  " + last_;
    line += "  elapsed " + format_duration(elapsed);
    // The mean time of a grading, for the students left, `parallel` at a time, counted from the last to finish.
    if (done_ > 0 && done_ < total_) {
        const double left = busy_seconds_ / static_cast<double>(done_) * static_cast<double>(total_ - done_) / parallel_;
        line += "  ETA " + format_duration(left - std::chrono::duration<double>(last_draw_ - last_finish_).count());
    }
    std::fputs("\r", stream_);
    print_text(stream_, line);
    std::fputs("\033[K", stream_);
    std::fflush(stream_);
}

void ClassProgress::clear() {
    if (quiet_ || !terminal_ || !drawn_) return;
    std::fprintf(stream_, "\r\033[K");
    std::fflush(stream_);
    drawn_ = false;
}

} // namespace whitted::grade
