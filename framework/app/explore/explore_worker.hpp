// The programs `whitted explore` runs: the worker (`whitted render` and `whitted trace` with the student's labs)
// and, in a live build, `cmake --build` to rebuild it.
//
// Why: the labs run in a child process, never in the server. A lab that crashes or loops ends its child, not the
// page; the worker can be rebuilt while the page is served; and each picture and tree is exactly what the
// commands a student already knows would give. The worker writes its pictures and JSON to a scratch folder,
// read back here and then deleted.
#pragma once

#include "child_process.hpp"
#include "explore/live_build.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace whitted {

/// What one run of a program gave.
struct WorkerRun {
    ChildExit exit;
    std::string output;                 // what it printed, standard output and error together
    std::optional<std::string> png;     // the picture it wrote, if any
    std::optional<nlohmann::json> json; // the JSON it wrote, if any (render: --stats-json; trace: the tree)
    double seconds = 0.0;
};

/// One `whitted render` of the scene.
struct RenderJob {
    std::optional<int> stage;               // none: the highest whose labs are done, as render picks
    std::optional<std::pair<int, int>> size; // none: the scene's
    std::string pass;                        // "": the colour; else a --pass name
};

/// Asked every few milliseconds while a program runs; false stops it.
using KeepGoing = std::function<bool()>;

class ExploreWorker {
  public:
    /// Runs for `scene`, writing to `scratch` (which must exist), rendering with `threads`.
    ExploreWorker(std::string scene, std::filesystem::path scratch, int threads);

    /// `program render` (a whitted) of `job`, with its picture and its --stats-json.
    WorkerRun render(const std::filesystem::path& program, const RenderJob& job, const KeepGoing& keep_going) const;
    /// `program trace` of pixel (x, y) at `stage`, sample `sample` (none: the pixel's centre or sample 0), with its
    /// --json and --picture.
    WorkerRun trace(const std::filesystem::path& program, int x, int y, std::optional<int> sample, int stage,
                    const KeepGoing& keep_going) const;
    /// `cmake --build` of the live build's worker target, never stopped half-way (stopping cmake would leave its
    /// compilers running).
    WorkerRun build(const LiveBuild& build) const;

  private:
    WorkerRun run(std::vector<std::string> argv, const std::string& png, const std::string& json,
                  const KeepGoing& keep_going) const;

    std::string scene_;
    std::filesystem::path scratch_;
    int threads_;
    mutable std::atomic<int> runs_{0}; // numbers the scratch files of each run
};

/// A KeepGoing that says no once `seconds` have passed.
KeepGoing for_at_most(double seconds);

} // namespace whitted
