// The programs built without a live build (every `whitted` but the main one, e.g. the mistake renderers):
// explore renders with the program itself and does not rebuild.
#include "explore/live_build.hpp"

namespace whitted {

std::optional<LiveBuild> live_build() { return std::nullopt; }

} // namespace whitted
