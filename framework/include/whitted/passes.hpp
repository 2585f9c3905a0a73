// Diagnostic passes: pictures of one quantity inside the ray tracer instead
// of the final colour (`whitted render --pass NAME`).
//
// Why: the final image mixes every step, so a wrong step hides behind the
// others. A pass shows one thing per pixel (the normal, the distance, which
// lights a point sees, how strongly it reflects, how many rays its tree has,
// what the rays cost) so a student can render the same pass with their code
// and with the reference and see which step differs. Each pass reads the
// pixel's ray tree (ray_tree.hpp) or calls one lab function at the eye ray's
// hit, through the student's own code.
#pragma once

#include "whitted/render.hpp"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace whitted {

enum class Pass { normal, depth, albedo, shadow, reflectance, fresnel, ray_depth, object_id, cost };

struct PassInfo {
    Pass pass;
    std::string_view name;    // as written after --pass
    Stage min_stage;          // the labs it calls: those up to this stage must be done
    std::string_view legend;  // how to read the picture, one sentence
};

/// Every pass, in the order of the list above.
std::span<const PassInfo> all_passes();

/// The pass called `name`, if there is one.
std::optional<Pass> find_pass(std::string_view name);

/// The name, stage and legend of a pass.
const PassInfo& pass_info(Pass pass);

struct PassResult {
    RenderResult render;  // the picture, ray counts and time
    std::string summary;  // numbers about the picture, one line (e.g. the cost's mean and maximum)
};

/// Renders the pass over the scene's camera view. Secondary rays follow
/// `settings` (stage, depth); passes about the eye ray's hit trace only that.
PassResult render_pass(const Scene& scene, const RenderSettings& settings, Pass pass, int threads = 0,
                       const ProgressCallback& progress = {});

} // namespace whitted
