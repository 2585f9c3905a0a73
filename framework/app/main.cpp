// The `whitted` command: render NFF and P3F scenes with the Whitted ray tracer.
#include "commands.hpp"

#include <cstdio>
#include <exception>
#include <string>
#include <utility>
#include <vector>

int main(int argc, char** argv) {
    CLI::App app{"whitted: a Whitted-style recursive ray tracer for NFF and P3F scenes."};
    app.footer("Example: whitted render scenes/whitted_1980.p3f -o whitted_1980.png --stats");
    app.require_subcommand(1);
    std::vector<whitted::Command> commands = {whitted::add_render_command(app), whitted::add_trace_command(app),
                                              whitted::add_diff_command(app), whitted::add_generate_command(app),
                                              whitted::add_labs_command(app)};
    for (whitted::Command& command : whitted::add_instructor_commands(app)) commands.push_back(std::move(command));

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& help) {
        return app.exit(help);
    } catch (const CLI::ParseError& error) {
        // Point at the help of the command that was given, if any.
        std::string command = "render";
        bool given = false;
        for (const whitted::Command& c : commands) {
            if (c.app->parsed()) {
                command = c.app->get_name();
                given = true;
            }
        }
        if (!given && argc > 1 && argv[1][0] != '-') {
            std::string names;
            for (const whitted::Command& c : commands) names += (names.empty() ? "" : ", ") + c.app->get_name();
            std::fprintf(stderr, "whitted: unknown command '%s'; the commands are %s.\nRun 'whitted --help' for what each does.\n",
                         argv[1], names.c_str());
            return 2;
        }
        std::fprintf(stderr, "whitted: %s\nRun 'whitted --help' or 'whitted %s --help' for the options.\n", error.what(),
                     command.c_str());
        return 2;
    }
    try {
        for (const whitted::Command& command : commands)
            if (command.app->parsed()) return command.run();
    } catch (const std::exception& error) {
        std::fprintf(stderr, "%s\n", error.what());
        return 1;
    }
    return 0;
}
