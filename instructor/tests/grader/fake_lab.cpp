// A stand-in for a grade_<lab> program: one test for each way a lab test can end.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <thread>

TEST(Fake, Passes) { EXPECT_EQ(2 + 2, 4); }

TEST(Fake, GivesAWrongAnswer) { EXPECT_EQ(2 + 2, 5) << "arithmetic is broken"; }

TEST(Fake, FailsEveryInput) { // 6 lines a failure, 3000 in all
    for (int input = 0; input < 500; ++input) EXPECT_EQ(input, -1) << "input " << input;
}

TEST(Fake, CallsAStub) { throw std::logic_error("labs/02_shadows.cpp:14: spawn_ray() is not implemented yet"); }

TEST(Fake, ThrowsSomethingElse) { throw std::runtime_error("the scene has no camera"); }

TEST(Fake, Segfaults) {
    volatile int* nowhere = nullptr;
    *nowhere = 1;
}

TEST(Fake, Loops) {
    volatile unsigned long counter = 0;
    for (;;) counter = counter + 1;
}

TEST(Fake, StubThrowsInAThread) {
    std::thread worker([] { throw std::logic_error("labs/05_refraction.cpp:20: refracted_direction() is not implemented yet"); });
    worker.join();
}

// Writes what instructor/link/checker_main.cpp writes when the worker dies while answering box_entry().
TEST(Fake, WorkerDiesDuringBoxEntry) {
    const char* report = std::getenv("WHITTED_LINK_REPORT");
    ASSERT_NE(report, nullptr);
    std::ofstream(report) << "the other side of the link closed it\nduring box_entry() (labs/10_bvh.cpp)\n";
    ADD_FAILURE() << "C++ exception with description \"the other side of the link closed it\" thrown in the test body.";
}

// Writes what tests/support/image_check.cpp writes for the grader: an image 2 % wrong.
TEST(FakeImage, IsTwoPercentOff) {
    const char* folder = std::getenv("WHITTED_TEST_OUTPUT");
    ASSERT_NE(folder, nullptr);
    std::ofstream(std::string(folder) + "/image.json")
        << R"({"passed": false, "failing_fraction": 0.02, "mean_error": 0.01, "max_error": 0.5, "worst_x": 3, "worst_y": 4, "psnr": 30.5, "non_finite_pixels": 0})";
    std::ofstream(std::string(folder) + "/reference.png") << "not really a png";
    ADD_FAILURE() << "the image differs";
}

TEST(HiddenFake, Passes) { SUCCEED(); }
