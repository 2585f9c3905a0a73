// The `whitted` command: render NFF and P3F scenes with the Whitted ray tracer.
#include "commands.hpp"
#include "exit_codes.hpp"
#include "platform.hpp"
#include "usage_error.hpp"
#include "version.hpp"
#include "whitted/crash_report.hpp"
#include "whitted/image.hpp"
#include "whitted/not_implemented.hpp"
#include "whitted/scene_loader.hpp"

#include <cstdio>
#include <exception>
#include <string>
#include <utility>
#include <vector>

int main(int argc, char** argv) {
    whitted::use_utf8_console();
    CLI::App app{"whitted: a Whitted-style recursive ray tracer for NFF and P3F scenes."};
    app.footer("Example: whitted render scenes/whitted_1980.p3f -o whitted_1980.png --stats\n"
               "Exit code: 0 done, 1 the answer is no (diff: the images differ), 2 cannot do what was given "
               "(a bad option, a bad or missing file, labs not done), 3 whitted itself failed.");
    // Options are --name on every system: CLI11 would also take /name on Windows, and then read a path
    // such as /tmp/scene.nff as an option. Set before the subcommands, which copy it.
    app.allow_windows_style_options(false);
    app.set_version_flag("-V,--version", whitted::version_line(), "Print the version and the build, then exit");
    app.require_subcommand(1);
    std::vector<whitted::Command> commands = {whitted::add_render_command(app), whitted::add_trace_command(app),
                                              whitted::add_diff_command(app), whitted::add_explore_command(app),
                                              whitted::add_generate_command(app), whitted::add_labs_command(app)};
    for (whitted::Command& command : whitted::add_instructor_commands(app)) commands.push_back(std::move(command));
    commands.push_back(whitted::add_completion_command(app));

    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& help_or_version) {
        return app.exit(help_or_version);
    } catch (const CLI::ParseError& error) {
        return whitted::explain_usage_error(error, commands, argc, argv);
    }
    whitted::report_crashes(); // a crash in lab code: one line naming the lab function, exit code 3
    try {
        for (const whitted::Command& command : commands)
            if (command.app->parsed()) return command.run();
    } catch (const whitted::SceneError& error) { // file:line:col: what is wrong
        std::fprintf(stderr, "%s\n", error.what());
        return whitted::exit_code::bad_input;
    } catch (const whitted::ImageError& error) { // an image that cannot be read or written
        std::fprintf(stderr, "%s\n", error.what());
        return whitted::exit_code::bad_input;
    } catch (const whitted::NotImplemented& error) { // a lab not done yet
        std::fprintf(stderr, "%s\n", error.what());
        return whitted::exit_code::bad_input;
    } catch (const std::exception& error) {
        // In a student's build it may be their lab's own exception: say both.
        std::fprintf(stderr, "whitted: stopped by an unexpected error: %s (if a lab's code throws it, fix it there; otherwise please report it)\n",
                     error.what());
        return whitted::exit_code::tool_failure;
    }
    return whitted::exit_code::success;
}
