// Image tests: render a scene with the linked labs and compare it with a
// committed reference picture through the image gate (image_compare.hpp).
//
// On failure the test writes four pictures next to each other in
// <build>/test-output/<test name>/: yours.png, reference.png, diff.png (the
// absolute difference, 16 times brighter) and heat.png (the error on a fixed
// colour scale, image_pictures.hpp), and says where they are.
// With WHITTED_TEST_OUTPUT=<folder> in the environment (`whitted grade` sets
// it for each test) the pictures go to that folder instead, pass or fail, with
// image.json holding the gate's numbers; reference.png is copied there before
// rendering, so it is there even when the render throws or crashes. With
// WHITTED_REFERENCE_ONLY=1 as well, the test stops there (skipped): the grader
// shows the reference picture of an image test it does not run.
// With WHITTED_TOGETHER=1 (the grader's first run of all of a lab's tests in
// one program) the test fails at once: the grader runs it again on its own.
// With WHITTED_UPDATE_REFERENCES=1 in the environment the test writes the
// reference instead (`make references`, instructors only: it must be run with
// the reference solution linked).
#pragma once

#include "whitted/lab_table.hpp"

#include <string>

namespace whitted::testing_helpers {

struct ImageCheck {
    std::string scene;     // path relative to the source tree, e.g. "scenes/03_blinn_phong.p3f"
    std::string reference; // path relative to the source tree, e.g. "tests/labs/03_blinn_phong/03_blinn_phong.png"
    int stage = kLabCount; // render with the features of labs 1..stage
    int width = 160;       // the scene file's aspect ratio is replaced by width x height
    int height = 120;
};

/// Renders the scene and expects it to pass the image gate against the reference (GoogleTest assertion).
void expect_matches_reference(const ImageCheck& check);

} // namespace whitted::testing_helpers
