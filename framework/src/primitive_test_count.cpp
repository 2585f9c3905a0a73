#include "whitted/primitive_test_count.hpp"

namespace whitted::detail {

// A count belongs to the thread that made it.
constinit thread_local PrimitiveTestCount* innermost_primitive_test_count = nullptr;

} // namespace whitted::detail
