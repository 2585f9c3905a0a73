#include "grade/worker_build.hpp"
#include "grade/submission.hpp"

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

std::map<std::string, BuildStep> compile_labs(const WorkerBuild& build, const std::vector<std::string>& labs) {
    std::map<std::string, BuildStep> steps;
    for (std::size_t first = 0; first < labs.size(); first += static_cast<std::size_t>(std::max(1, build.jobs))) {
        std::vector<ProcessSpec> specs;
        const std::size_t last = std::min(labs.size(), first + static_cast<std::size_t>(std::max(1, build.jobs)));
        for (std::size_t i = first; i < last; ++i) {
            std::vector<std::string> argv = {build.kit.compiler.string()};
            argv.insert(argv.end(), build.kit.compile_arguments.begin(), build.kit.compile_arguments.end());
            argv.insert(argv.end(), {"-I", kit_include(build.kit).string(), "-c", "labs/" + labs[i] + ".cpp", "-o", labs[i] + ".o"});
            specs.push_back(fenced(build, std::move(argv)));
        }
        const std::vector<ProcessRun> runs = run_together(specs);
        for (std::size_t i = first; i < last; ++i)
            steps[labs[i]] = step_of(build.sandbox.unwrap(runs[i - first]), specs[i - first].limits);
        build.sandbox.end_runs();
    }
    return steps;
}

BuildStep link_worker(const WorkerBuild& build, const std::string& name, const std::vector<std::string>& own_labs,
                      const std::vector<std::string>& all_labs) {
    std::vector<std::string> argv = {build.kit.compiler.string()};
    argv.insert(argv.end(), build.kit.compile_arguments.begin(), build.kit.compile_arguments.end());
    argv.push_back(build.kit.main_object.string());
    for (const std::string& lab : all_labs) {
        if (std::find(own_labs.begin(), own_labs.end(), lab) != own_labs.end()) argv.push_back(lab + ".o");
        else argv.push_back(build.kit.remote_objects.at(lab).string());
    }
    for (const fs::path& library : build.kit.libraries) argv.push_back(library.string());
    argv.insert(argv.end(), build.kit.link_arguments.begin(), build.kit.link_arguments.end());
    argv.insert(argv.end(), {"-o", name});
    const ProcessSpec spec = fenced(build, std::move(argv));
    const BuildStep step = step_of(build.sandbox.unwrap(run_process(spec)), spec.limits);
    build.sandbox.end_runs();
    return step;
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
