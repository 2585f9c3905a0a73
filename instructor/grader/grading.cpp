#include "grader/grading.hpp"
#include "grader/builder.hpp"
#include "process/control_group.hpp"
#include "grader/kit.hpp"
#include "grader/lab_fences.hpp"
#include "grader/submission.hpp"
#include "grader/tamper_check.hpp"
#include "grader/test_runner.hpp"
#include "grader/text.hpp"
#include "grader/worker_build.hpp"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <unistd.h>

namespace whitted::grade {
namespace {

namespace fs = std::filesystem;

bool is_lab(const std::string& name) { return name != "integration"; }

// The longest run of a lab's tests together (passed_together): the reference's take well under a second.
constexpr double kTogetherSeconds = 10.0;
constexpr std::size_t kMaxObjectBytes = std::size_t{128} << 20; // the compiler writes no larger file

// What no run may change: the instructor tree's sources and data, and the checkers.
FileRecord relied_on_files(const GradingSetup& setup, const WorkerKit& kit) {
    const fs::path& tree = setup.instructor_tree;
    FileRecord record = FileRecord::of({tree / "tests", tree / "instructor", tree / "solution", tree / "scenes", tree / "labs",
                                         tree / "framework", tree / "cmake"});
    std::vector<fs::path> checkers;
    for (const auto& [lab, checker] : kit.checkers) checkers.push_back(checker);
    record.add(FileRecord::of(checkers));
    return record;
}

// The HEAD files of the tree's git history, which holds the solution too: .git/HEAD, or for a worktree
// (.git is a file "gitdir: DIR") DIR/HEAD and the HEAD of the repository it shares (DIR/commondir).
std::vector<fs::path> git_heads(const fs::path& tree) {
    const fs::path git = tree / ".git";
    std::error_code error;
    if (fs::is_directory(git, error)) return {git / "HEAD"};
    std::ifstream link(git);
    std::string line;
    if (!std::getline(link, line) || line.rfind("gitdir: ", 0) != 0) return {};
    fs::path gitdir = line.substr(8);
    if (gitdir.is_relative()) gitdir = tree / gitdir;
    std::vector<fs::path> heads = {gitdir / "HEAD"};
    std::ifstream common(gitdir / "commondir");
    if (std::string shared; std::getline(common, shared))
        heads.push_back((fs::path(shared).is_relative() ? gitdir / shared : fs::path(shared)) / "HEAD");
    return heads;
}

// Files the student's code must not read, one of each kind; the probe of make_sandbox tries them.
std::vector<fs::path> secrets(const GradingSetup& setup, const WorkerKit& kit) {
    std::vector<fs::path> files = {setup.instructor_tree / "solution" / "01_ray_casting.cpp", setup.instructor_tree / "instructor" / "rubric.json",
                                   setup.out, setup.out / "tests", fs::read_symlink("/proc/self/exe")};
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(setup.instructor_tree / "instructor" / "tests" / "hidden"))
        if (entry.is_regular_file()) {
            files.push_back(entry.path());
            break;
        }
    for (const auto& [lab, checker] : kit.checkers) files.push_back(checker);
    const std::vector<fs::path> history = git_heads(setup.instructor_tree);
    files.insert(files.end(), history.begin(), history.end());
    return files;
}

class LabGrader {
public:
    LabGrader(const GradingSetup& setup, const std::map<std::string, std::string>& refused)
        : setup_(setup), refused_(refused), paths_(shown_paths(setup)),
          deadline_(Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(setup.budget_seconds))) {}

    LabGrader(const LabGrader&) = delete;
    LabGrader& operator=(const LabGrader&) = delete;
    // What the student's code left where every user may write, once none of its processes is left.
    ~LabGrader() {
        if (!sandbox_.identity) return;
        sandbox_.end_runs();
        remove_user_leftovers(sandbox_.identity->uid);
    }

    /// The instructor build brought up to date, the kit staged, the fences set up.
    const Sandbox& prepare() {
        setup_.progress("updating the checkers and the grading kit in " + setup_.instructor_build.string());
        try {
            update_instructor_build(setup_.instructor_build, setup_.instructor_tree, setup_.jobs);
            kit_ = stage_kit(read_kit(setup_.instructor_build / "grading-kit.txt"), setup_.work / "kit");
        } catch (const std::runtime_error& e) {
            throw GraderFailure(e.what());
        }
        paths_.emplace_back((setup_.work / "kit" / "include").string() + "/", "framework/include/");
        paths_.emplace_back((setup_.work / "build").string() + "/", "build/");
        paths_.emplace_back(setup_.work.string() + "/", "");
        relied_on_ = relied_on_files(setup_, kit_);
        try {
            sandbox_ = make_sandbox(setup_.sandbox, secrets(setup_, kit_), setup_.work, setup_.max_processes, setup_.allow_exposed_answers);
        } catch (const std::runtime_error& e) {
            throw GraderFailure(e.what());
        }
        // One ceiling for all the student's code's processes at once, where the machine gives a control group.
        std::string no_group;
        if (std::optional<ControlGroup> group = ControlGroup::make(compile_memory(), sandbox_.processes, no_group)) {
            group_.emplace(std::move(*group));
            sandbox_.groups = group_->join_files();
            sandbox_.fences.push_back("a " + group_->kind() + " for all its processes together (" + mebibytes(compile_memory()) +
                                      " while compiling, " + mebibytes(setup_.test_limits.address_space) + " while tested, " +
                                      std::to_string(sandbox_.processes) + " processes)");
        } else {
            sandbox_.gaps.push_back(no_group + " (the memory ceiling is per process)");
        }
        setup_.progress(sandbox_.description());
        if (!sandbox_.bwrap_error.empty()) setup_.progress("bwrap said: " + sandbox_.bwrap_error);
        return sandbox_;
    }

    /// The link fence over the staged kit (lab_fences.hpp).
    LabFences read_fences() const {
        try {
            return LabFences(kit_);
        } catch (const std::exception& e) {
            throw GraderFailure(std::string("cannot read the grading kit's symbols: ") + e.what());
        }
    }

    /// Why the compiled object of `lab` may not be linked (the fenced functions it calls), or "".
    static std::string fenced_calls(const LabFences& fences, const fs::path& build, const std::string& lab) {
        try {
            return LabFences::describe(lab, fences.refused(lab, read_regular_file(build / (lab + ".o"), kMaxObjectBytes)));
        } catch (const std::exception& e) {
            return "labs/" + lab + ".cpp compiled to an object the grader cannot read (" + std::string(e.what()) + ").\n";
        }
    }

    /// Compiles the lab files and links a worker per lab and one for the whole renderer.
    void build_workers(const std::vector<std::string>& labs) {
        const fs::path build = setup_.work / "build";
        fs::create_directories(build / "labs");
        for (const std::string& lab : labs) fs::copy_file(setup_.out / "labs" / (lab + ".cpp"), build / "labs" / (lab + ".cpp"));
        fs::create_directories(setup_.work / "workers");
        // With a user of the grading's own, the submission's files and programs are that user's alone: another
        // grading running at once (another user) must not read them.
        const fs::perms shared = sandbox_.identity ? fs::perms(0700) : fs::perms(0755);
        fs::permissions(build / "labs", shared);
        fs::permissions(build, shared);
        give_folder(sandbox_, build / "labs");
        give_folder(sandbox_, build);
        share_with_student_code(setup_.work / "workers", 0750);
        const WorkerBuild worker_build{kit_, sandbox_, build, setup_.jobs, deadline_};
        setup_.progress("compiling the lab files");
        const std::map<std::string, BuildStep> compiled = compile_labs(worker_build, labs);
        const LabFences fences = read_fences();
        bool all_compiled = true;
        std::vector<WorkerParts> workers;
        for (const std::string& lab : labs) {
            const BuildStep& step = compiled.at(lab);
            if (!step.ok) {
                all_compiled = false;
                failures_[lab] = {Status::compile_error, "labs/" + lab + ".cpp does not compile", first_compiler_errors(step.log, paths_)};
            } else if (const std::string fenced = fenced_calls(fences, build, lab); !fenced.empty()) {
                all_compiled = false;
                failures_[lab] = {Status::compile_error, "labs/" + lab + ".cpp calls what grading does not let it use", fenced};
            } else {
                workers.push_back({lab, {lab}});
            }
        }
        if (all_compiled) workers.push_back({"integration", labs});
        else failures_["integration"] = {Status::compile_error, "the labs do not build together: not every lab file compiles", ""};
        setup_.progress("linking the workers");
        const std::map<std::string, BuildStep> linked = link_workers(worker_build, workers, labs);
        for (const WorkerParts& worker : workers) {
            const std::string& name = worker.name;
            const std::string program = "worker_" + name;
            const BuildStep& step = linked.at(name);
            if (!step.ok) {
                failures_[name] = {Status::compile_error, "the worker of " + name + " does not link", first_compiler_errors(step.log, paths_)};
                continue;
            }
            try {
                take_program(build / program, setup_.work / "workers" / program);
                share_with_student_code(setup_.work / "workers" / program, 0750);
            } catch (const std::exception& e) {
                failures_[name] = {Status::compile_error, std::string("the worker of ") + name + " " + e.what(), ""};
            }
        }
        // The build folder belongs to the student code's user: a test's worker could leave something there for the
        // next one. Nothing of it is needed once the workers are out (the compilers' processes are gone).
        std::error_code removed;
        fs::remove_all(build, removed);
        if (removed) throw GraderFailure("cannot remove the student's build folder " + build.string() + ": " + removed.message());
        if (group_ && !group_->set_memory(setup_.test_limits.address_space))
            throw GraderFailure("cannot lower the memory ceiling of the student's code's control group for the tests");
    }

    /// Grades every lab's tests in two passes (Pass): every lab's visible tests, then every lab's hidden tests, each
    /// pass lab by lab in rubric order; the results in rubric order, each lab's tests in listing order.
    std::vector<LabResult> grade(const Rubric& rubric) {
        std::vector<LabRun> runs;
        std::set<std::string> visible, hidden;
        for (const LabRubric& lab : rubric.labs) {
            runs.push_back(start(lab));
            visible.merge(rules_in_pass(lab, runs.back().plan, runs.back().names, Pass::visible));
            hidden.merge(rules_in_pass(lab, runs.back().plan, runs.back().names, Pass::hidden));
        }
        check_passes(rubric, visible, hidden);
        for (const Pass pass : {Pass::visible, Pass::hidden})
            for (LabRun& run : runs) test(run, pass);
        std::vector<LabResult> results;
        for (LabRun& run : runs) results.push_back(finish(std::move(run)));
        return results;
    }

private:
    struct LabFailure {
        Status status;
        std::string message;
        std::string details; // the compiler's first errors
    };

    // One lab across the two passes: its checker and worker, its tests, the rubric's plan for them, and the results.
    struct LabRun {
        const LabRubric* lab;
        TestProgram program;
        std::vector<std::string> names;    // as the checker lists them
        LabPlan plan;
        std::optional<LabFailure> failure; // why none of its tests can run, if so: missing, refused or not compiled
        LabResult result;                  // tests[t] is names[t]'s, once its pass has graded it
    };

    // The lab's tests listed by its checker (no student code runs) and planned with the rubric.
    LabRun start(const LabRubric& lab) {
        LabRun run{&lab,
                   TestProgram{lab.lab, kit_.checkers.at(lab.lab), {(setup_.work / "workers" / ("worker_" + lab.lab)).string()},
                               setup_.out / "tests" / lab.lab, setup_.test_limits, paths_, sandbox_},
                   {}, {}, std::nullopt, {}};
        std::string problem;
        run.names = list_tests(run.program, problem);
        if (!problem.empty()) throw GraderFailure("the checker of " + lab.lab + " does not list its tests: " + problem);
        if (const auto refused = refused_.find(lab.lab); refused != refused_.end()) run.failure = LabFailure{Status::missing, refused->second, ""};
        else if (const auto failed = failures_.find(lab.lab); failed != failures_.end()) run.failure = failed->second;
        run.plan = plan_lab(lab, run.names);
        run.result.lab = lab.lab;
        run.result.title = lab.title;
        run.result.notes = run.plan.notes;
        run.result.tests.resize(run.names.size());
        if (run.failure) {
            run.result.compile_errors = run.failure->details;
            run.result.problem = run.failure->message;
        }
        return run;
    }

    // Grades the lab's tests of one pass, in pass_order, each after the rules it requires.
    void test(LabRun& run, Pass pass) {
        const std::vector<std::size_t> order = pass_order(*run.lab, run.plan, run.names, pass);
        if (order.empty()) return;
        setup_.progress("testing " + run.lab->lab + (pass == Pass::hidden ? " (hidden tests)" : ""));
        const std::set<std::string> passed = run_together(run, order);
        for (const std::size_t t : order) {
            const Rule* rule = run.plan.rule_of_test[t];
            grade_test(run, t, rule ? unmet_prerequisite(*rule, finished_) : std::nullopt, passed);
            // A timeout costs its own test alone: the tests that need this one's rule still run (a failed answer
            // skips them; a slow one may be the machine's doing, and the other tests stand on their own).
            const Status status = run.result.tests[t].outcome.status;
            if (rule && status != Status::passed && status != Status::timeout)
                finished_[run.lab->lab + ":" + rule->id].push_back({run.names[t], status});
        }
        if (const std::optional<std::string> change = relied_on_.first_change(relied_on_files(setup_, kit_)))
            throw GraderFailure("while " + run.lab->lab + " was tested, a file the grader relies on changed: " + *change +
                                ". Grading stopped so that no grade depends on it; restore the file (git checkout, make build) and grade again.");
    }

    // The pass's tests first all in one pair: the names of those that passed there; every other test (image tests
    // fail there at once) runs on its own, which tells why it failed. A run that takes longer than kTogetherSeconds
    // (a hang, or very slow code) counts for nothing and costs no more than that.
    std::set<std::string> run_together(const LabRun& run, const std::vector<std::size_t>& order) {
        if (run.failure || seconds_left() < 1.0) return {};
        std::vector<std::string> together;
        for (const std::size_t t : order)
            if (run.plan.rule_of_test[t]) together.push_back(run.names[t]);
        return passed_together(run.program, together, std::min(kTogetherSeconds, seconds_left()));
    }

    // Grades test t (passed together already, run on its own, or not run for `reason`). One pair at a time: a checker
    // and its worker each want a core, and two pairs at once on two cores took longer than one after the other.
    void grade_test(LabRun& run, std::size_t t, const std::optional<std::string>& reason, const std::set<std::string>& passed) {
        const std::string& lab = run.lab->lab;
        // The whole renderer's tests are skipped for a failed prerequisite before its worker's build is blamed.
        const std::optional<LabFailure> failure = reason && !is_lab(lab) ? std::nullopt : run.failure;
        const double left = seconds_left();
        if (reason || failure) return score(run, t, not_run(lab, run.names[t], failure, reason));
        if (passed.count(run.names[t])) {
            TestOutcome outcome;
            outcome.lab = lab;
            outcome.name = run.names[t];
            outcome.status = Status::passed;
            return score(run, t, std::move(outcome));
        }
        if (left < 0.5) return score(run, t, not_run(lab, run.names[t], out_of_budget(), std::nullopt));
        run.program.limits.wall_seconds = std::min(setup_.test_limits.wall_seconds, left);
        score(run, t, run_test(run.program, run.names[t]));
    }

    // Scores test t with its outcome (the reference picture fetched for a failed image test that has none).
    void score(LabRun& run, std::size_t t, TestOutcome outcome) {
        const Rule* rule = run.plan.rule_of_test[t];
        if (rule && rule->image && outcome.status != Status::passed && outcome.pictures.empty() && !outcome.image)
            outcome.pictures = fetch_reference_picture(run.program, run.names[t]);
        const long points = score_test(outcome, run.plan.max_cents[t], rule, setup_.rubric.image_ramp);
        const bool image = (rule && rule->image) || outcome.image || !outcome.pictures.empty();
        run.result.tests[t] = ScoredTest{std::move(outcome), rule ? rule->id : "", run.plan.max_cents[t], points, image};
    }

    // The lab's result once both passes ran: its points, and each test that did not pass told to the instructor.
    LabResult finish(LabRun run) {
        for (const ScoredTest& test : run.result.tests) {
            run.result.score_cents += test.score_cents;
            run.result.max_cents += test.max_cents;
            if (test.outcome.status != Status::passed && !is_lab_wide(run.result, test.outcome))
                setup_.progress("  " + test.outcome.name + ": " + std::string(status_label(test.outcome.status)));
        }
        if (!run.result.problem.empty()) {
            const auto not_run = std::count_if(run.result.tests.begin(), run.result.tests.end(),
                                               [&](const ScoredTest& test) { return is_lab_wide(run.result, test.outcome); });
            setup_.progress("  " + run.result.lab + ": " + run.result.problem + " (" + std::to_string(not_run) + " tests not run)");
        }
        return std::move(run.result);
    }

    using Clock = std::chrono::steady_clock;

    // Makes a file of the grader's readable (and runnable) by the student code's user alone, not changeable by it.
    void share_with_student_code(const fs::path& path, unsigned mode) const {
        if (!sandbox_.identity) return fs::permissions(path, fs::perms(mode | 0005));
        if (chown(path.c_str(), 0, sandbox_.identity->gid) != 0)
            throw GraderFailure("cannot give " + path.string() + " to the student code's group");
        fs::permissions(path, fs::perms(mode));
    }

    // The control group's ceiling while `--jobs` compilers run.
    std::size_t compile_memory() const { return static_cast<std::size_t>(std::max(setup_.jobs, 1)) * kCompilerMemory; }
    static std::string mebibytes(std::size_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

    double seconds_left() const { return std::chrono::duration<double>(deadline_ - Clock::now()).count(); }

    // Why a test is not run once the grading's time budget ran out.
    LabFailure out_of_budget() const {
        char seconds[32];
        std::snprintf(seconds, sizeof seconds, "%g", setup_.budget_seconds);
        return {Status::timeout, std::string("not run: the grading's time budget of ") + seconds + " s ran out", ""};
    }

    // The outcome of a test that is not run.
    static TestOutcome not_run(const std::string& lab, const std::string& name, const std::optional<LabFailure>& failure,
                               const std::optional<std::string>& reason) {
        TestOutcome outcome;
        outcome.lab = lab;
        outcome.name = name;
        outcome.status = failure ? failure->status : Status::skipped;
        outcome.message = failure ? failure->message : reason.value_or("no rule of this lab could run");
        return outcome;
    }

    const GradingSetup& setup_;
    const std::map<std::string, std::string>& refused_;
    std::vector<std::pair<std::string, std::string>> paths_;
    WorkerKit kit_;
    Sandbox sandbox_;
    std::optional<ControlGroup> group_; // removed with the grader, after its last run
    FileRecord relied_on_;
    std::map<std::string, LabFailure> failures_; // lab or "integration" -> why its worker was not built
    RuleFailures finished_;
    Clock::time_point deadline_;
};

} // namespace

std::vector<std::pair<std::string, std::string>> shown_paths(const GradingSetup& setup) {
    std::vector<std::pair<std::string, std::string>> paths = {{(setup.out / "labs").string() + "/", "labs/"},
                                                              {setup.out.string() + "/", ""},
                                                              {setup.instructor_build.string() + "/", "build/"},
                                                              {setup.instructor_tree.string() + "/", ""}};
    if (!setup.work.empty()) paths.emplace_back(setup.work.string() + "/", "");
    return paths;
}

GradingResult grade_submission(const GradingSetup& setup) {
    std::vector<std::string> labs;
    for (const LabRubric& lab : setup.rubric.labs)
        if (is_lab(lab.lab)) labs.push_back(lab.lab);
    const std::map<std::string, std::string> refused =
        copy_lab_files(setup.submission_labs, setup.instructor_tree / "labs", setup.out / "labs", labs);
    fs::remove_all(setup.out / "tests");
    fs::create_directories(setup.out / "tests");
    fs::permissions(setup.out / "tests", fs::perms(0700)); // the checkers' reference pictures: not for the student's code

    LabGrader grader(setup, refused);
    GradingResult result;
    result.fences = grader.prepare().description();
    grader.build_workers(labs);
    result.labs = grader.grade(setup.rubric);
    for (const LabResult& lab : result.labs) {
        result.score_cents += lab.score_cents;
        result.max_cents += lab.max_cents;
    }
    return result;
}

} // namespace whitted::grade
