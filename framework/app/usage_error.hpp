// What to say when the command line is wrong: CLI11's reason, or for a
// mistyped command or option the nearest real one.
#pragma once

#include "commands.hpp"

#include <CLI/CLI.hpp>

#include <stdexcept>
#include <vector>

namespace whitted {

/// A mistake in what a command was given that CLI11 cannot see (found once the options are parsed): exit code 2.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Explains `error` on stderr, naming the closest command or option when one is near, and returns exit code 2.
int explain_usage_error(const CLI::ParseError& error, const std::vector<Command>& commands, int argc, char** argv);

} // namespace whitted
