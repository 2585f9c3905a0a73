// What `whitted explore` shows, kept up to date: it renders the scene with the worker (explore_worker.hpp),
// first small and then whole, watches the lab files and the scene, and on a save rebuilds (in a live build)
// and renders again. The page asks for its state, its pictures and its trees (explore_server.hpp).
//
// Why: one place holds what the page shows, so that a request never waits for a render or a build and always
// gets the last good picture, with the build's errors or the render's failure beside it. Each build that
// succeeds is copied to the scratch folder and the copy runs: a build that fails keeps the last good program,
// and a build never waits for a running one (nor fails on Windows to rewrite a program that runs).
#pragma once

#include "explore/explore_worker.hpp"
#include "explore/live_build.hpp"
#include "whitted/image.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <string>

namespace whitted {

struct ExploreSettings {
    std::string scene;               // the scene file
    std::optional<int> stage;        // --stage; none: the highest whose labs are done, as render picks
    int threads = 0;                 // for the worker's renders; 0: one per core
    std::filesystem::path worker;    // without a live build, the program that renders (this one)
    std::optional<LiveBuild> live;   // rebuild the worker when a lab file is saved
    std::filesystem::path scratch;   // an existing folder for the worker's files
};

class ExploreSession {
  public:
    explicit ExploreSession(ExploreSettings settings);

    /// Builds (live) and renders, then again after each save of a lab file or the scene, until `stopping`.
    void run(const std::atomic<bool>& stopping);

    /// What the page shows besides pictures: the activity, the build's errors, the render's message, the
    /// difference from the goal (GET /state).
    nlohmann::json state() const;
    /// A picture as PNG: "picture" (the latest render), "goal", "difference" (the heat map) or a pass name.
    /// Throws ExploreRequestError when there is none.
    std::string picture(const std::string& view);
    /// Pixel (x, y)'s ray tree at the stage of the picture shown (whitted trace --json).
    nlohmann::json tree(int x, int y, int sample);
    /// The picture of the last tree() of (x, y, sample): its rays over the scene and from the side.
    std::string tree_picture(int x, int y, int sample) const;

  private:
    struct Snapshot; // the lab files' and the scene's times and sizes
    void update(const std::string& why, const KeepGoing& keep_going);
    bool load_scene_facts();
    bool build_worker(const std::string& why);
    void render_picture(const KeepGoing& keep_going);
    void set_activity(const std::string& activity, const std::string& note);
    std::filesystem::path program() const;
    KeepGoing for_a_request() const;

    ExploreSettings settings_;
    ExploreWorker worker_;
    std::atomic<int> saves_{0}; // counts the saves seen: a request's run stops at the next one
    int builds_ = 0;            // counts the builds that succeeded (the run loop's own)

    mutable std::mutex mutex_; // guards everything below
    std::filesystem::path program_;    // the worker that runs: this program, or a copy of the last good build
    std::string activity_ = "starting", activity_note_;
    std::chrono::steady_clock::time_point activity_start_ = std::chrono::steady_clock::now();
    int width_ = 0, height_ = 0;       // the scene's picture size
    std::string scene_error_;          // the scene does not load: file:line: why
    nlohmann::json build_;             // the last build: state, errors, output, seconds (null: not live)
    nlohmann::json render_;            // the last render: state, message, seconds, stage
    std::string png_;                  // the picture shown (the last good one)
    int version_ = 0;                  // counts the pictures shown
    bool preview_ = false;             // png_ is the small first render
    int stage_ = 0;                    // the stage png_ was rendered at (0: no picture yet)
    std::optional<Image> goal_;        // a lab's scene: the lab's goal picture
    std::string goal_png_, goal_file_;
    int goal_stage_ = 0;
    nlohmann::json difference_;        // the gate's numbers against the goal (null: none)
    std::map<std::string, std::string> views_; // the difference and the passes of the picture shown
    std::map<std::string, std::string> trees_; // tree pictures, by "x y sample"
};

} // namespace whitted
