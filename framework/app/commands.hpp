// The subcommands of `whitted`. Each one registers its options with CLI11 and
// returns how to run it once the command line has been parsed.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <vector>

namespace whitted {

struct Command {
    CLI::App* app;            // the subcommand, to ask whether it was given
    std::function<int()> run; // runs it; returns the exit code
};

/// `whitted render SCENE ...`
Command add_render_command(CLI::App& app);

/// `whitted trace SCENE --pixel X Y ...`
Command add_trace_command(CLI::App& app);

/// `whitted diff A B [-o DIFF]`
Command add_diff_command(CLI::App& app);

/// `whitted generate KIND [--level N] [-o FILE]`
Command add_generate_command(CLI::App& app);

/// `whitted explore SCENE [--stage K] [--port N]` (without cpp-httplib: says what to install)
Command add_explore_command(CLI::App& app);

/// `whitted labs [--tsv]`
Command add_labs_command(CLI::App& app);

/// `whitted completion bash`
Command add_completion_command(CLI::App& app);

/// The instructor build's extra commands (`whitted grade`); none in the student's.
std::vector<Command> add_instructor_commands(CLI::App& app);

} // namespace whitted
