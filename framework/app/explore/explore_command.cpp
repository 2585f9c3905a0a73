// `whitted explore SCENE [--stage K] [--port N]`: the scene rendered with the student's labs, on a page
// served on this machine only, where a click on a pixel shows its ray tree.
#include "commands.hpp"
#include "exit_codes.hpp"
#include "child_process.hpp"
#include "explore/explore_page.hpp"
#include "explore/explore_server.hpp"
#include "explore/explore_session.hpp"
#include "explore/live_build.hpp"
#include "image_options.hpp"
#include "stage_choice.hpp"
#include "whitted/scene_loader.hpp"

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace whitted {
namespace {

struct ExploreOptions {
    std::string scene;
    std::optional<int> stage;
    int port = 0;
    int threads = 0;
    bool no_rebuild = false;
    bool from_copy = false; // this program is the copy that serves (Windows: serve_from_copy)
};

// A folder of its own for the worker's files, removed at the end.
struct ScratchFolder {
    std::filesystem::path path;
    explicit ScratchFolder(const std::string& token)
        : path(std::filesystem::temp_directory_path() / ("whitted-explore-" + token.substr(0, 12))) {
        std::filesystem::create_directories(path);
    }
    ~ScratchFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
};

// Windows cannot rewrite the file of a running program: while the page is served, the student's own build of
// `whitted` (make test, a lab's preset) would fail to link it. There a copy of whitted serves the page, started in
// this console, and this program ends at once. The copies of earlier sessions are removed (not a running one).
int serve_from_copy(const ExploreOptions& options) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "whitted-explore-copies";
    std::filesystem::create_directories(folder);
    std::error_code ignored;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ignored)) std::filesystem::remove(entry, ignored);
    const std::filesystem::path self = own_executable();
    const std::filesystem::path copy = folder / ("whitted-" + random_token().substr(0, 8) + self.extension().string());
    std::filesystem::copy_file(self, copy);
    std::vector<std::string> argv{copy.string(), "explore", options.scene, "--port", std::to_string(options.port),
                                  "--threads", std::to_string(options.threads), "--from-copy"};
    if (options.stage) argv.insert(argv.end(), {"--stage", std::to_string(*options.stage)});
    start_detached(argv);
    std::printf("whitted explore: serving from a copy of whitted, so that your builds can still relink it; "
                "its link follows. Ctrl-C stops it.\n");
    return exit_code::success;
}

int run_explore(const ExploreOptions& options) {
    // The scene's errors first, before anything is served: the student fixes them in the file.
    LoadedScene loaded = load_scene(options.scene);
    for (const std::string& warning : loaded.warnings) std::fprintf(stderr, "%s\n", warning.c_str());
    const auto [width, height] = output_size(loaded.data.camera, std::nullopt, std::nullopt);
    if (const std::string problem = check_output_size(width, height); !problem.empty()) {
        std::fprintf(stderr, "whitted: %s\n", problem.c_str());
        return exit_code::bad_input;
    }
    if (!options.no_rebuild && !options.from_copy && live_build() && running_programs_are_locked())
        return serve_from_copy(options);
    const std::string token = random_token();
    const ScratchFolder scratch(token);
    ExploreSettings settings{options.scene, options.stage, options.threads, own_executable(), live_build(), scratch.path};
    if (options.no_rebuild) settings.live.reset();
    if (settings.live) settings.worker = settings.live->worker;
    ExploreSession session(std::move(settings));

    ExploreContent content;
    content.page = explore_page();
    content.state = [&] { return session.state(); };
    content.picture_png = [&](const std::string& view) { return session.picture(view); };
    content.tree = [&](int x, int y, int sample) { return session.tree(x, y, sample); };
    content.tree_png = [&](int x, int y, int sample) { return session.tree_picture(x, y, sample); };
    ExploreServer server(std::move(content), token);
    try {
        server.start(options.port);
    } catch (const std::runtime_error& error) {
        std::fprintf(stderr, "whitted explore: %s\n", error.what());
        return exit_code::bad_input;
    }
    std::printf("whitted explore: open %s in your browser (this machine only; Ctrl-C stops)\n", server.url().c_str());
    if (const std::optional<LiveBuild> live = options.no_rebuild ? std::nullopt : live_build())
        std::printf("whitted explore: watching %s: a save rebuilds and renders again\n", live->labs_dir.string().c_str());
    std::fflush(stdout);
    const std::atomic<bool> never_stops{false}; // Ctrl-C ends the program
    session.run(never_stops);
    return exit_code::success;
}

} // namespace

Command add_explore_command(CLI::App& app) {
    auto options = std::make_shared<ExploreOptions>();
    CLI::App* command = app.add_subcommand(
        "explore", "Render a scene with your labs and show it on a page in your browser, served on this machine only: "
                   "a click on a pixel shows its ray tree.");
    command->add_option("scene", options->scene, "Scene file (.nff or .p3f)")->required();
    add_stage_option(*command, options->stage);
    command->add_option("--port", options->port, "Port on 127.0.0.1 to serve the page on (default 0: a free one)")
        ->check(CLI::Range(0, 65535));
    command->add_option("--threads", options->threads, "Threads for rendering; 0 = one per core")->check(CLI::Range(0, 1024));
    command->add_flag("--no-rebuild", options->no_rebuild,
                      "Render with this program as it is: do not rebuild it when a lab file is saved");
    command->add_flag("--from-copy", options->from_copy)->group(""); // the copy that serves, on Windows
    command->footer("Example: whitted explore scenes/05_refraction.p3f\n"
                    "Exit code: 2 cannot serve what was given (a bad option, a missing or malformed scene file, labs not "
                    "done yet, a port in use), 3 whitted itself failed.");
    return Command{command, [options] { return run_explore(*options); }};
}

} // namespace whitted
