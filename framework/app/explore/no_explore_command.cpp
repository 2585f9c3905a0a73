// `whitted explore` where cpp-httplib was not found when whitted was built: it says what to install.
#include "commands.hpp"
#include "exit_codes.hpp"

#include <cstdio>

namespace whitted {

Command add_explore_command(CLI::App& app) {
    CLI::App* command = app.add_subcommand("explore", "Show a scene and its ray trees in your browser (needs cpp-httplib; see below)");
    command->allow_extras();
    return Command{command, [] {
                       std::fprintf(stderr, "whitted explore: this whitted was built without cpp-httplib 0.11 or later, the web server it needs. "
                                            "Install it (Debian 12, Ubuntu 24.04: sudo apt-get install libcpp-httplib-dev; Windows and "
                                            "macOS: it comes with vcpkg.json), then build again (cmake -B build .)\n");
                       return exit_code::bad_input;
                   }};
}

} // namespace whitted
