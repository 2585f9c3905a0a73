#include "whitted/primitive_test_count.hpp"

namespace whitted {
namespace {

// The innermost count of this thread: a count belongs to the thread that made it.
thread_local PrimitiveTestCount* t_innermost = nullptr;

} // namespace

PrimitiveTestCount::PrimitiveTestCount() : outer_(t_innermost) { t_innermost = this; }

PrimitiveTestCount::~PrimitiveTestCount() { t_innermost = outer_; }

void PrimitiveTestCount::note_test() {
    if (PrimitiveTestCount* count = t_innermost) ++count->tests_;
}

} // namespace whitted
