// `whitted generate KIND [--level N] [-o FILE]`: write a procedural benchmark
// scene (sphereflake, fractal tetrahedron, random triangle soup as NFF; a dense torus mesh as P3F), to a file or to stdout.
//
// Why a command: students and `make bench` get scenes of any size without
// downloading SPD, and the output is an ordinary scene file to render or read.
#include "commands.hpp"
#include "exit_codes.hpp"
#include "whitted/generators.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace whitted {
namespace {

struct GenerateOptions {
    std::string kind;
    std::optional<int> level;
    std::string output; // empty: stdout
};

int run_generate(const GenerateOptions& options) {
    const Generator& generator = *find_generator(options.kind); // CLI11 checked the name
    const int level = options.level.value_or(generator.default_level);
    const std::string error = generator_level_error(std::string(generator.name), level, generator.min_level, generator.max_level);
    if (!error.empty()) {
        std::fprintf(stderr, "whitted generate: %s\n", error.c_str());
        return exit_code::bad_input;
    }
    if (options.output.empty()) {
        generator.write(level, std::cout);
        std::cout.flush();
        return std::cout ? exit_code::success : exit_code::bad_input;
    }
    std::ofstream file(options.output, std::ios::binary);
    if (file) generator.write(level, file);
    file.close();
    if (!file) {
        std::fprintf(stderr, "whitted generate: cannot write %s\n", options.output.c_str());
        return exit_code::bad_input;
    }
    return exit_code::success;
}

} // namespace

Command add_generate_command(CLI::App& app) {
    auto options = std::make_shared<GenerateOptions>();
    std::vector<std::string> names;
    std::string levels;
    for (const Generator& generator : generators()) {
        names.emplace_back(generator.name);
        levels += (levels.empty() ? "" : "; ") + std::string(generator.name) + " " +
                  std::to_string(generator.min_level) + " to " + std::to_string(generator.max_level) + ", default " +
                  std::to_string(generator.default_level);
    }
    CLI::App* command = app.add_subcommand("generate", "Write a procedural benchmark scene: sphereflake and tetra (SPD style, NFF), torus (one dense P3F mesh), soup (random triangles, NFF).");
    command->add_option("kind", options->kind, "What to generate: sphereflake, tetra, torus or soup")
        ->required()
        ->check(CLI::IsMember(names));
    command->add_option("--level", options->level, "Recursion level (" + levels + ")");
    command->add_option("-o,--output", options->output, "Scene file to write: .nff for sphereflake, tetra and soup, .p3f for torus (default: standard output)");
    command->footer("Example: whitted generate sphereflake --level 4 -o flake4.nff\n"
                    "Exit code: 0 scene written, 2 a bad kind, level or option, or the file cannot be written, "
                    "3 whitted itself failed.");
    return Command{command, [options] { return run_generate(*options); }};
}

} // namespace whitted
