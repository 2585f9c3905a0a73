// Counting ray-primitive tests: how lab 10's tests measure a walk of a BVH.
//
// Why: a walk is right when it finds the nearest hit, and good when it finds it
// testing few primitives. The walk is given no counter to fill (it could fill
// it wrongly), so the count is kept below it: intersect() notes each test on
// the thread that makes it, and in a grading the checker notes each test the
// student's process asks it to make.
#pragma once

#include <cstdint>

namespace whitted {

class PrimitiveTestCount;

namespace detail {
/// This thread's innermost count, or null (primitive_test_count.cpp): read inline by
/// note_test(), which intersect() calls for every primitive test.
extern constinit thread_local PrimitiveTestCount* innermost_primitive_test_count;
} // namespace detail

/// Counts the ray-primitive tests made on this thread while it lives; when
/// counts nest, only the innermost one counts.
class PrimitiveTestCount {
  public:
    PrimitiveTestCount() : outer_(detail::innermost_primitive_test_count) { detail::innermost_primitive_test_count = this; }
    ~PrimitiveTestCount() { detail::innermost_primitive_test_count = outer_; }
    PrimitiveTestCount(const PrimitiveTestCount&) = delete;
    PrimitiveTestCount& operator=(const PrimitiveTestCount&) = delete;

    /// The tests counted so far.
    std::uint64_t tests() const { return tests_; }

    /// Notes one test in this thread's innermost count, if there is one.
    static void note_test() {
        if (PrimitiveTestCount* count = detail::innermost_primitive_test_count) ++count->tests_;
    }

  private:
    std::uint64_t tests_ = 0;
    PrimitiveTestCount* outer_ = nullptr;
};

} // namespace whitted
