// The mark of an output folder `whitted grade` wrote: a folder holding it may be
// emptied and written again; any other non-empty folder is refused as --out.
#pragma once

namespace whitted::grade {

/// The marker file's name in a grading's output folder.
inline constexpr const char* kGradeOutputMarker = ".whitted-grade";

/// The marker's content.
inline constexpr const char* kGradeOutputMarkerText = "whitted grade output; the grader empties labs/ and tests/ here\n";

} // namespace whitted::grade
