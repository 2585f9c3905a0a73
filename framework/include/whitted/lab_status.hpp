// Which labs are finished: each lab's functions are called once on a tiny
// scene, and a lab whose function throws NotImplemented is not done yet.
//
// Why: `whitted render` uses this to render the highest stage whose labs are
// all done, and to explain what is missing, instead of stopping at the first
// unfinished function deep inside a render.
#pragma once

#include "whitted/lab_table.hpp"

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace whitted {

class Scene;
class Tracer;

struct LabStatus {
    int number = 0;      // 1..kLabCount
    std::string name;    // "05_refraction": the file stem used everywhere
    std::string title;   // "refraction"
    bool done = true;
    std::string message; // the first "is not implemented yet" message, when not done
};

/// The status of every lab of the table, in order.
std::vector<LabStatus> probe_labs();

/// One call of each lab function on a tiny scene, by function name; `scene` and `tracer` must outlive them.
std::map<std::string_view, std::function<void()>> lab_probes(const Scene& scene, const Tracer& tracer);

/// The largest k such that labs 1..k are all done (0 when lab 1 is not).
int highest_complete_stage(const std::vector<LabStatus>& labs);

} // namespace whitted
