// Which lab function is running, for the report of a crash (whitted/crash_report.hpp).
//
// Why: a crash in lab code (an index past the end of a vector, a null pointer,
// a recursion without end) kills the program with a signal, and all the system
// says is "segmentation fault". The framework calls lab code from a few places;
// each marks the call with a LabCall, which keeps the function's name in a
// variable of the thread while it runs, so that the crash report can name it.
// Calls nest (a lab function calls the framework, which calls another lab
// function): the innermost one is named. A function a lab calls within its own
// file (bvh_closest_hit calling box_entry) runs inside the marked one. A mark
// is two stores to the thread's own memory, beside a call that does far more.
#pragma once

#include <cstddef>
#include <utility>

namespace whitted::detail {

/// The name of the lab function running on this thread, innermost ("box_entry"); null outside lab code.
extern constinit thread_local const char* running_lab_function;

/// Marks lab function `name` (a string literal) as running on this thread while the mark lives.
class LabCall {
  public:
    explicit LabCall(const char* name) noexcept : outer_(running_lab_function) { running_lab_function = name; }
    ~LabCall() { running_lab_function = outer_; }
    LabCall(const LabCall&) = delete;
    LabCall& operator=(const LabCall&) = delete;

  private:
    const char* outer_;
};

/// Calls lab function `function`, named `name`, with `args`, marked as running.
template <class Function, class... Args>
decltype(auto) call_lab(const char* name, Function&& function, Args&&... args) {
    const LabCall running(name);
    return std::forward<Function>(function)(std::forward<Args>(args)...);
}

/// While it lives, the crash report works on this thread even when its stack
/// has overflowed (a recursion without end): the report gets a small stack of
/// its own. Does nothing unless report_crashes() was called.
class CrashReportStack {
  public:
    CrashReportStack();
    ~CrashReportStack();
    CrashReportStack(const CrashReportStack&) = delete;
    CrashReportStack& operator=(const CrashReportStack&) = delete;

  private:
    void* memory_ = nullptr;
};

} // namespace whitted::detail
