// Writes a loaded scene as an equivalent POV-Ray 3.7 scene, so that `make bench`
// can time POV-Ray on exactly the geometry, lights and materials `whitted` renders.
//
// Why: comparing against an established renderer only means something when both
// trace the same rays: same camera, same shadow rays, same reflection and
// refraction depth, no antialiasing and no adaptive depth cut-off.
#pragma once

#include "whitted/scene.hpp"

#include <iosfwd>
#include <string>

namespace whitted::bench {

struct PovOptions {
    int max_trace_level = 5; // POV-Ray's max_trace_level (the eye ray counts as level 1)
    // POV-Ray lets light through transparent objects (filtered shadows); whitted's
    // shadow feelers stop at any surface. When set, each transparent object casts
    // no shadow itself and an invisible opaque copy of it casts the shadow instead.
    bool opaque_shadows = true;
    std::string source; // where the scene came from, written in the file's first comment
};

/// POV-Ray's perspective camera vectors for our camera (see pov_scene.cpp for the derivation).
struct PovCamera {
    Point3 location;
    Vec3 direction; // from the eye to the centre of the view plane
    Vec3 right;     // across the view plane, left to right, its full width
    Vec3 up;        // across the view plane, bottom to top, its full height
    double horizontal_angle = 0.0; // degrees, edge to edge (POV's `angle`), for reference
};

/// The POV-Ray camera vectors that shoot exactly the eye rays of `camera`.
PovCamera pov_camera(const Camera& camera);

/// Writes `data` (camera at its resolution, lights, materials, every primitive) as a .pov file.
void write_pov_scene(const SceneData& data, const PovOptions& options, std::ostream& out);

} // namespace whitted::bench
