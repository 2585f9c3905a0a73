// `whitted trace`: one pixel's ray tree as text, as JSON and as a picture.
//
// Why: the tree is what a student has to reason about when a pixel is wrong,
// so it is shown with the physics checked next to each ray: a reflected ray is
// compared with the mirror law, a refracted one with Snell's law, a shadow
// feeler that hits its own surface is called out. The checks are the
// framework's own computations, not the labs' code, so they can disagree.
#pragma once

#include "whitted/image.hpp"
#include "whitted/ray_tree.hpp"
#include "whitted/scene.hpp"
#include "whitted/tracer.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace whitted {

/// Which of a pixel's samples (lab 7) the tree is of, and the pixel's value.
struct ShownSample {
    int index = 0, count = 1; // sample `index` of `count` (0 .. count - 1)
    Vec2 place;               // where in the pixel it was traced, from its lower left corner, 0..1
    Color pixel;              // the pixel's value: pixel_color(), the average of its samples
};

/// What the reports say about the traced pixel besides its tree.
struct TraceContext {
    const Scene& scene;
    const RenderSettings& settings;
    std::string scene_path;
    int x = 0, y = 0;          // the pixel: column, and row from the top of the image
    int width = 0, height = 0; // the image's size
    std::optional<ShownSample> sample{}; // none: the pixel is one ray through its centre, the tree's eye ray
};

/// One pixel's traced ray tree, and which of its samples it is of.
struct TracedPixel {
    RayTree tree;
    std::optional<ShownSample> sample; // none: one ray through the pixel's centre
};

/// Traces pixel (x, y) of an image `height` rows high (y from the top) as `whitted render` computes it: from
/// stage 7 on (when settings has samples), sample `sample` (0 .. spp - 1, checked by the caller) where
/// pixel_color() traces it, with the pixel's value; before, one ray through the pixel's centre.
TracedPixel trace_pixel_tree(const Scene& scene, const RenderSettings& settings, int x, int y, int height, int sample);

/// The samples a pixel has at these settings: spp from stage 7 (lab 7) on, none before.
int traced_samples(const RenderSettings& settings);

/// "sphere (scenes/x.p3f:12)": the shape and the scene-file line that made it.
std::string object_name(const TraceContext& context, std::uint32_t primitive);

/// A secondary ray's direction next to the law it should follow.
struct DirectionCheck {
    std::string law;                 // "mirror law" or "Snell's law"
    double eta_i = 1.0, eta_t = 1.0; // Snell's law: the indices on the incoming and the far side
    double theta_i = 0.0;            // degrees between wo and the normal at the parent's hit
    double theta_out = 0.0;          // degrees between the traced ray and the normal (its side)
    std::optional<Vec3> expected;    // the direction the law gives; none: total internal reflection
    double theta_expected = 0.0;     // degrees between the expected direction and the normal (its side)
    double off_degrees = 0.0;        // angle between the traced and the expected direction
    bool agrees = false;             // within 0.01 degrees
};

/// The check of node `index` when it is a reflected or refracted ray.
std::optional<DirectionCheck> check_direction(const RayTree& tree, int index, const TraceContext& context);

/// A transparent hit from which the code cast no refracted ray.
struct MissingRefraction {
    double eta_i = 1.0, eta_t = 1.0; // the indices on the incoming and the far side
    double sin_theta_t = 0.0;        // what Snell's law gives; above 1: total internal reflection, as it should be
};

/// The check of node `index` when it hit a transparent surface (stage 5 on,
/// above the maximum depth) and none of its children is a refracted ray.
std::optional<MissingRefraction> check_missing_refraction(const RayTree& tree, int index, const TraceContext& context);

/// True when a blocked shadow feeler was stopped by the very surface it starts on (hits_its_own_surface()).
bool blocked_by_own_surface(const RayTree& tree, int index, const TraceContext& context);

/// The tree as indented text, with the checks, for the terminal.
std::string ray_tree_text(const RayTree& tree, const TraceContext& context);

/// The tree as nested JSON objects (one per ray, children inside).
nlohmann::json ray_tree_json(const RayTree& tree, const TraceContext& context);

/// Two panels: `eye_view` (the scene's view, possibly rendered larger than the
/// image traced) with the pixel ringed and the rays drawn over it, and the
/// shapes seen by `side_camera` (its normal pass, `side_normals`, drawn as
/// grey) with the same rays.
Image ray_tree_picture(const RayTree& tree, const TraceContext& context, const Image& eye_view,
                       const Image& side_normals, const Camera& side_camera);

/// A camera looking at the whole tree from the side (from the eye camera's right).
Camera side_camera_for(const RayTree& tree, const Camera& eye_camera, int width, int height);

} // namespace whitted
