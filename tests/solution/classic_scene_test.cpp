// The classic scene, rendered small, against a committed reference picture.
//
// The reference (tests/images/whitted_1980_96.png) was rendered by this
// framework's solution and checked by eye against Whitted's picture: hollow
// glass shell, mirror sphere, shadows, checkerboard. The comparison uses the
// image gate (image_compare.hpp): a pixel fails when a channel is off by more
// than 4/255; at most 0.5 % of pixels may fail and the mean error must stay
// below 1/255. That absorbs rounding differences between compilers and
// optimisation levels, and catches any change a viewer could see.
// Regenerate after an intended change with:
//   ./build/whitted render scenes/whitted_1980.p3f --width 96 --height 96 -o tests/images/whitted_1980_96.png
#include "whitted/image_compare.hpp"
#include "whitted/render.hpp"
#include "whitted/scene_loader.hpp"

#include <gtest/gtest.h>

using namespace whitted;

TEST(ClassicScene, MatchesTheCommittedReferenceWithinTheImageGate) {
    LoadedScene loaded = load_scene(WHITTED_SOURCE_DIR "/scenes/whitted_1980.p3f");
    EXPECT_TRUE(loaded.warnings.empty());
    loaded.data.camera = loaded.data.camera.with_resolution(96, 96);
    RenderSettings settings;
    settings.max_depth = loaded.data.max_depth;
    const Scene scene(std::move(loaded.data));
    const Image rendered = render(scene, settings, 2).image;
    const Image reference = read_image(WHITTED_SOURCE_DIR "/tests/images/whitted_1980_96.png");
    const ImageDifference difference = compare_images(reference, rendered);
    EXPECT_TRUE(difference.passed) << difference.summary();
}
