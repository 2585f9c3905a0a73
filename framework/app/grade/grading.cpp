#include "grade/grading.hpp"
#include "grade/builder.hpp"
#include "grade/prebuilt.hpp"
#include "grade/submission.hpp"
#include "grade/tamper_check.hpp"
#include "grade/test_runner.hpp"
#include "grade/text.hpp"

#include <algorithm>
#include <optional>

namespace whitted::grade {
namespace {

namespace fs = std::filesystem;

bool is_lab(const std::string& name) { return name != "integration"; }

// What a test must not change: the instructor tree's sources and data, and the imported libraries.
FileRecord relied_on_files(const GradingSetup& setup) {
    const fs::path& tree = setup.instructor_tree;
    FileRecord record = FileRecord::of({tree / "tests", tree / "solution", tree / "scenes", tree / "labs", tree / "framework", tree / "cmake"});
    if (!setup.prebuilt.empty()) record.add(FileRecord::of({setup.prebuilt}, {".a", ".o", ".cmake"}));
    return record;
}

// The grading build folder; the prebuilt parts are added once they are known to be usable.
BuildFolder shared_build_folder(const GradingSetup& setup) {
    BuildFolder folder;
    folder.instructor_tree = setup.instructor_tree;
    folder.build = setup.build;
    folder.labs = setup.out / "labs";
    folder.jobs = setup.jobs;
    return folder;
}

class LabGrader {
public:
    LabGrader(const GradingSetup& setup, const std::vector<std::string>& missing)
        : setup_(setup), missing_(missing), folder_(shared_build_folder(setup)),
          paths_(shown_paths(setup)) {}

    /// The fences of the tests, known once the test programs' folder exists.
    const Sandbox& fence_tests() {
        sandbox_ = make_sandbox(setup_.sandbox, {setup_.instructor_tree, setup_.build / "tests", setup_.out / "tests"},
                                setup_.max_processes);
        setup_.progress(sandbox_.description);
        if (!sandbox_.unreachable.empty()) setup_.progress("user nobody cannot reach " + sandbox_.unreachable);
        if (!sandbox_.bwrap_error.empty()) setup_.progress("bwrap said: " + sandbox_.bwrap_error);
        return sandbox_;
    }

    // The framework, the reference labs and the lab tests: imported from the instructor build when it can be, else compiled here.
    void build_shared_parts() {
        if (!setup_.prebuilt.empty()) {
            setup_.progress("updating the shared parts in " + setup_.prebuilt.string());
            const PrebuiltCheck prebuilt = update_prebuilt(setup_.prebuilt, setup_.instructor_tree, setup_.jobs);
            if (prebuilt.usable) folder_.prebuilt = setup_.prebuilt;
            else setup_.progress("not importing them: " + prebuilt.reason);
        }
        setup_.progress("configuring " + setup_.build.string());
        const BuildStep configured = configure(folder_);
        if (!configured.ok) throw GraderFailure("configuring the instructor tree failed:\n" + trim_text(configured.log, 40));
        for (const std::string& note : split_lines(prebuilt_notes(configured.log))) setup_.progress(note);
        setup_.progress("building the shared parts that are not imported: the framework, the reference, the tests");
        const BuildStep built = build_targets(folder_, {"grading_shared_parts"});
        if (!built.ok) throw GraderFailure("building the instructor tree failed:\n" + first_compiler_errors(built.log, paths_));
    }

    LabResult grade(const LabRubric& lab) {
        LabResult result;
        result.lab = lab.lab;
        result.title = lab.title;
        // Prerequisites in earlier labs are known now; those within this lab, once their rule has run.
        const bool missing = std::find(missing_.begin(), missing_.end(), lab.lab) != missing_.end();
        const bool any_runs = !missing && std::any_of(lab.rules.begin(), lab.rules.end(), [&](const Rule& rule) {
                                  return !unmet_prerequisite(rule, finished_);
                              });
        LabRun run{program(lab.lab, "grade_"), {}, std::nullopt, {}};
        if (missing) {
            run.lab_status = Status::missing;
            run.lab_message = "the submission has no " + lab.lab + ".cpp";
        } else if (any_runs) {
            build_lab(lab.lab, run, result);
        }
        if (any_runs && !run.lab_status) {
            std::string problem;
            run.names = list_tests(run.program, problem);
            if (run.names.empty()) {
                run.lab_status = Status::crash;
                run.lab_message = "the test program did not start: " + split_lines(problem).front();
            }
        }
        if (!any_runs || run.lab_status) {
            run.program = program(lab.lab, "list_");
            run.names = names_from_reference(run.program);
        }

        const LabPlan plan = plan_lab(lab, run.names);
        result.notes = plan.notes;
        result.tests.resize(run.names.size());
        auto grade_test = [&](std::size_t t, const std::optional<std::string>& reason) {
            const Rule* rule = plan.rule_of_test[t];
            TestOutcome outcome = reason || !any_runs || run.lab_status ? not_run(lab.lab, run, t, reason) : run_test(run.program, run.names[t]);
            if (rule && rule->image && outcome.status != Status::passed && outcome.pictures.empty() && !outcome.image)
                outcome.pictures = fetch_reference_picture(run.program, run.names[t]);
            const long score = score_test(outcome, plan.max_cents[t], rule, setup_.rubric.image_ramp);
            const bool image = (rule && rule->image) || outcome.image || !outcome.pictures.empty();
            result.tests[t] = ScoredTest{std::move(outcome), rule ? rule->id : "", plan.max_cents[t], score, image};
        };
        for (std::size_t r = 0; r < lab.rules.size(); ++r) {
            const std::optional<std::string> unmet = unmet_prerequisite(lab.rules[r], finished_);
            std::vector<Failure>& failures = finished_[lab.lab + ":" + lab.rules[r].id];
            for (std::size_t t = 0; t < run.names.size(); ++t) {
                if (plan.rule_of_test[t] != &lab.rules[r]) continue;
                grade_test(t, unmet);
                if (result.tests[t].outcome.status != Status::passed) failures.push_back({run.names[t], result.tests[t].outcome.status});
            }
        }
        for (std::size_t t = 0; t < run.names.size(); ++t)
            if (!plan.rule_of_test[t]) grade_test(t, std::nullopt);
        for (const ScoredTest& test : result.tests) {
            result.score_cents += test.score_cents;
            result.max_cents += test.max_cents;
            if (test.outcome.status != Status::passed) setup_.progress("  " + test.outcome.name + ": " + std::string(status_label(test.outcome.status)));
        }
        return result;
    }

private:
    // How one lab's tests are run: by which program, which tests, or why none of them runs.
    struct LabRun {
        TestProgram program;
        std::vector<std::string> names;
        std::optional<Status> lab_status; // when the lab's program cannot run at all
        std::string lab_message;
    };

    TestProgram program(const std::string& lab, const std::string& prefix) const {
        return {lab, setup_.build / "tests" / (prefix + lab), setup_.out / "tests" / lab, setup_.test_limits, paths_, sandbox_};
    }

    // Builds the student's lab file alone first, so that its errors are the ones shown.
    void build_lab(const std::string& lab, LabRun& run, LabResult& result) {
        setup_.progress("building " + lab);
        BuildStep built = is_lab(lab) ? build_targets(folder_, {"student_" + lab}) : BuildStep{true, {}};
        if (built.ok) built = build_targets(folder_, {"grade_" + lab});
        if (built.ok) return;
        run.lab_status = Status::compile_error;
        run.lab_message = is_lab(lab) ? "labs/" + lab + ".cpp does not compile" : "the labs do not build together";
        result.compile_errors = first_compiler_errors(built.log, paths_);
    }

    // The outcome of a test that is not run.
    static TestOutcome not_run(const std::string& lab, const LabRun& run, std::size_t t, const std::optional<std::string>& reason) {
        TestOutcome outcome;
        outcome.lab = lab;
        outcome.name = run.names[t];
        outcome.status = run.lab_status.value_or(Status::skipped);
        outcome.message = run.lab_status ? run.lab_message : reason.value_or("no rule of this lab could run");
        return outcome;
    }

    // The test names from the lab's tests linked with the reference alone (list_<lab>), for a lab whose own program cannot list them.
    std::vector<std::string> names_from_reference(const TestProgram& lister) {
        const std::string target = lister.program.filename().string();
        const BuildStep built = build_targets(folder_, {target});
        if (!built.ok) throw GraderFailure("building " + target + " failed:\n" + first_compiler_errors(built.log, paths_));
        std::string problem;
        std::vector<std::string> names = list_tests(lister, problem);
        if (!problem.empty()) throw GraderFailure("the reference tests do not list: " + problem);
        return names;
    }

    const GradingSetup& setup_;
    const std::vector<std::string>& missing_;
    BuildFolder folder_;
    std::vector<std::pair<std::string, std::string>> paths_;
    RuleFailures finished_;
    Sandbox sandbox_;
};

} // namespace

std::vector<std::pair<std::string, std::string>> shown_paths(const GradingSetup& setup) {
    std::vector<std::pair<std::string, std::string>> paths = {{(setup.out / "labs").string() + "/", "labs/"},
                                                              {setup.out.string() + "/", ""},
                                                              {setup.build.string() + "/", "build/"},
                                                              {setup.instructor_tree.string() + "/", ""}};
    // Imported objects named in a link error look as if the grading build had compiled them.
    if (!setup.prebuilt.empty()) paths.emplace_back(setup.prebuilt.string() + "/", "build/");
    return paths;
}

GradingResult grade_submission(const GradingSetup& setup) {
    std::vector<std::string> labs;
    for (const LabRubric& lab : setup.rubric.labs)
        if (is_lab(lab.lab)) labs.push_back(lab.lab);
    const std::vector<std::string> missing =
        copy_lab_files(setup.submission_labs, setup.instructor_tree / "labs", setup.out / "labs", labs);
    fs::remove_all(setup.out / "tests");

    LabGrader grader(setup, missing);
    grader.build_shared_parts();
    fs::create_directories(setup.out / "tests");
    GradingResult result;
    result.isolation = grader.fence_tests().description;
    const FileRecord relied_on = relied_on_files(setup);
    for (const LabRubric& lab : setup.rubric.labs) {
        result.labs.push_back(grader.grade(lab));
        if (const std::optional<std::string> change = relied_on.first_change(relied_on_files(setup)))
            throw GraderFailure("while " + lab.lab + " was tested, a file the grader relies on changed: " + *change +
                                ". Grading stopped so that no grade depends on it; restore the file (git checkout, make build) and grade again.");
        result.score_cents += result.labs.back().score_cents;
        result.max_cents += result.labs.back().max_cents;
    }
    return result;
}

} // namespace whitted::grade
