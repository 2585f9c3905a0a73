// The grader's pictures: the heat map's fixed scale and the gate numbers file.
#include "image_pictures.hpp"

#include "grader/test_report.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

using namespace whitted;
using namespace whitted::testing_helpers;

TEST(ImagePictures, HeatMapUsesTheFixedScale) {
    Image reference(4, 1, Color(0.5));
    Image test = reference;
    test.at(1, 0) = Color(0.5 + 4.0 / 255.0, 0.5, 0.5);   // at the tolerance: dark blue
    test.at(2, 0) = Color(0.5, 0.5 + 16.0 / 255.0, 0.5);  // 16 steps: yellow
    test.at(3, 0) = Color(std::numeric_limits<double>::quiet_NaN());
    const Image heat = heat_picture(reference, test);
    EXPECT_EQ(heat.at(0, 0), Color(0.0));
    EXPECT_EQ(heat.at(1, 0), Color(0.0, 0.0, 0.55));
    EXPECT_EQ(heat.at(2, 0), Color(1.0, 1.0, 0.0));
    EXPECT_EQ(heat.at(3, 0), Color(1.0, 0.0, 1.0));
}

TEST(ImagePictures, GateNumbersRoundTripThroughTheGrader) {
    Image reference(10, 10, Color(0.2));
    Image test = reference;
    test.at(7, 2) = Color(1.0);
    const ImageDifference difference = compare_images(reference, test);
    const std::filesystem::path file = std::filesystem::temp_directory_path() / ("image_numbers_" + std::to_string(getpid()) + ".json");
    write_gate_numbers(difference, "scenes/x.p3f", 3, file);
    const std::optional<grade::ImageNumbers> numbers = grade::read_image_numbers(file);
    std::filesystem::remove(file);
    ASSERT_TRUE(numbers.has_value());
    EXPECT_FALSE(numbers->passed); // 1 % of the pixels fail
    EXPECT_DOUBLE_EQ(numbers->failing_fraction, 0.01);
    EXPECT_EQ(numbers->worst_x, 7);
    EXPECT_EQ(numbers->worst_y, 2);
    ASSERT_TRUE(numbers->psnr.has_value());
    EXPECT_NEAR(*numbers->psnr, difference.psnr, 1e-6);
}

TEST(ImagePictures, DifferencePictureComparesTheValuesTheFilesHold) {
    // 0.5 and 0.5 + 0.1/255 are both written as 128: no difference. Three steps
    // apart, the picture shows 3 x 16 = 48 steps.
    const Image reference(3, 1, Color(0.5));
    Image test = reference;
    test.at(0, 0) = Color(0.5 + 0.1 / 255.0);
    test.at(1, 0) = Color(0.5, 0.5 + 3.0 / 255.0, 0.5);
    test.at(2, 0) = Color(std::numeric_limits<double>::infinity());
    const Image diff = difference_picture(test, reference);
    EXPECT_EQ(diff.at(0, 0), Color(0.0));
    EXPECT_EQ(diff.at(1, 0), Color(0.0, 48.0 / 255.0, 0.0));
    EXPECT_EQ(diff.at(2, 0), Color(1.0, 0.0, 1.0));
}
