// The crash report (whitted/crash_report.hpp) and the mark of the running lab
// function (lab_call.hpp). The one file of the framework that differs between
// systems: POSIX (Linux, macOS) catches the signals with sigaction() on a
// stack of their own, Windows with signal(), which it offers for SIGSEGV,
// SIGFPE, SIGILL and SIGABRT (it has no SIGBUS, and a stack overflow there
// ends the program before any handler runs).
//
// The handler runs in the middle of a crash, so it only does what is safe in a
// signal handler: it reads the mark, fills a buffer of its own, writes it with
// write() (_write() on Windows) and ends the program with std::_Exit(). No
// allocation, no lock, no printf. When several threads crash at once, the
// first one reports and the others wait for it to end the program.
#include "whitted/crash_report.hpp"

#include "lab_call.hpp"
#include "whitted/lab_table.hpp"

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdlib>
#include <string_view>

#ifdef _WIN32
#include <io.h>
#else
#include <unistd.h>
#endif

namespace whitted {

namespace detail {
constinit thread_local const char* running_lab_function = nullptr;
} // namespace detail

namespace {

constexpr int kCrashExitCode = 3; // the README's "whitted itself failed, or an unexpected error"
bool g_reporting = false;         // set once by report_crashes(), before any thread that runs lab code

// The lab whose row of the lab table lists `function`, or null.
const LabInfo* lab_with_function(std::string_view function) {
    for (const LabInfo& row : kLabs) {
        std::string_view rest = row.functions;
        while (!rest.empty()) {
            const std::size_t space = rest.find(' ');
            if (rest.substr(0, space) == function) return &row;
            rest = space == std::string_view::npos ? std::string_view() : rest.substr(space + 1);
        }
    }
    return nullptr;
}

// A line built in a buffer of its own, cut at its size.
struct CrashLine {
    char text[640];
    std::size_t size = 0;

    void add(std::string_view part) {
        const std::size_t count = std::min(part.size(), sizeof text - size);
        std::copy_n(part.data(), count, text + size);
        size += count;
    }
    void add(int number) {
        char digits[12];
        int count = 0;
        unsigned value = number < 0 ? 0u - static_cast<unsigned>(number) : static_cast<unsigned>(number);
        do digits[count++] = static_cast<char>('0' + value % 10); while ((value /= 10) != 0 && count < 11);
        if (number < 0) add("-");
        while (count > 0) add(std::string_view(&digits[--count], 1));
    }
};

// What the signal is called, and what in a lab's code usually raises it.
struct SignalText {
    std::string_view name, cause;
};
SignalText signal_text(int signal) {
    switch (signal) {
    case SIGSEGV:
        return {"segmentation fault",
                "a bad memory access: an index outside an array or vector, a null or dangling pointer, or a recursion "
                "that never ends"};
#ifndef _WIN32
    case SIGBUS: return {"bus error", "a bad memory access: a dangling or misaligned pointer"};
#endif
    case SIGFPE: return {"arithmetic error", "an integer division (or remainder) by zero"};
    case SIGILL: return {"illegal instruction", "often a function that ends without returning its value"};
    case SIGABRT: return {"abort", "abort() or a failed assert() stopped the program"};
    default: return {"signal", "an unexpected signal"};
    }
}

void write_error(const CrashLine& line) {
    std::size_t written = 0;
    while (written < line.size) {
#ifdef _WIN32
        const int count = _write(2, line.text + written, static_cast<unsigned>(line.size - written));
#else
        const ssize_t count = write(2, line.text + written, line.size - written);
#endif
        if (count <= 0) return;
        written += static_cast<std::size_t>(count);
    }
}

// Set by the first thread to crash: another thread that crashes meanwhile waits for it to end the program.
std::atomic_flag g_crashed; // clear: C++20 deprecates ATOMIC_FLAG_INIT, the default is clear

extern "C" void report_crash(int signal) {
    if (g_crashed.test_and_set()) {
        for (;;) {
#ifndef _WIN32
            pause();
#endif
        }
    }
    CrashLine line;
    const char* function = detail::running_lab_function;
    line.add("whitted: crashed ");
    if (function) {
        line.add("in "), line.add(function), line.add("()");
        if (const LabInfo* lab = lab_with_function(function)) line.add(" (labs/"), line.add(lab->stem), line.add(".cpp)");
    } else {
        line.add("outside the labs' code");
    }
    const SignalText text = signal_text(signal);
    line.add(": "), line.add(text.name), line.add(" (signal "), line.add(signal), line.add(")");
    if (function) line.add(" -- "), line.add(text.cause);
    else line.add(" -- a bug of whitted itself: please report it");
    line.add("\n");
    write_error(line);
    std::_Exit(kCrashExitCode);
}

#ifndef _WIN32
// The size of a crash report's own stack: the handler needs little, the system's frame some more.
std::size_t report_stack_size() { return std::max<std::size_t>(SIGSTKSZ, 64 * 1024); }

// Gives this thread `memory` as the stack for signal handlers; true when the system took it.
bool use_report_stack(void* memory) {
    stack_t stack{};
    stack.ss_sp = memory;
    stack.ss_size = report_stack_size();
    return sigaltstack(&stack, nullptr) == 0;
}
#endif

constexpr int kSignals[] = {
    SIGSEGV, SIGFPE, SIGILL, SIGABRT,
#ifndef _WIN32
    SIGBUS,
#endif
};

} // namespace

void report_crashes() {
    g_reporting = true;
#ifdef _WIN32
    for (const int signal : kSignals) std::signal(signal, report_crash);
#else
    static detail::CrashReportStack main_thread; // this thread's, for as long as the program runs
    struct sigaction action {};
    action.sa_handler = report_crash;
    sigemptyset(&action.sa_mask);
    // On the thread's report stack. The signal stays blocked while its handler runs: a crash in the report
    // itself ends the program as it would have without one.
    action.sa_flags = SA_ONSTACK;
    for (const int signal : kSignals) sigaction(signal, &action, nullptr);
#endif
}

namespace detail {

CrashReportStack::CrashReportStack() {
#ifndef _WIN32
    if (!g_reporting) return;
    memory_ = std::malloc(report_stack_size());
    if (memory_ && !use_report_stack(memory_)) {
        std::free(memory_);
        memory_ = nullptr;
    }
#endif
}

CrashReportStack::~CrashReportStack() {
#ifndef _WIN32
    if (!memory_) return;
    stack_t off{};
    off.ss_flags = SS_DISABLE;
    sigaltstack(&off, nullptr);
    std::free(memory_);
#endif
}

} // namespace detail

} // namespace whitted
