// What the passes share: their special colours, the colour scale for counts,
// and the last step that turns raw numbers into a picture with a summary.
#pragma once

#include "whitted/image.hpp"
#include "whitted/passes.hpp"

#include <string>

namespace whitted::detail {

inline const Color kBackground(0.0);                 // the eye ray hit nothing
inline const Color kNotApplicable(0.05, 0.05, 0.3);  // dark blue: the pass says nothing here
inline const Color kShadowBackground(0.0, 0.3, 0.3); // teal: black means "in shadow" in the shadow pass

/// A scale for counts: dark blue, light blue, green, yellow, red, from s = 0 to 1.
Color ramp(double s);

/// Turns the raw numbers of the depth and cost passes into colours, and says
/// in one line what the picture holds (empty when there is nothing to add).
std::string finish_pass(Pass pass, Image& image);

} // namespace whitted::detail
