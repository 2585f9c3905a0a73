// The pinhole camera of the slides: eye, at, up, a vertical field of view and
// a resolution, with the derived viewing frame and view-plane size.
//
// Why: the frame (xe, ye, ze), the view distance df and the view-plane size
// (w, h) are computed once here, exactly as the slides define them, so that lab
// 1's `primary_ray()` only has to place a point on the view plane.
#pragma once

#include "whitted/math.hpp"

namespace whitted {

struct Camera {
    // What the scene file gives.
    Point3 eye{0.0, 0.0, 1.0};
    Point3 at{0.0, 0.0, 0.0};
    Vec3 up{0.0, 1.0, 0.0};
    double fovy = 45.0; // full vertical field of view in degrees, edge to edge of the view plane
    int res_x = 512;
    int res_y = 512;
    // The thin lens of the course's P3F camera (depth of field). The lens is a
    // disk of this diameter around the eye, in the xe, ye plane; 0 = a pinhole.
    double aperture = 0.0;    // lens diameter in scene units (P3F `aperture a`: a pixel widths, a w / res_x)
    double focal_ratio = 1.0; // distance to the plane in focus / df (P3F `focal f`)

    // Derived by `Camera::create`.
    double df = 1.0;    // view distance |eye - at|
    double h = 1.0;     // view-plane height: 2 df tan(fovy / 2)
    double w = 1.0;     // view-plane width: res_x / res_y * h
    Vec3 xe{1, 0, 0};   // right
    Vec3 ye{0, 1, 0};   // up, perpendicular to the view direction
    Vec3 ze{0, 0, 1};   // backwards: from `at` towards `eye`

    /// Builds the camera and its frame. Assumes eye != at, up not parallel to
    /// at - eye, 0 < fovy < 180 and positive resolution (the scene loader checks them).
    static Camera create(Point3 eye, Point3 at, Vec3 up, double fovy_degrees, int res_x, int res_y);

    /// The same camera with another resolution: the view-plane height and the
    /// lens (aperture in scene units, focal_ratio) are kept, the width follows the new aspect ratio.
    Camera with_resolution(int new_res_x, int new_res_y) const;
};

} // namespace whitted
