// A range of ray parameters t, open at both ends.
//
// Why: every intersection routine answers "is there a hit with t inside this
// range?". Shrinking the range's max to the nearest hit found so far is how the
// closest hit is kept, and a shadow feeler's range stops at the light.
#pragma once

#include "whitted/math.hpp"

namespace whitted {

struct Interval {
    double min = 0.0;
    double max = kInfinity;

    /// True when min < t < max.
    constexpr bool surrounds(double t) const { return min < t && t < max; }
};

} // namespace whitted
