#include "whitted/camera.hpp"

#include <cmath>

namespace whitted {

Camera Camera::create(Point3 eye, Point3 at, Vec3 up, double fovy_degrees, int res_x, int res_y) {
    Camera camera;
    camera.eye = eye;
    camera.at = at;
    camera.up = up;
    camera.fovy = fovy_degrees;
    camera.res_x = res_x;
    camera.res_y = res_y;
    // The frame of the slides: ze points back at the eye, xe to the right, ye up.
    camera.df = glm::length(eye - at);
    camera.ze = (eye - at) / camera.df;
    camera.xe = glm::normalize(glm::cross(up, camera.ze));
    camera.ye = glm::cross(camera.ze, camera.xe);
    // The view plane passes through `at`: h = 2 df tan(fovy / 2), w = ResX / ResY h.
    camera.h = 2.0 * camera.df * std::tan(radians(fovy_degrees) / 2.0);
    camera.w = static_cast<double>(res_x) / res_y * camera.h;
    return camera;
}

Camera Camera::with_resolution(int new_res_x, int new_res_y) const {
    Camera camera = create(eye, at, up, fovy, new_res_x, new_res_y);
    // The same lens in scene units: the same blur, in more or fewer pixels.
    camera.aperture = aperture;
    camera.focal_ratio = focal_ratio;
    return camera;
}

} // namespace whitted
