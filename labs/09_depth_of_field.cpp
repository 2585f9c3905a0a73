// Lab 9 — depth of field: a real camera has a lens, not a pinhole. Rays from
// every point of the lens that pass through one point of the plane in focus
// meet there again (that point is sharp); a point nearer or farther is seen
// through many lens points at slightly different places (a blurred disk).
// Handout: docs/labs/09_depth_of_field.md. Tests: make test LAB=9
#include "whitted/labs.hpp"

namespace whitted {

// The point of the unit disk for u in [0, 1)^2 (Shirley and Chiu's concentric
// mapping: equal areas of the square go to equal areas of the disk).
// First a = 2u - 1, in the square [-1, 1]^2; a = (0, 0) is the centre (0, 0).
// When |a.x| > |a.y| (the wedges left and right): radius r = a.x, angle
// (pi / 4) (a.y / a.x). Otherwise (the wedges above and below): r = a.y, angle
// pi / 2 - (pi / 4) (a.x / a.y). The point is (r cos(angle), r sin(angle)).
Vec2 concentric_disk(Vec2 u) {
    not_implemented();
}

// The eye ray through viewport position (x, y) (in pixels, as for primary_ray)
// that starts on the lens at the point lens_u picks. The lens is a disk of
// diameter camera.aperture around the eye in the camera's xe, ye plane: its point
// is eye + (aperture / 2) (d.x xe + d.y ye) with d = concentric_disk(lens_u).
// p = (x / res_x - 1/2) w xe + (y / res_y - 1/2) h ye - df ze is the point
// primary_ray aims at, seen from the eye; every lens ray of (x, y) passes
// through the focal point eye + camera.focal_ratio p. The direction is a unit vector.
Ray thin_lens_ray(const Camera& camera, double x, double y, Vec2 lens_u) {
    not_implemented();
}

} // namespace whitted
