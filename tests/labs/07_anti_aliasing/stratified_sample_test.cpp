// Lab 7, stratified_sample(): where each sample of a pixel goes. The pixel is
// cut into a cols x rows grid as square as the count allows; sample k lies in
// cell k (row by row from the bottom left), at the place u within the cell.
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace whitted;
using namespace whitted::testing_helpers;

TEST(StratifiedSample, FourSamplesWithUAtOneHalfAreTheCentresOfTheQuarters) {
    // 2 x 2 cells; u = (0.5, 0.5) is the middle of each: (col + 0.5) / 2, (row + 0.5) / 2.
    const Vec2 half(0.5, 0.5);
    expect_vec2(stratified_sample(0, 4, half), 0.25, 0.25, "sample 0 (bottom left)");
    expect_vec2(stratified_sample(1, 4, half), 0.75, 0.25, "sample 1 (bottom right)");
    expect_vec2(stratified_sample(2, 4, half), 0.25, 0.75, "sample 2 (top left)");
    expect_vec2(stratified_sample(3, 4, half), 0.75, 0.75, "sample 3 (top right)");
}

TEST(StratifiedSample, UPlacesTheSampleWithinItsCell) {
    // 3 x 3 cells of side 1/3: sample 5 is column 2, row 1; u = (0.25, 0.75) puts it at
    // ((2 + 0.25) / 3, (1 + 0.75) / 3) = (0.75, 0.583333...).
    expect_vec2(stratified_sample(5, 9, Vec2(0.25, 0.75)), 0.75, 1.75 / 3.0, "sample 5 of 9");
    // u = (0, 0) is the cell's bottom-left corner.
    expect_vec2(stratified_sample(4, 9, Vec2(0.0, 0.0)), 1.0 / 3.0, 1.0 / 3.0, "sample 4 of 9 at u = 0");
}

TEST(StratifiedSample, ACountThatIsNotASquareUsesTheSquarestGrid) {
    // 8 = 4 x 2: sample 5 is column 1, row 1 -> ((1 + 0.5) / 4, (1 + 0.5) / 2).
    expect_vec2(stratified_sample(5, 8, Vec2(0.5, 0.5)), 0.375, 0.75, "sample 5 of 8 (4 x 2)");
    // 6 = 3 x 2: sample 4 is column 1, row 1.
    expect_vec2(stratified_sample(4, 6, Vec2(0.5, 0.5)), 0.5, 0.75, "sample 4 of 6 (3 x 2)");
    // 12 = 4 x 3: sample 11 is column 3, row 2.
    expect_vec2(stratified_sample(11, 12, Vec2(0.0, 0.0)), 0.75, 2.0 / 3.0, "sample 11 of 12 (4 x 3)");
    // 5 is prime: 5 x 1, five columns the height of the pixel.
    expect_vec2(stratified_sample(3, 5, Vec2(0.5, 0.5)), 0.7, 0.5, "sample 3 of 5 (5 x 1)");
    expect_vec2(stratified_sample(1, 2, Vec2(0.5, 0.25)), 0.75, 0.25, "sample 1 of 2 (2 x 1)");
}

TEST(StratifiedSample, OneSampleIsAnywhereInThePixel) {
    // One sample: a grid of one cell, the whole pixel, so the place is u itself.
    expect_vec2(stratified_sample(0, 1, Vec2(0.3, 0.8)), 0.3, 0.8, "the only sample");
    // Two samples: 2 x 1 cells, each half the pixel wide: the same u puts sample 0 at (0.3 / 2, 0.8)
    // and sample 1 at ((1 + 0.3) / 2, 0.8).
    expect_vec2(stratified_sample(0, 2, Vec2(0.3, 0.8)), 0.15, 0.8, "sample 0 of 2");
    expect_vec2(stratified_sample(1, 2, Vec2(0.3, 0.8)), 0.65, 0.8, "sample 1 of 2");
}

TEST(StratifiedSample, EverySampleLiesInItsOwnCellOfThePixel) {
    const Vec2 places[] = {{0.0, 0.0}, {0.999999, 0.999999}, {0.5, 0.1}, {0.123, 0.987}};
    for (int count = 1; count <= 36; ++count) {
        const SampleGrid grid = sample_grid(count);
        for (int k = 0; k < count; ++k) {
            for (const Vec2& u : places) {
                const Vec2 p = stratified_sample(k, count, u);
                ASSERT_TRUE(p.x >= 0.0 && p.x < 1.0 && p.y >= 0.0 && p.y < 1.0)
                    << "sample " << k << " of " << count << " is outside the pixel: (" << p.x << ", " << p.y << ")";
                // Cell k is column k % cols, row k / cols: [col / cols, (col + 1) / cols) across
                // (a rounding error of the division aside), and the same upwards.
                const int col = k % grid.cols, row = k / grid.cols;
                const bool in_column = p.x >= double(col) / grid.cols - 1e-12 && p.x < double(col + 1) / grid.cols + 1e-12;
                const bool in_row = p.y >= double(row) / grid.rows - 1e-12 && p.y < double(row + 1) / grid.rows + 1e-12;
                ASSERT_TRUE(in_column && in_row)
                    << "sample " << k << " of " << count << " (a " << grid.cols << " x " << grid.rows
                    << " grid) should be in cell (" << col << ", " << row << ") but is at (" << p.x << ", " << p.y << ")";
            }
        }
    }
}
