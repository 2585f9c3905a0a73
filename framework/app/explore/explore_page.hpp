// The one page of `whitted explore` (explore_page.cpp).
#pragma once

namespace whitted {

/// The page's HTML, CSS and JavaScript, as one document.
const char* explore_page();

} // namespace whitted
