// Answers the checker sends ahead with a call to the worker (AnswerAhead in lab_link.hpp).
#include "lab_link.hpp"

#include "whitted/labs.hpp"

namespace whitted::link {

std::vector<AnswerAhead> Link::fresnel_blend_answers(const Tracer& tracer, const Hit& hit, const Vec3& wo) {
    std::vector<AnswerAhead> answers;
    // Only where this program answers all three, and the graded lab may call them (lab 6's checker).
    if (role_ != Role::checker) return answers;
    for (const Op op : {Op::spawn_ray, Op::mirror_direction, Op::refracted_direction})
        if (!allowed(op, nullptr) || !refused_inside(Op::fresnel_blend, op).empty()) return answers;
    // A call encoded as the worker's remote_NN.cpp encodes it, answered by serve_op() as a real call is.
    auto answer = [&](Op op, const auto&... arguments) {
        Writer call;
        call.raw(static_cast<std::uint16_t>(op));
        (call.put(arguments), ...);
        AnswerAhead ahead{std::move(call.bytes()), {}};
        const std::vector<std::byte> arguments_only(ahead.call.begin() + 2, ahead.call.end());
        Reader in(arguments_only);
        Writer reply;
        try {
            serve_op(*this, op, in, reply);
        } catch (...) {
            return false; // one that throws is asked for, and throws, over the link
        }
        ahead.reply = std::move(reply.bytes());
        answers.push_back(std::move(ahead));
        return true;
    };
    // The calls of the reference's fresnel_blend() (solution/06_fresnel.cpp): the mirror ray, and the refracted ray
    // for both orders of the indices, in the same order whichever side the hit is on, so that the answers tell
    // nothing of which order the reference picks there (lab 6's own work). At most six: answers.size() <= 8.
    if (hit.material >= tracer.scene().material_count()) return answers;
    answers.reserve(6);
    const double ior = tracer.scene().material(hit).ior;
    if (answer(Op::mirror_direction, wo, hit.normal)) answer(Op::spawn_ray, hit, mirror_direction(wo, hit.normal));
    for (const auto& [eta_i, eta_t] : {std::pair{1.0, ior}, std::pair{ior, 1.0}})
        if (answer(Op::refracted_direction, wo, hit.normal, eta_i, eta_t))
            if (const std::optional<Vec3> wt = refracted_direction(wo, hit.normal, eta_i, eta_t)) answer(Op::spawn_ray, hit, *wt);
    return answers;
}

} // namespace whitted::link
