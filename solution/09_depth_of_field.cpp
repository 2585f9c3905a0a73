// Lab 9 — depth of field: eye rays from points of a thin lens, focused on a plane.
#include "whitted/labs.hpp"

#include <cmath>

namespace whitted {

Vec2 concentric_disk(Vec2 u) {
    // The square [-1, 1]^2, its centre at the origin.
    const Vec2 a = 2.0 * u - Vec2(1.0);
    if (a.x == 0.0 && a.y == 0.0) return Vec2(0.0);
    // Each square around the centre becomes a circle of the same radius: the wedges
    // left and right of the diagonals by their x, those above and below by their y.
    double r, angle;
    if (std::abs(a.x) > std::abs(a.y)) {
        r = a.x;
        angle = (kPi / 4.0) * (a.y / a.x);
    } else {
        r = a.y;
        angle = kPi / 2.0 - (kPi / 4.0) * (a.x / a.y);
    }
    return r * Vec2(std::cos(angle), std::sin(angle));
}

Ray thin_lens_ray(const Camera& camera, double x, double y, Vec2 lens_u) {
    // p: the point of the view plane primary_ray aims at, seen from the eye.
    const Vec3 p = camera.w * (x / camera.res_x - 0.5) * camera.xe +
                   camera.h * (y / camera.res_y - 0.5) * camera.ye - camera.df * camera.ze;
    // The lens point, seen from the eye: a disk of radius aperture / 2 in the xe, ye plane.
    const Vec2 d = concentric_disk(lens_u);
    const Vec3 lens = (camera.aperture / 2.0) * (d.x * camera.xe + d.y * camera.ye);
    // Every ray of this viewport position meets at the focal point eye + focal_ratio p.
    return Ray{camera.eye + lens, glm::normalize(camera.focal_ratio * p - lens)};
}

} // namespace whitted
