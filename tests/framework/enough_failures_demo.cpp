// A test that fails on purpose, for tests/CMakeLists.txt to read its output:
// a loop over 100 inputs that all fail stops after five failures, with one line
// saying so (enough_failures() in lab_helpers.hpp), not after a hundred.
#include "lab_helpers.hpp"

#include <gtest/gtest.h>

using whitted::testing_helpers::enough_failures;

TEST(EnoughFailures, ALoopOverManyFailingInputsStopsAfterFive) {
    for (int input = 0; input < 100; ++input) {
        EXPECT_EQ(input, -1) << "input " << input;
        if (enough_failures()) return;
    }
}
