// Degenerate geometry, extreme cameras and huge depths: the reference renderer
// finishes, writes no NaN or infinite pixel, and its fast leaf kernels agree
// bit for bit with the labs' intersection code. Each scene is one the loader
// accepts; what it refuses (a polygon without area, a zero radius, from == at)
// is in tests/bad_scenes/.
#include "whitted/engine/leaf_kernels.hpp"
#include "whitted/render.hpp"
#include "whitted/scene_loader.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

using namespace whitted;

namespace {

// A viewpoint looking at the origin from +z, then the body.
std::string nff(const std::string& body, const std::string& camera = "from 0 1 6\nat 0 1 0\nup 0 1 0\nangle 45\n") {
    return "v\n" + camera + "hither 0.01\nresolution 24 18\n" + body;
}

// Lights and the materials used below: a plain red one, a mirror, and glass.
const std::string kLights = "l 3 6 5\nl -4 2 3 0.5 0.5 0.5\nb 0.2 0.3 0.5\n";
const std::string kRed = "f 1 0 0 0.7 0.3 20 0 1\n";
const std::string kMirror = "f 0.2 0.2 0.2 0.1 0.9 50 0 1\n";
const std::string kGlass = "f 1 1 1 0 0.1 200 0.9 1.5\n";

RenderResult render_with(const SceneData& data, const LeafKernels* kernels, const RenderSettings& settings) {
    return render(Scene(SceneData(data), kernels), settings, 2);
}

// Renders the NFF text both ways and checks the three promises.
void expect_finite_and_alike(const std::string& text, RenderSettings settings = {}) {
    const LoadedScene loaded = parse_scene(text, Dialect::nff, "degenerate.nff");
    settings.max_depth = loaded.data.max_depth;
    const RenderResult labs = render_with(loaded.data, nullptr, settings);
    EXPECT_EQ(count_non_finite(labs.image), 0u);
    const RenderResult fast = render_with(loaded.data, linked_leaf_kernels(), settings);
    ASSERT_EQ(fast.image.pixels.size(), labs.image.pixels.size());
    EXPECT_EQ(std::memcmp(fast.image.pixels.data(), labs.image.pixels.data(), labs.image.pixels.size() * sizeof(Color)), 0)
        << "the fast leaf kernels and the labs' code disagree";
}

} // namespace

TEST(DegenerateScenes, SliverTrianglesWithTinyAreaRender) {
    // Slivers just thick enough for the loader (thinner ones are refused as having no area):
    // height 1e-6 over a base of 4, and one tilted by 1e-7 out of its plane.
    expect_finite_and_alike(nff(kLights + kRed + "p 3\n-2 0 0\n2 0 0\n0 1e-6 0\n" + "p 3\n-2 1 0\n2 1 1e-7\n0 1.000001 0\n"));
}

TEST(DegenerateScenes, VanishingVertexNormalsRender) {
    // pp normals of length 1e-300 (accepted: not zero) and of mixed directions that cancel at the centre.
    expect_finite_and_alike(nff(kLights + kRed + "pp 3\n-1 0 0 0 0 1e-300\n1 0 0 0 0 1e-300\n0 2 0 0 0 1e-300\n" +
                                "pp 3\n-1 0 -1 1 0 1\n1 0 -1 -1 0 1\n0 2 -1 0 -1 0.0001\n"));
}

TEST(DegenerateScenes, CoincidentSurfacesRender) {
    // The same sphere twice with different materials, a triangle lying on a plane-like
    // polygon, and two identical mirror triangles facing each other's copy.
    expect_finite_and_alike(nff(kLights + kRed + "s 0 1 0 1\n" + kMirror + "s 0 1 0 1\n" +
                                "p 4\n-3 0 -3\n3 0 -3\n3 0 3\n-3 0 3\n" + kRed + "p 3\n-1 0 -1\n1 0 -1\n0 0 1\n" + kMirror +
                                "p 3\n-2 0 -2\n2 0 -2\n0 3 -2\n" + "p 3\n-2 0 -2\n2 0 -2\n0 3 -2\n"));
}

TEST(DegenerateScenes, TinyAndHugeSpheresRender) {
    expect_finite_and_alike(nff(kLights + kGlass + "s 0 1 0 1e-12\n" + kRed + "s 0 -1e12 0 1e12\n" + kMirror + "s 1e14 0 -1e14 1e13\n"));
}

TEST(DegenerateScenes, EyeInsideGlassAndOnASurfaceRenders) {
    expect_finite_and_alike(nff(kLights + kGlass + "s 0 1 6 0.5\n" + kRed + "p 4\n-9 1 -9\n9 1 -9\n9 1 9\n-9 1 9\n"));
}

TEST(DegenerateScenes, LightsOnAndInsideSurfacesRender) {
    expect_finite_and_alike(nff("l 0 1 1\nl 0 0 0\n" + kRed + "s 0 1 0 1\np 4\n-3 0 -3\n3 0 -3\n3 0 3\n-3 0 3\n"));
}

TEST(DegenerateScenes, ExtremeFieldsOfViewRender) {
    const std::string body = kLights + kMirror + "s 0 1 0 1\n" + kRed + "p 4\n-3 0 -3\n3 0 -3\n3 0 3\n-3 0 3\n";
    expect_finite_and_alike(nff(body, "from 0 1 6\nat 0 1 0\nup 0 1 0\nangle 0.000001\n"));
    expect_finite_and_alike(nff(body, "from 0 1 6\nat 0 1 0\nup 0 1 0\nangle 179.99999\n"));
}

TEST(DegenerateScenes, FarAwayEyeAndNearlyParallelUpRender) {
    const std::string body = kLights + kRed + "s 0 1 0 1\n";
    expect_finite_and_alike(nff(body, "from 0 1 1e15\nat 0 1 0\nup 0 1 0\nangle 1e-9\n"));
    // up 1e-8 radians away from the view direction: accepted, and the frame stays finite.
    expect_finite_and_alike(nff(body, "from 0 1 6\nat 0 1 0\nup 0 1e-8 -1\nangle 45\n"));
}

TEST(DegenerateScenes, HugeDepthInAHallOfMirrorsEnds) {
    // Two facing mirrors with a glass sphere between them: at depth 100 with no
    // adaptive cut-off the ray tree would have 2^100 rays; the per-pixel ray cap ends it.
    RenderSettings settings;
    settings.min_weight = 0.0;
    expect_finite_and_alike(nff("maxdepth 100\n" + kLights + "f 1 1 1 0 1 1 0 1\n" + "p 4\n-5 -5 -3\n5 -5 -3\n5 5 -3\n-5 5 -3\n" +
                                    "p 4\n-5 -5 9\n-5 5 9\n5 5 9\n5 -5 9\n" + kGlass + "s 0 1 0 1\ns 0 1 0 -0.9\n"),
                            settings);
}
