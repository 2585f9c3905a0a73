#include "grader/worker_build.hpp"
#include "grader/submission.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>

namespace whitted::grade {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kMaxProgramBytes = std::size_t{256} << 20;

Limits compiler_limits(const WorkerBuild& build) {
    Limits limits;
    const double left = std::chrono::duration<double>(build.deadline - std::chrono::steady_clock::now()).count();
    limits.wall_seconds = std::clamp(left, 0.5, 120.0);
    limits.cpu_seconds = 120;
    limits.address_space = kCompilerMemory;
    limits.file_size = std::size_t{128} << 20;
    limits.output_bytes = 64 * 1024;
    return limits;
}

ProcessSpec fenced(const WorkerBuild& build, std::vector<std::string> argv) {
    ProcessSpec spec;
    spec.argv = std::move(argv);
    spec.working_directory = build.folder;
    spec.environment = {{"TMPDIR", build.folder.string()}};
    spec.limits = compiler_limits(build);
    return build.sandbox.wrap(std::move(spec), {build.kit.root}, build.folder);
}

BuildStep step_of(const ProcessRun& run, const Limits& limits) {
    BuildStep step;
    step.ok = run.end == ProcessRun::End::exited && run.exit_code == 0;
    step.log = run.output;
    if (!step.ok) step.log.append("\n").append(describe(run, limits)).append("\n");
    return step;
}

} // namespace

namespace {

// Runs the fenced steps `jobs` at a time; returns each step's outcome, in order.
std::vector<BuildStep> run_steps(const WorkerBuild& build, const std::vector<ProcessSpec>& specs) {
    std::vector<BuildStep> steps;
    const std::size_t jobs = static_cast<std::size_t>(std::max(1, build.jobs));
    for (std::size_t first = 0; first < specs.size(); first += jobs) {
        const std::vector<ProcessSpec> batch(specs.begin() + static_cast<std::ptrdiff_t>(first),
                                             specs.begin() + static_cast<std::ptrdiff_t>(std::min(specs.size(), first + jobs)));
        const std::vector<ProcessRun> runs = run_together(batch);
        for (std::size_t i = 0; i < batch.size(); ++i) steps.push_back(step_of(build.sandbox.unwrap(runs[i]), batch[i].limits));
        build.sandbox.end_runs();
    }
    return steps;
}

} // namespace

std::map<std::string, BuildStep> compile_labs(const WorkerBuild& build, const std::vector<std::string>& given_labs) {
    // The longest files first: they compile `jobs` at a time and each batch waits for its slowest, so files of
    // about the same size go together (the reference's lab 10 and lab 1, then the rest).
    std::vector<std::pair<std::uintmax_t, std::string>> by_size;
    for (const std::string& lab : given_labs) {
        std::error_code error;
        const std::uintmax_t size = fs::file_size(build.folder / "labs" / (lab + ".cpp"), error);
        by_size.emplace_back(error ? 0 : size, lab);
    }
    std::stable_sort(by_size.begin(), by_size.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<std::string> labs;
    for (const auto& [size, lab] : by_size) labs.push_back(lab);
    std::vector<ProcessSpec> specs;
    for (const std::string& lab : labs) {
        std::vector<std::string> argv = {build.kit.compiler.string()};
        argv.insert(argv.end(), build.kit.compile_arguments.begin(), build.kit.compile_arguments.end());
        argv.insert(argv.end(), {"-I", kit_include(build.kit).string(), "-c", "labs/" + lab + ".cpp", "-o", lab + ".o"});
        specs.push_back(fenced(build, std::move(argv)));
    }
    const std::vector<BuildStep> steps = run_steps(build, specs);
    std::map<std::string, BuildStep> by_lab;
    for (std::size_t i = 0; i < labs.size(); ++i) by_lab[labs[i]] = steps[i];
    return by_lab;
}

std::map<std::string, BuildStep> link_workers(const WorkerBuild& build, const std::vector<WorkerParts>& workers,
                                              const std::vector<std::string>& all_labs) {
    std::vector<ProcessSpec> specs;
    for (const WorkerParts& worker : workers) {
        std::vector<std::string> argv = {build.kit.compiler.string()};
        argv.insert(argv.end(), build.kit.compile_arguments.begin(), build.kit.compile_arguments.end());
        argv.push_back(build.kit.main_object.string());
        for (const std::string& lab : all_labs) {
            if (std::find(worker.own_labs.begin(), worker.own_labs.end(), lab) != worker.own_labs.end()) argv.push_back(lab + ".o");
            else argv.push_back(build.kit.remote_objects.at(lab).string());
        }
        for (const fs::path& library : build.kit.libraries) argv.push_back(library.string());
        argv.insert(argv.end(), build.kit.link_arguments.begin(), build.kit.link_arguments.end());
        // Stripped: the worker has no symbol table in which to look up the framework's fenced functions.
        argv.insert(argv.end(), {"-s", "-o", "worker_" + worker.name});
        specs.push_back(fenced(build, std::move(argv)));
    }
    const std::vector<BuildStep> steps = run_steps(build, specs);
    std::map<std::string, BuildStep> by_name;
    for (std::size_t i = 0; i < workers.size(); ++i) by_name[workers[i].name] = steps[i];
    return by_name;
}

void take_program(const fs::path& built, const fs::path& destination) {
    const std::string content = read_regular_file(built, kMaxProgramBytes);
    fs::remove(destination);
    {
        std::ofstream out(destination, std::ios::binary);
        out << content;
        if (!out.flush()) throw std::runtime_error("cannot write " + destination.string());
    }
    fs::permissions(destination, fs::perms(0755));
}

} // namespace whitted::grade
