// Lab 7 answered by the other side of the grading link (lab_link.hpp).
#include "lab_link.hpp"

#include "whitted/labs.hpp"

namespace whitted {

using link::Link;
using link::Op;

Vec2 stratified_sample(int index, int count, Vec2 u) {
    Link& link = Link::current();
    // A worker asks for the sample's cell once and computes every u's sample itself (StratifiedCell).
    if (link.role() == link::Role::worker && count >= 1)
        if (const std::optional<link::StratifiedCell> cell = link.stratified_cell(index, count)) return cell->sample(u);
    Link::Call call(link, Op::stratified_sample);
    call.args().put(index), call.args().put(count), call.args().put(u);
    return call.result<Vec2>();
}

Color pixel_color(const Tracer& tracer, int x, int y) {
    Link::Call call(Link::current(), Op::pixel_color);
    call.tracer(tracer), call.args().put(x), call.args().put(y);
    return call.result<Color>();
}

} // namespace whitted
