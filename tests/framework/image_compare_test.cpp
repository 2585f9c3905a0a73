// The image gate: few slightly-off pixels pass; many wrong pixels, a uniform
// shift or a single NaN fail.
#include "whitted/image_compare.hpp"

#include <gtest/gtest.h>

#include <limits>

using namespace whitted;

namespace {

Image gradient(int width, int height) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) image.at(x, y) = Color(x / double(width), y / double(height), 0.5);
    return image;
}

} // namespace

TEST(ImageCompare, IdenticalImagesPassWithInfinitePsnr) {
    const Image a = gradient(40, 30);
    const ImageDifference d = compare_images(a, a);
    EXPECT_TRUE(d.passed);
    EXPECT_EQ(d.failing_pixels, 0u);
    EXPECT_EQ(d.psnr, kInfinity);
}

TEST(ImageCompare, AFewPixelsOffPassButAreCounted) {
    // 100 x 100 = 10,000 pixels; 2 % is 200. Ten fully wrong pixels: 0.1 % fail,
    // mean error 10 / 10,000 = 0.001 < 1/255.
    const Image a = gradient(100, 100);
    Image b = a;
    for (int i = 0; i < 10; ++i) b.at(i * 7, i * 3) = Color(1.0) - b.at(i * 7, i * 3);
    const ImageDifference d = compare_images(a, b);
    EXPECT_EQ(d.failing_pixels, 10u);
    EXPECT_TRUE(d.passed) << d.summary();
}

TEST(ImageCompare, OnePercentFullyWrongPixelsFailOnTheMeanError) {
    const Image a = gradient(100, 100);
    Image b = a;
    for (int i = 0; i < 100; ++i) b.at(i, (i * 37) % 100) = Color(1.0, 0.0, 1.0);
    const ImageDifference d = compare_images(a, b);
    EXPECT_FALSE(d.passed) << d.summary();
}

TEST(ImageCompare, ThreePercentSlightlyOffPixelsFailOnTheFraction) {
    // 300 of 10,000 pixels off by 6/255: 3 % > 2 % fail, while the mean error
    // 0.03 x 6/255 = 0.18/255 stays below 1/255.
    const Image a(100, 100, Color(0.5));
    Image b = a;
    for (int i = 0; i < 300; ++i) b.pixels[i * 33] = Color(0.5 + 6.0 / 255.0);
    const ImageDifference d = compare_images(a, b);
    EXPECT_EQ(d.failing_pixels, 300u);
    EXPECT_FALSE(d.passed) << d.summary();
    // 150 such pixels (1.5 %) pass.
    Image c = a;
    for (int i = 0; i < 150; ++i) c.pixels[i * 66] = Color(0.5 + 6.0 / 255.0);
    EXPECT_TRUE(compare_images(a, c).passed);
}

TEST(ImageCompare, AUniformTwoStepShiftFailsOnTheMeanError) {
    // Every pixel 2/255 darker: no pixel exceeds the 4/255 tolerance, but the mean does exceed 1/255.
    const Image a(50, 50, Color(0.5));
    const Image b(50, 50, Color(0.5 - 2.0 / 255.0));
    const ImageDifference d = compare_images(a, b);
    EXPECT_EQ(d.failing_pixels, 0u);
    EXPECT_NEAR(d.mean_error, 2.0 / 255.0, 1e-12);
    EXPECT_FALSE(d.passed);
}

TEST(ImageCompare, ASingleNanPixelFails) {
    const Image a = gradient(64, 64);
    Image b = a;
    b.at(5, 6).y = std::numeric_limits<double>::quiet_NaN();
    const ImageDifference d = compare_images(a, b);
    EXPECT_EQ(d.non_finite_pixels, 1u);
    EXPECT_EQ(d.worst_x, 5);
    EXPECT_EQ(d.worst_y, 6);
    EXPECT_FALSE(d.passed);
}

TEST(ImageCompare, DifferentSizesFail) {
    const ImageDifference d = compare_images(gradient(10, 10), gradient(10, 11));
    EXPECT_FALSE(d.same_size);
    EXPECT_FALSE(d.passed);
}

TEST(ImageCompare, ValuesAboveOneCompareAsWrittenClamped) {
    // Both write as 255: the gate judges the files, not the unclamped floats.
    const ImageDifference d = compare_images(Image(4, 4, Color(1.5)), Image(4, 4, Color(3.0)));
    EXPECT_TRUE(d.passed);
    EXPECT_EQ(d.max_error, 0.0);
}
