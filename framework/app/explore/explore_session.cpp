#include "explore/explore_session.hpp"

#include "exit_codes.hpp"
#include "explore/compiler_messages.hpp"
#include "explore/explore_server.hpp"
#include "image_options.hpp"
#include "whitted/image_compare.hpp"
#include "whitted/image_pictures.hpp"
#include "whitted/lab_table.hpp"
#include "whitted/passes.hpp"
#include "whitted/scene_loader.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>
#include <tuple>
#include <vector>

namespace whitted {
namespace {

// At most the last `lines` lines of a program's output, for the page.
std::string tail(const std::string& output, int lines = 60) {
    std::size_t start = output.size();
    while (start > 0 && lines >= 0)
        if (output[--start] == '\n') --lines;
    return output.substr(start == 0 ? 0 : start + 1);
}

// Why a run of the worker gave no picture or tree, for the page.
std::string failure_text(const WorkerRun& run, const std::string& doing) {
    if (run.exit.reason == "stopped") return doing + " was stopped";
    const std::string said = tail(run.output);
    if (run.exit.crashed) return "your labs crashed while " + doing + " (" + run.exit.reason + ")\n" + said;
    return said.empty() ? doing + " failed: " + run.exit.reason : said;
}

std::string tree_key(int x, int y, int sample) {
    return std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(sample);
}

} // namespace

// The lab files' (in a live build) and the scene's last write times and sizes: a save changes them.
struct ExploreSession::Snapshot {
    std::map<std::filesystem::path, std::pair<std::filesystem::file_time_type, std::uintmax_t>> files;
    bool operator==(const Snapshot&) const = default;

    static Snapshot of(const ExploreSettings& settings) {
        Snapshot snapshot;
        std::error_code error;
        auto add = [&](const std::filesystem::path& path) {
            const auto time = std::filesystem::last_write_time(path, error);
            const auto size = std::filesystem::file_size(path, error);
            snapshot.files[path] = {time, error ? 0 : size};
        };
        add(settings.scene);
        if (settings.live)
            for (const auto& entry : std::filesystem::directory_iterator(settings.live->labs_dir, error)) {
                const std::filesystem::path& path = entry.path();
                // Not an editor's hidden files (Emacs's lock file .#05_refraction.cpp): the student's saves only.
                const bool hidden = path.filename().string().starts_with(".");
                if (!hidden && (path.extension() == ".cpp" || path.extension() == ".hpp")) add(path);
            }
        return snapshot;
    }

    // The files that differ from `before`, for "labs/05_refraction.cpp saved".
    std::string changes_since(const Snapshot& before) const {
        std::string names;
        for (const auto& [path, stamp] : files) {
            const auto old = before.files.find(path);
            if (old == before.files.end() || old->second != stamp)
                names += (names.empty() ? "" : ", ") + path.filename().string();
        }
        return names.empty() ? "a file was removed" : names + " saved";
    }
};

ExploreSession::ExploreSession(ExploreSettings settings)
    : settings_(std::move(settings)), worker_(settings_.scene, settings_.scratch, settings_.threads) {
    // A live build's worker runs from a copy of each good build (build_worker); without one, the program given.
    if (settings_.live) add_library_folder(settings_.live->worker.parent_path());
    else program_ = settings_.worker;
    // A lab's scene (scenes/05_refraction.p3f) has its goal picture in the handout (docs/labs/images/).
    const std::filesystem::path scene(settings_.scene);
    for (const LabInfo& lab : kLabs) {
        if (scene.stem() != lab.stem) continue;
        const std::filesystem::path goal =
            scene.parent_path() / ".." / "docs" / "labs" / "images" / (std::string(lab.stem) + "_goal.png");
        try {
            goal_ = read_image(goal);
            goal_png_ = png_bytes(*goal_);
            goal_file_ = goal.lexically_normal().generic_string();
            goal_stage_ = lab.number;
        } catch (const std::exception&) { // no goal picture beside this scene: nothing to compare with
        }
    }
}

void ExploreSession::run(const std::atomic<bool>& stopping) {
    Snapshot seen = Snapshot::of(settings_);
    std::string why = "first render";
    for (;;) {
        const KeepGoing unchanged = [&] { return !stopping && Snapshot::of(settings_) == seen; };
        update(why, unchanged);
        // Until a save (or the end): a look every 200 ms.
        for (;;) {
            if (stopping) return;
            std::this_thread::sleep_for(std::chrono::milliseconds(200));
            Snapshot now = Snapshot::of(settings_);
            if (now == seen) continue;
            why = now.changes_since(seen);
            seen = std::move(now);
            ++saves_;
            break;
        }
    }
}

std::filesystem::path ExploreSession::program() const {
    const std::lock_guard lock(mutex_);
    return program_;
}

// A request's run: at most 120 s, and stopped by the next save (a lab that loops forever must not hold it).
KeepGoing ExploreSession::for_a_request() const {
    const KeepGoing in_time = for_at_most(120);
    const int saves = saves_;
    return [this, in_time, saves] { return in_time() && saves_ == saves; };
}

void ExploreSession::set_activity(const std::string& activity, const std::string& note) {
    const std::lock_guard lock(mutex_);
    activity_ = activity;
    activity_note_ = note;
    activity_start_ = std::chrono::steady_clock::now();
}

void ExploreSession::update(const std::string& why, const KeepGoing& keep_going) {
    if (!load_scene_facts()) return;
    if (settings_.live && !build_worker(why)) return;
    render_picture(keep_going);
}

// The scene's picture size; false (and the error on the page) when the scene does not load.
bool ExploreSession::load_scene_facts() {
    std::string error;
    int width = 0, height = 0;
    try {
        const LoadedScene loaded = load_scene(settings_.scene);
        std::tie(width, height) = output_size(loaded.data.camera, std::nullopt, std::nullopt);
        error = check_output_size(width, height);
    } catch (const std::exception& scene_error) {
        error = scene_error.what();
    }
    const std::lock_guard lock(mutex_);
    scene_error_ = error;
    if (!error.empty()) {
        activity_ = "idle";
        activity_note_ = "the scene does not load";
        return false;
    }
    width_ = width;
    height_ = height;
    return true;
}

// Rebuilds the worker; false (and the compiler's errors on the page) when it does not build.
bool ExploreSession::build_worker(const std::string& why) {
    set_activity("building", why + ": rebuilding " + settings_.live->worker_target);
    // Runs to its end (explore_worker.hpp says why): a save meanwhile builds again after it.
    const WorkerRun run = worker_.build(*settings_.live);
    bool built = run.exit.success();
    std::string copy_error;
    if (built) {
        // The new program runs from a copy of its own; the last one's copy goes (unless it still runs: Windows).
        const std::filesystem::path& worker = settings_.live->worker;
        const std::filesystem::path copy =
            settings_.scratch / ("worker-" + std::to_string(++builds_) + worker.extension().string());
        std::error_code error;
        std::filesystem::copy_file(worker, copy, std::filesystem::copy_options::overwrite_existing, error);
        if (error) {
            built = false;
            copy_error = "cannot copy " + worker.string() + " to " + copy.string() + ": " + error.message();
        } else {
            std::filesystem::path old;
            {
                const std::lock_guard lock(mutex_);
                old = std::exchange(program_, copy);
            }
            if (!old.empty()) std::filesystem::remove(old, error);
        }
    }
    const std::vector<CompilerError> errors = built ? std::vector<CompilerError>{} : build_errors(run.output);
    nlohmann::json shown = nlohmann::json::array();
    for (const CompilerError& error : errors)
        shown.push_back({{"file", error.file}, {"line", error.line}, {"column", error.column}, {"message", error.message}});
    const std::lock_guard lock(mutex_);
    build_ = {{"state", built ? "built" : "failed"}, {"why", why}, {"errors", shown},
              {"output", tail(run.output, 200) + copy_error},
              {"exit", run.exit.reason}, {"seconds", run.seconds}};
    if (!built) {
        activity_ = "idle";
        activity_note_ = "the build failed: the picture is the last one that built";
        const CompilerError first = errors.empty() ? CompilerError{"", 0, 0, copy_error} : errors.front();
        std::fprintf(stderr, "whitted explore: your labs do not build: %s%s%s\n", first.file.c_str(),
                     first.file.empty() ? "" : (":" + std::to_string(first.line) + ": ").c_str(), first.message.c_str());
    }
    return built;
}

// Renders the picture small, then whole; the page shows each as it comes.
void ExploreSession::render_picture(const KeepGoing& keep_going) {
    int width = 0, height = 0;
    {
        const std::lock_guard lock(mutex_);
        width = width_;
        height = height_;
    }
    const std::filesystem::path program = this->program();
    if (program.empty()) return; // nothing built yet
    struct Step {
        bool preview;
        std::optional<std::pair<int, int>> size;
    };
    std::vector<Step> steps;
    if (width * height >= 64 * 64) steps.push_back({true, std::pair{std::max(1, width / 4), std::max(1, height / 4)}});
    steps.push_back({false, std::nullopt});
    // A lab's scene is rendered at its lab's stage, as its goal picture is; when those labs are not all done,
    // at the highest stage whose labs are (as render picks), with render's list of what is missing.
    std::optional<int> stage = settings_.stage ? settings_.stage : goal_ ? std::optional(goal_stage_) : std::nullopt;
    std::string missing;
    for (const Step& step : steps) {
        set_activity("rendering", step.preview ? "a quarter-size picture first" : "the whole picture");
        WorkerRun run = worker_.render(program, RenderJob{stage, step.size, ""}, keep_going);
        if (!settings_.stage && stage && !run.exit.crashed && run.exit.code == exit_code::bad_input) {
            missing = tail(run.output);
            stage.reset();
            run = worker_.render(program, RenderJob{stage, step.size, ""}, keep_going);
        }
        if (run.exit.reason == "stopped" && !keep_going()) return; // a save came: the next render replaces it
        // Exit 1: a picture with NaN pixels, marked; shown with render's message.
        const bool drawn = run.png && (run.exit.success() || (!run.exit.crashed && run.exit.code == 1));
        const std::lock_guard lock(mutex_);
        render_ = {{"state", drawn ? (step.preview ? "preview" : "done") : "failed"}, {"seconds", run.seconds},
                   {"message", (missing.empty() ? "" : missing + "\n") + (drawn ? tail(run.output) : failure_text(run, "rendering"))}};
        activity_ = drawn && step.preview ? "rendering" : "idle";
        activity_note_ = drawn ? "" : "the render failed: the picture is the last one that rendered";
        if (!drawn) {
            const std::string said = render_["message"];
            std::fprintf(stderr, "whitted explore: the render failed: %s\n", said.substr(0, said.find('\n')).c_str());
            return;
        }
        png_ = std::move(*run.png);
        ++version_;
        preview_ = step.preview;
        stage_ = run.json ? run.json->value("stage", 0) : 0;
        render_["stage"] = stage_;
        views_.clear();
        difference_ = nullptr;
        if (step.preview || !goal_) continue;
        std::optional<Image> picture;
        try {
            picture = read_png_bytes(png_, "the picture");
        } catch (const std::exception&) { // not a whole PNG (a full disk): no difference
        }
        if (picture && goal_->width == picture->width && goal_->height == picture->height) {
            const ImageDifference d = compare_images(*goal_, *picture);
            const ImageGate gate;
            difference_ = {{"failing_pixels", d.failing_pixels}, {"pixels", d.pixel_count}, {"non_finite_pixels", d.non_finite_pixels},
                           {"failing_fraction", d.failing_fraction}, {"mean_error", d.mean_error}, {"max_error", d.max_error},
                           {"worst", {d.worst_x, d.worst_y}}, {"psnr", std::isfinite(d.psnr) ? nlohmann::json(d.psnr) : nlohmann::json(nullptr)},
                           {"passed", d.passed}, {"pixel_tolerance", gate.pixel_tolerance},
                           {"max_failing_fraction", gate.max_failing_fraction}, {"max_mean_error", gate.max_mean_error}};
            views_["difference"] = png_bytes(heat_picture(*goal_, *picture));
        }
    }
}

nlohmann::json ExploreSession::state() const {
    nlohmann::json passes = nlohmann::json::array();
    for (const PassInfo& pass : all_passes()) passes.push_back(pass.name);
    const std::lock_guard lock(mutex_);
    nlohmann::json state = {{"scene", settings_.scene}, {"width", width_}, {"height", height_},
                            {"activity", activity_}, {"note", activity_note_},
                            {"activity_seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - activity_start_).count()}, {"scene_error", scene_error_},
                            {"build", build_}, {"render", render_}, {"version", version_}, {"preview", preview_},
                            {"stage", stage_}, {"difference", difference_}, {"passes", passes}, {"live", nullptr},
                            {"goal", nullptr}};
    if (settings_.live)
        state["live"] = {{"labs", settings_.live->labs_dir.generic_string()}, {"target", settings_.live->worker_target}};
    if (goal_) state["goal"] = {{"file", goal_file_}, {"stage", goal_stage_}};
    return state;
}

std::string ExploreSession::picture(const std::string& view) {
    int stage = 0, version = 0;
    {
        const std::lock_guard lock(mutex_);
        if (view == "picture" && version_ > 0) return png_;
        if (view == "goal" && goal_) return goal_png_;
        if (const auto found = views_.find(view); found != views_.end()) return found->second;
        if (view == "picture") throw ExploreRequestError("no picture yet");
        if (view == "goal") throw ExploreRequestError("this scene has no goal picture (only a lab's scene has one)");
        if (view == "difference")
            throw ExploreRequestError(goal_ ? "no difference yet: it needs the whole picture" : "this scene has no goal picture to compare with");
        if (!find_pass(view)) throw ExploreRequestError("no view called '" + view.substr(0, 40) + "'");
        if (stage_ == 0) throw ExploreRequestError("no picture yet: the passes follow the picture's stage");
        stage = stage_;
        version = version_;
    }
    const WorkerRun run = worker_.render(program(), RenderJob{stage, std::nullopt, view}, for_a_request());
    if (!run.png || !run.exit.success()) throw ExploreRequestError(failure_text(run, "rendering the " + view + " pass"));
    const std::lock_guard lock(mutex_);
    if (version == version_) views_[view] = *run.png;
    return *run.png;
}

nlohmann::json ExploreSession::tree(int x, int y, int sample) {
    int stage = 0, version = 0;
    {
        const std::lock_guard lock(mutex_);
        if (stage_ == 0) throw ExploreRequestError("no picture yet: a tree is traced at the picture's stage");
        if (x < 0 || y < 0 || x >= width_ || y >= height_)
            throw ExploreRequestError("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                                      std::to_string(width_) + "x" + std::to_string(height_) + " picture");
        if (sample < 0) throw ExploreRequestError("sample " + std::to_string(sample) + ": samples are numbered from 0");
        stage = stage_;
        version = version_;
    }
    const WorkerRun run = worker_.trace(program(), x, y, sample > 0 ? std::optional(sample) : std::nullopt, stage, for_a_request());
    if (!run.json || !run.exit.success()) throw ExploreRequestError(failure_text(run, "tracing the pixel"));
    nlohmann::json tree = *run.json;
    tree["version"] = version; // the picture it belongs to
    const std::lock_guard lock(mutex_);
    if (trees_.size() > 100) trees_.clear();
    if (run.png) trees_[tree_key(x, y, sample)] = *run.png;
    return tree;
}

std::string ExploreSession::tree_picture(int x, int y, int sample) const {
    const std::lock_guard lock(mutex_);
    const auto found = trees_.find(tree_key(x, y, sample));
    if (found == trees_.end()) throw ExploreRequestError("no tree of that pixel and sample: click the pixel first");
    return found->second;
}

} // namespace whitted
