// The ray tree of one pixel: every ray the tracer cast for it, with what each
// ray hit and what it added to the colour.
//
// Why: the hardest bugs of a ray tracer live inside the recursion. A refracted
// ray bent the wrong way or a shadow feeler that hits its own surface changes
// a pixel in ways the final picture cannot explain. A `Tracer` given a RayTree
// writes every ray down as it goes (Whitted's own picture of the algorithm is
// this tree), and `whitted trace` and the diagnostic passes (`--pass`) read it.
// Ordinary renders give no tree and pay nothing for it.
#pragma once

#include "whitted/hit.hpp"
#include "whitted/interval.hpp"

#include <optional>
#include <vector>

namespace whitted {

/// What became of a ray the labs asked the tracer to cast.
enum class RayFate {
    traced,            // cast into the scene
    below_min_weight,  // not cast: its weight from the eye is below RenderSettings::min_weight
    over_budget,       // not cast: the pixel had already cast RenderSettings::max_rays_per_pixel rays
};

struct RayNode {
    RayKind kind = RayKind::eye;
    int depth = 1;               // the eye ray is 1; a shadow feeler has the depth of the ray whose hit casts it
    int parent = -1;             // index in RayTree::nodes (-1 for the eye ray)
    std::vector<int> children;   // in the order they were cast: shadow feelers, then reflected and refracted rays
    Ray ray;
    Interval t_range;            // the hits the ray asks about (a feeler's stops just short of the light)
    Color weight{1.0};           // the coefficient given to trace() (Ks, T, Kr...); 1 for eye rays and feelers
    Color path_weight{1.0};      // product of the weights from the eye down to this ray
    RayFate fate = RayFate::traced;

    // Eye, reflected and refracted rays.
    std::optional<Hit> hit;      // the closest hit; none: the ray sees the background
    std::optional<Color> local;  // the local colour at the hit (flat, Lambert or Blinn-Phong, by stage)
    std::optional<Color> reflection; // what reflection() returned, when it was called
    std::optional<Color> refraction; // what refraction() returned, when it was called
    std::optional<Color> fresnel;    // what fresnel_blend() returned, when it was called
    Color color{0.0};            // what trace() returned: weight × the colour seen along the ray

    // Shadow feelers (kind == RayKind::shadow).
    double light_distance = 0.0; // the feeler asks about 0 < t < light_distance
    bool blocked = false;        // the answer of occluded(); `hit` then holds the nearest blocker
};

struct RayTree {
    std::vector<RayNode> nodes; // nodes[0] is the eye ray, once a pixel has been traced

    /// Forgets the previous pixel's rays.
    void clear() { nodes.clear(); }
};

class Scene;

/// True when `feeler`, a shadow feeler cast from the hit `start`, was blocked
/// by the very surface it starts from: shadow acne (lab 2), not a shadow.
bool hits_its_own_surface(const Scene& scene, const Hit& start, const RayNode& feeler);

} // namespace whitted
