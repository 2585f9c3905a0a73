// Writes a loaded scene as an equivalent POV-Ray 3.7 scene, so that `make bench`
// can time POV-Ray on exactly the geometry, lights and materials `whitted` renders.
//
// Why: comparing against an established renderer only means something when both
// trace the same rays: same camera, same shadow rays, same reflection and
// refraction depth, no antialiasing and no adaptive depth cut-off.
#pragma once

#include "whitted/scene.hpp"

#include <iosfwd>

namespace whitted::bench {

struct PovOptions {
    int max_trace_level = 5; // POV-Ray's max_trace_level (the eye ray counts as level 1)
};

/// Writes `data` (camera at its resolution, lights, materials, every primitive) as a .pov file.
void write_pov_scene(const SceneData& data, const PovOptions& options, std::ostream& out);

} // namespace whitted::bench
