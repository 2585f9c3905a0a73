#include "usage_error.hpp"

#include "closest_name.hpp"
#include "exit_codes.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

namespace whitted {
namespace {

// "a, b and c".
std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i)
        text += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    return text;
}

// The long options of a command, without their dashes ("width" for --width).
std::vector<std::string> long_option_names(const CLI::App& command) {
    std::vector<std::string> names;
    for (const CLI::Option* option : command.get_options())
        for (const std::string& name : option->get_lnames()) names.push_back(name);
    return names;
}

// The first "--name" on the command line that `command` does not know, without its dashes and value.
std::optional<std::string> unknown_long_option(const CLI::App& command, int argc, char** argv) {
    const std::vector<std::string> known = long_option_names(command);
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (arg == "--") break;
        if (arg.size() <= 2 || arg.substr(0, 2) != "--") continue;
        const std::string name(arg.substr(2, arg.find('=') - 2));
        if (std::find(known.begin(), known.end(), name) == known.end()) return name;
    }
    return std::nullopt;
}

} // namespace

int explain_usage_error(const CLI::ParseError& error, const std::vector<Command>& commands, int argc, char** argv) {
    const Command* given = nullptr;
    for (const Command& command : commands)
        if (command.app->parsed()) given = &command;
    std::vector<std::string> names;
    for (const Command& command : commands) names.push_back(command.app->get_name());

    if (!given && argc > 1 && argv[1][0] != '-') {
        const std::optional<std::string> guess = closest_name(argv[1], names);
        const std::string hint = guess ? "; did you mean '" + *guess + "'?" : "";
        std::fprintf(stderr, "whitted: unknown command '%s'%s\nThe commands are %s; 'whitted --help' says what each does.\n",
                     argv[1], hint.c_str(), joined(names).c_str());
        return exit_code::bad_input;
    }
    const std::string command = given ? given->app->get_name() : "render";
    // A mistyped option of the command given, or of whitted itself (--version) before any command.
    const CLI::App* options_of = given ? given->app : commands.front().app->get_parent();
    if (!given || dynamic_cast<const CLI::ExtrasError*>(&error)) {
        if (const std::optional<std::string> unknown = unknown_long_option(*options_of, argc, argv)) {
            const std::optional<std::string> guess = closest_name(*unknown, long_option_names(*options_of));
            const std::string hint = guess ? "; did you mean '--" + *guess + "'?" : "";
            const std::string who = given ? "whitted " + command : "whitted";
            std::fprintf(stderr, "%s: unknown option '--%s'%s\nRun '%s --help' for the options.\n", who.c_str(),
                         unknown->c_str(), hint.c_str(), who.c_str());
            return exit_code::bad_input;
        }
    }
    std::fprintf(stderr, "whitted: %s\nRun 'whitted --help' or 'whitted %s --help' for the options.\n", error.what(),
                 command.c_str());
    return exit_code::bad_input;
}

} // namespace whitted
