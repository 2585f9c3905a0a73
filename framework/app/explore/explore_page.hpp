// The one page of `whitted explore` (explore_page.cpp).
#pragma once

#include <string>

namespace whitted {

/// The page's HTML, CSS and JavaScript, as one document.
std::string explore_page();

} // namespace whitted
