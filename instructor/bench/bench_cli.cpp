// Parsing `whitted-bench`'s command line with CLI11 (see bench_options.hpp).
#include "bench_options.hpp"

#include "whitted/generators.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace whitted::bench {

std::vector<int> parse_levels(const std::string& generator_name, const std::string& text) {
    const Generator& generator = *find_generator(generator_name);
    std::vector<int> levels;
    if (text == "none") return levels;
    std::istringstream list(text);
    for (std::string item; std::getline(list, item, ',');) {
        std::size_t used = 0;
        int level = -1;
        try {
            level = std::stoi(item, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != item.size())
            throw std::invalid_argument("expected " + generator_name + " levels like 4,5,6 (or none), found '" + text + "'");
        const std::string error = generator_level_error(generator_name, level, generator.min_level, generator.max_level);
        if (!error.empty()) throw std::invalid_argument(error);
        if (std::find(levels.begin(), levels.end(), level) == levels.end()) levels.push_back(level);
    }
    if (levels.empty()) throw std::invalid_argument("expected " + generator_name + " levels like 4,5,6 (or none), found ''");
    return levels;
}

CommandLine parse_command_line(int argc, char** argv) {
    CommandLine result;
    BenchOptions& o = result.options;
    BenchSettings& s = o.settings;
    std::string flake = "4", tetra = "none", soup = "none";
    bool no_povray = false, no_embree = false;

    CLI::App app{"whitted-bench: time whitted against POV-Ray 3.7 and Embree 3 on the same scenes (make bench)."};
    app.add_option("scenes", o.scenes, "More scenes to measure (.nff or .p3f)")->check(CLI::ExistingFile);
    app.add_option("--flake", flake, "Sphereflake levels to generate and measure, e.g. 4,5,6, or none (default 4)");
    app.add_option("--tetra", tetra, "Fractal tetrahedron levels to generate and measure, e.g. 6 (default none)");
    app.add_option("--soup", soup, "Random triangle soup levels to generate and measure, e.g. 4 (default none)");
    app.add_option("--size", s.size, "Image width and height in pixels (default 512)")->check(CLI::Range(1, 16384));
    app.add_option("--threads", s.threads, "Rendering threads of every program (default 2)")->check(CLI::Range(1, 1024));
    app.add_option("--depth", s.depth, "Deepest ray; the eye ray is depth 1 (default 5)")->check(CLI::Range(1, 100));
    app.add_option("--runs", s.runs, "Measured runs per scene and program (default 5)")->check(CLI::Range(1, 1000));
    app.add_option("--warmup", s.warmup, "Unmeasured runs before them (default 1)")->check(CLI::Range(0, 100));
    app.add_option("--out", o.out, "Folder for scenes, images and results (default bench-results)");
    app.add_flag("--no-povray", no_povray, "Leave out the POV-Ray comparison");
    app.add_flag("--no-embree", no_embree, "Leave out the Embree comparison");
    app.add_option("--whitted", o.whitted, "The whitted program to measure (default: the one beside this program)")
        ->check(CLI::ExistingFile);
    app.add_option("--student-whitted", o.student_whitted,
                   "Also measure this build with the student's labs (e.g. build/whitted-student)")
        ->check(CLI::ExistingFile);
    app.add_option("--baseline", o.baseline,
                   "Flag whitted's load or render times that got worse than in this earlier results.json "
                   "(make bench: instructor/bench/baseline.json)")
        ->check(CLI::ExistingFile);
    app.footer("Example: whitted-bench --flake 4,5,6 teapot6.nff mount6.nff --runs 5 --out bench-results");

    try {
        app.parse(argc, argv);
        o.flake_levels = parse_levels("sphereflake", flake);
        o.tetra_levels = parse_levels("tetra", tetra);
        o.soup_levels = parse_levels("soup", soup);
    } catch (const CLI::CallForHelp& help) {
        result.exit_code = app.exit(help);
        return result;
    } catch (const CLI::ParseError& error) {
        std::fprintf(stderr, "whitted-bench: %s (see whitted-bench --help)\n", error.what());
        result.exit_code = 2;
        return result;
    } catch (const std::invalid_argument& error) {
        std::fprintf(stderr, "whitted-bench: %s\n", error.what());
        result.exit_code = 2;
        return result;
    }
    o.povray = !no_povray;
    o.embree = !no_embree;
    if (o.scenes.empty() && o.flake_levels.empty() && o.tetra_levels.empty() && o.soup_levels.empty()) {
        std::fprintf(stderr, "whitted-bench: no scenes: give scene files, --flake, --tetra or --soup\n");
        result.exit_code = 2;
    }
    return result;
}

} // namespace whitted::bench
