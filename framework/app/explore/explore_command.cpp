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
#include "platform.hpp"
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
};

// A new folder of a random name for the worker's files, readable by this user alone, removed at the end: in the
// build folder (the student's own) when there is one, else in the system's temporary folder.
struct ScratchFolder {
    std::filesystem::path path;
    explicit ScratchFolder(const std::optional<LiveBuild>& live) {
        const std::filesystem::path parent =
            live ? live->build_dir / "explore-scratch" : std::filesystem::temp_directory_path();
        std::filesystem::create_directories(parent);
        for (int attempt = 0; attempt < 100; ++attempt) {
            path = parent / ("whitted-explore-" + random_token().substr(0, 16));
            if (std::filesystem::create_directory(path)) {
                std::error_code ignored;
                std::filesystem::permissions(path, std::filesystem::perms::owner_all, ignored);
                return;
            }
        }
        throw std::runtime_error("cannot make a folder of its own in " + parent.string());
    }
    ~ScratchFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
};

int run_explore(const ExploreOptions& options) {
    // The scene's errors first, before anything is served: the student fixes them in the file.
    LoadedScene loaded = load_scene(options.scene);
    for (const std::string& warning : loaded.warnings) std::fprintf(stderr, "%s\n", warning.c_str());
    const auto [width, height] = output_size(loaded.data.camera, std::nullopt, std::nullopt);
    if (const std::string problem = check_output_size(width, height); !problem.empty()) {
        std::fprintf(stderr, "whitted: %s\n", problem.c_str());
        return exit_code::bad_input;
    }
    // While the page is served, the student's own builds (make test, a lab's preset) must still relink whitted.
    free_own_file();
    const std::string token = random_token();
    const std::optional<LiveBuild> live = options.no_rebuild ? std::nullopt : live_build();
    const ScratchFolder scratch(live);
    ExploreSession session(ExploreSettings{options.scene, options.stage, options.threads, own_executable(), live, scratch.path});

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
    if (live) std::printf("whitted explore: watching %s: a save rebuilds and renders again\n", live->labs_dir.string().c_str());
    std::fflush(stdout);
    static std::atomic<bool> interrupted{false}; // Ctrl-C: the session ends, then the server, then the scratch folder
    stop_on_interrupt(interrupted);
    session.run(interrupted);
    server.stop();
    std::printf("whitted explore: stopped\n");
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
    command->footer("Example: whitted explore scenes/05_refraction.p3f\n"
                    "Exit code: 0 stopped with Ctrl-C, 2 cannot serve what was given (a bad option, a missing or malformed "
                    "scene file, a port in use), 3 whitted itself failed. A lab not done yet is told on the page.");
    return Command{command, [options] { return run_explore(*options); }};
}

} // namespace whitted
