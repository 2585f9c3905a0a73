// Lab 5 answered by the other side of the grading link (lab_link.hpp).
#include "lab_link.hpp"

#include "whitted/labs.hpp"

namespace whitted {

using link::Link;
using link::Op;

std::optional<Vec3> refracted_direction(const Vec3& wo, const Vec3& n, double eta_i, double eta_t) {
    Link::Call call(Link::current(), Op::refracted_direction);
    call.args().put(wo), call.args().put(n), call.args().put(eta_i), call.args().put(eta_t);
    return call.result<std::optional<Vec3>>();
}

Color refraction(const Tracer& tracer, const Hit& hit, const Vec3& wo, int depth) {
    Link::Call call(Link::current(), Op::refraction);
    call.tracer(tracer), call.args().put(hit), call.args().put(wo), call.args().put(depth);
    return call.result<Color>();
}

} // namespace whitted
