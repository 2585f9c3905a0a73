// Lab 4 written by a student who tries to get answers grading must not give
// (or whose code crashes): mirror_direction() is right; reflection() misbehaves
// as WHITTED_HOSTILE says.
// Every reflection test run with it must fail: the checker refuses the first
// two and says the link broke; the worker itself refuses a tracer it did not
// make (and were that check removed, the checker would refuse what it asks).
#include "whitted/labs.hpp"

#include <cstdlib>
#include <string>

namespace whitted {

Vec3 mirror_direction(const Vec3& wo, const Vec3& n) { return 2.0 * glm::dot(wo, n) * n - wo; }

Color reflection(const Tracer& tracer, const Hit& hit, const Vec3& wo, int depth) {
    const char* mode_env = std::getenv("WHITTED_HOSTILE");
    const std::string mode = mode_env ? mode_env : "";
    if (mode == "later_lab") {
        // Lab 6's answer, asked for from lab 4's code.
        return Color(fresnel_reflectance(glm::dot(wo, hit.normal), 1.0, 1.5));
    }
    if (mode == "forged_hit") {
        // A hit on a material the scene does not have, handed to the reference's is_lit.
        Hit forged = hit;
        forged.material = 123456789;
        return Color(is_lit(tracer, forged, PointLight{Point3(0.0, 10.0, 0.0), Color(1.0)}) ? 1.0 : 0.0);
    }
    if (mode == "segfault") {
        // Dies in the middle of the call: the checker names the call it was waiting for.
        volatile int* nowhere = nullptr;
        *nowhere = 1;
    }
    if (mode == "own_tracer") {
        // A tracer of its own, at stage 6, to get lab 5 and 6 answers through trace().
        RenderSettings settings;
        settings.stage = 6;
        RayStats stats;
        const Tracer mine(tracer.scene(), settings, stats);
        return mine.trace(spawn_ray(hit, mirror_direction(wo, hit.normal)), depth + 1, RayKind::reflected, Color(1.0));
    }
    std::abort();
}

} // namespace whitted
