// Lab 6 answered by the other side of the grading link (lab_link.hpp).
#include "lab_link.hpp"

#include "whitted/labs.hpp"

namespace whitted {

using link::Link;
using link::Op;

double fresnel_reflectance(double cos_theta_i, double eta_i, double eta_t) {
    Link::Call call(Link::current(), Op::fresnel_reflectance);
    call.args().put(cos_theta_i), call.args().put(eta_i), call.args().put(eta_t);
    return call.result<double>();
}

Color fresnel_blend(const Tracer& tracer, const Hit& hit, const Vec3& wo, int depth) {
    Link& link = Link::current();
    Link::Call call(link, Op::fresnel_blend);
    call.answers_ahead(link.fresnel_blend_answers(tracer, hit, wo));
    call.tracer(tracer), call.args().put(hit), call.args().put(wo), call.args().put(depth);
    return call.result<Color>();
}

} // namespace whitted
