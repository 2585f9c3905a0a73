// The image size a benchmark tool renders at, from --width and --height.
//
// Why: the POV-Ray exporter and the Embree harness must frame a scene exactly as
// `whitted render` does for the same options: both sizes given are used as they
// are; one alone keeps the scene file's aspect ratio; none keeps the file's size.
#pragma once

#include "whitted/camera.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace whitted::bench {

/// The camera at the size asked for (the view-plane height is kept, as whitted render does).
inline Camera camera_at_size(const Camera& camera, std::optional<int> width, std::optional<int> height) {
    int w = camera.res_x, h = camera.res_y;
    if (width && height) {
        w = *width;
        h = *height;
    } else if (width) {
        w = *width;
        h = std::max(1, static_cast<int>(std::lround(*width * double(camera.res_y) / camera.res_x)));
    } else if (height) {
        h = *height;
        w = std::max(1, static_cast<int>(std::lround(*height * double(camera.res_x) / camera.res_y)));
    }
    return camera.with_resolution(w, h);
}

} // namespace whitted::bench
