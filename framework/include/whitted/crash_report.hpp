// A crash in lab code, reported as one line that names the lab function that
// was running:
//
//   whitted: crashed in bvh_closest_hit() (labs/10_bvh.cpp): segmentation fault (signal 11) -- a bad memory access: ...
//
// instead of the system's bare "Segmentation fault", then exit code 3 (the
// README's "Exit codes"). The framework marks every call it makes into lab code
// (framework/src/lab_call.hpp); a function a lab calls within its own file runs
// inside the one the framework called, which is the one named.
#pragma once

namespace whitted {

/// From now on, a crash of this program (a bad memory access, an integer
/// division by zero, abort(), an illegal instruction) prints that line on the
/// standard error and exits with code 3. For the `whitted` command's main().
void report_crashes();

} // namespace whitted
