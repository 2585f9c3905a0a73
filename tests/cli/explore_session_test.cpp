// What `whitted explore` shows (framework/app/explore/explore_session.hpp), with this build's `whitted` as its
// worker, on lab 5's scene: the picture is the one `whitted render` writes, the passes and the trees are
// whitted's, the difference from lab 5's goal picture passes with correct labs, and a request it cannot answer
// says why. No web server: the page's requests are the session's functions.
#include "child_process.hpp"
#include "explore/explore_server.hpp"
#include "explore/explore_session.hpp"
#include "whitted/image.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <random>
#include <thread>

using namespace whitted;

namespace {

const std::string kScene = WHITTED_SCENES_DIR "/05_refraction.p3f";

// A scratch folder of the test's own, removed at its end (whether it passed or not).
struct ScratchFolder {
    std::filesystem::path path;
    ScratchFolder() {
        std::random_device random;
        path = std::filesystem::temp_directory_path() / ("whitted-session-test-" + std::to_string(random()));
        std::filesystem::create_directories(path);
    }
    ~ScratchFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
};

// The session running in a thread until the test ends.
class RunningSession {
  public:
    explicit RunningSession(ExploreSettings settings) : session_(std::move(settings)), thread_([this] { session_.run(stopping_); }) {}
    ~RunningSession() {
        stopping_ = true;
        thread_.join();
    }
    ExploreSession& operator*() { return session_; }
    ExploreSession* operator->() { return &session_; }

    // The state once the first whole render has ended (done or failed), or after 120 s.
    nlohmann::json rendered() {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
        for (;;) {
            nlohmann::json state = session_.state();
            const std::string render = state["render"].is_object() ? state["render"].value("state", "") : "";
            if ((render == "done" || render == "failed") && state["activity"] == "idle") return state;
            if (std::chrono::steady_clock::now() > deadline) return state;
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
    }

  private:
    std::atomic<bool> stopping_{false};
    ExploreSession session_;
    std::thread thread_;
};

ExploreSettings settings_for(std::filesystem::path worker, const std::filesystem::path& scratch) {
    return ExploreSettings{kScene, std::nullopt, 2, std::move(worker), std::nullopt, scratch};
}

} // namespace

TEST(ExploreSession, ShowsWhatWhittedRenderWritesAndItsPassesTreesAndDifference) {
    const ScratchFolder folder;
    const std::filesystem::path& scratch = folder.path;
    RunningSession session(settings_for(WHITTED_PROGRAM, scratch));
    const nlohmann::json state = session.rendered();
    ASSERT_EQ(state["render"].value("state", ""), "done") << state["render"].value("message", "") << "\n" << state.dump(1);
    // A lab's scene at its lab's stage, as its goal picture.
    EXPECT_EQ(state["stage"], 5);
    EXPECT_EQ(state["goal"]["stage"], 5);
    EXPECT_EQ(state["width"], 320);
    EXPECT_EQ(state["preview"], false);

    // The picture shown is the one `whitted render --stage 5` writes, pixel for pixel.
    const std::filesystem::path written = scratch / "render.png";
    const ChildExit render = run_child({WHITTED_PROGRAM, "render", kScene, "--stage", "5", "--quiet", "-o", written.string()},
                                       scratch / "render.txt");
    ASSERT_TRUE(render.success()) << render.reason;
    const Image shown = read_png_bytes(session->picture("picture"), "the picture shown");
    const Image expected = read_image(written);
    ASSERT_EQ(shown.width, expected.width);
    ASSERT_EQ(shown.height, expected.height);
    EXPECT_TRUE(shown.pixels == expected.pixels) << "the picture shown is not whitted render's";

    // Correct labs match lab 5's goal; the heat map is there.
    ASSERT_TRUE(state["difference"].is_object()) << state.dump(1);
    EXPECT_TRUE(state["difference"]["passed"].get<bool>()) << state["difference"].dump(1);
    EXPECT_EQ(read_png_bytes(session->picture("difference"), "the heat map").width, 320);
    EXPECT_EQ(read_png_bytes(session->picture("goal"), "the goal").width, 320);

    // A pass: a picture of the scene's size.
    EXPECT_EQ(read_png_bytes(session->picture("normal"), "the normal pass").height, 240);

    // A pixel's tree at the picture's stage, and the picture of its rays (two panels side by side).
    const nlohmann::json tree = session->tree(110, 125, 0);
    EXPECT_EQ(tree["stage"], 5);
    EXPECT_EQ(tree["pixel"], (nlohmann::json{110, 125}));
    EXPECT_EQ(tree["ray"]["kind"], "eye");
    EXPECT_GT(read_png_bytes(session->tree_picture(110, 125, 0), "the rays").width, 320);
}

TEST(ExploreSession, ARequestItCannotAnswerSaysWhy) {
    const ScratchFolder folder;
    const std::filesystem::path& scratch = folder.path;
    RunningSession session(settings_for(WHITTED_PROGRAM, scratch));
    const nlohmann::json state = session.rendered();
    ASSERT_EQ(state["render"].value("state", ""), "done") << state["render"].value("message", "");
    const auto message_of = [](const auto& request) {
        try {
            request();
        } catch (const ExploreRequestError& error) {
            return std::string(error.what());
        }
        return std::string("(no error)");
    };
    EXPECT_EQ(message_of([&] { session->tree(320, 0, 0); }), "pixel (320, 0) is outside the 320x240 picture");
    EXPECT_EQ(message_of([&] { session->tree(0, -1, 0); }), "pixel (0, -1) is outside the 320x240 picture");
    // Stage 5 has no samples: whitted trace says so, and the page shows it.
    EXPECT_NE(message_of([&] { session->tree(1, 1, 3); }).find("--sample 3"), std::string::npos);
    EXPECT_EQ(message_of([&] { session->picture("nothing"); }), "no view called 'nothing'");
    EXPECT_EQ(message_of([&] { session->tree_picture(5, 5, 0); }), "no tree of that pixel and sample: click the pixel first");
}

TEST(ExploreSession, AWorkerThatCannotRunIsAFailedRenderNotAFailedSession) {
    const ScratchFolder folder;
    const std::filesystem::path& scratch = folder.path;
    RunningSession session(settings_for(scratch / "no-such-whitted", scratch));
    const nlohmann::json state = session.rendered();
    EXPECT_EQ(state["render"].value("state", ""), "failed");
    EXPECT_NE(state["render"].value("message", "").find("no-such-whitted"), std::string::npos) << state.dump(1);
    EXPECT_EQ(state["version"], 0); // no picture
}

#if defined(WHITTED_CRASHING_PROGRAM) && !defined(_WIN32)
// A lab that crashes ends its render, not the session: the page says where (whitted's crash report, exit 3) and
// the terminal too, and the session goes on answering. (The instructor's tree: whitted-crashing is the reference
// but for lab 10, whose bvh_closest_hit() crashes as WHITTED_TEST_CRASH says.)
TEST(ExploreSession, ALabThatCrashesIsAFailedRenderWithTheCrashReport) {
    const ScratchFolder folder;
    setenv("WHITTED_TEST_CRASH", "segfault", 1); // inherited by the worker
    // Under the sanitizers, the worker's crash is the real signal, reported by whitted (as add_crash_test sets it).
    const char* sanitizer_options = std::getenv("ASAN_OPTIONS");
    const std::string kept = sanitizer_options ? sanitizer_options : "";
    setenv("ASAN_OPTIONS", "handle_segv=0:handle_sigfpe=0:handle_sigbus=0:handle_abort=0:detect_leaks=0", 1);
    ::testing::internal::CaptureStderr();
    std::string said;
    {
        RunningSession session(
            ExploreSettings{WHITTED_SCENES_DIR "/10_bvh.p3f", std::nullopt, 2, WHITTED_CRASHING_PROGRAM, std::nullopt, folder.path});
        const nlohmann::json state = session.rendered();
        said = ::testing::internal::GetCapturedStderr();
        EXPECT_EQ(state["render"].value("state", ""), "failed") << state.dump(1);
        EXPECT_NE(state["render"].value("message", "").find("crashed in bvh_closest_hit()"), std::string::npos) << state.dump(1);
        EXPECT_EQ(state["version"], 0);
        EXPECT_EQ(session->state()["scene"], WHITTED_SCENES_DIR "/10_bvh.p3f"); // still answering
    }
    unsetenv("WHITTED_TEST_CRASH");
    if (sanitizer_options) setenv("ASAN_OPTIONS", kept.c_str(), 1);
    else unsetenv("ASAN_OPTIONS");
    EXPECT_NE(said.find("whitted explore: the render failed: whitted: crashed in bvh_closest_hit()"), std::string::npos) << said;
}
#endif
