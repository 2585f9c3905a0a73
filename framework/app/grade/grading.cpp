#include "grade/grading.hpp"
#include "grade/builder.hpp"
#include "grade/submission.hpp"
#include "grade/test_runner.hpp"
#include "grade/text.hpp"

#include <algorithm>
#include <optional>

namespace whitted::grade {
namespace {

namespace fs = std::filesystem;

bool is_lab(const std::string& name) { return name != "integration"; }

class LabGrader {
public:
    LabGrader(const GradingSetup& setup, const std::vector<std::string>& missing)
        : setup_(setup), missing_(missing), folder_{setup.instructor_tree, setup.build, setup.out / "labs", setup.jobs},
          paths_(shown_paths(setup)) {}

    void build_shared_parts() {
        setup_.progress("configuring " + setup_.build.string());
        const BuildStep configured = configure(folder_);
        if (!configured.ok) throw GraderFailure("configuring the instructor tree failed:\n" + trim_text(configured.log, 40));
        std::vector<std::string> targets = {"test_support"};
        for (const LabRubric& lab : setup_.rubric.labs) {
            if (!is_lab(lab.lab)) continue;
            targets.push_back("reference_" + lab.lab);
            targets.push_back("labtests_" + lab.lab);
        }
        setup_.progress("building the framework, the reference and the tests");
        const BuildStep built = build_targets(folder_, targets);
        if (!built.ok) throw GraderFailure("building the instructor tree failed:\n" + first_compiler_errors(built.log, paths_));
    }

    LabResult grade(const LabRubric& lab) {
        LabResult result;
        result.lab = lab.lab;
        result.title = lab.title;
        std::vector<std::optional<std::string>> unmet;
        for (const Rule& rule : lab.rules) unmet.push_back(unmet_prerequisite(rule, finished_));
        const bool missing = std::find(missing_.begin(), missing_.end(), lab.lab) != missing_.end();
        const bool any_runs = !missing && std::any_of(unmet.begin(), unmet.end(), [](const auto& u) { return !u; });

        // A status for the whole lab when its program cannot run.
        std::optional<Status> lab_status;
        std::string lab_message;
        const TestProgram program{lab.lab, setup_.build / "tests" / ("grade_" + lab.lab), setup_.out / "tests" / lab.lab,
                                  setup_.test_limits, paths_};
        if (missing) {
            lab_status = Status::missing;
            lab_message = "the submission has no " + lab.lab + ".cpp";
        } else if (any_runs) {
            setup_.progress("building " + lab.lab);
            BuildStep built = is_lab(lab.lab) ? build_targets(folder_, {"student_" + lab.lab}) : BuildStep{true, {}};
            if (built.ok) built = build_targets(folder_, {"grade_" + lab.lab});
            if (!built.ok) {
                lab_status = Status::compile_error;
                result.compile_errors = first_compiler_errors(built.log, paths_);
                lab_message = is_lab(lab.lab) ? "labs/" + lab.lab + ".cpp does not compile" : "the labs do not build together";
            }
        }
        std::vector<std::string> names;
        if (any_runs && !lab_status) {
            std::string problem;
            names = list_tests(program, problem);
            if (names.empty()) {
                lab_status = Status::crash;
                lab_message = "the test program did not start: " + split_lines(problem).front();
            }
        }
        if (names.empty()) names = names_from_reference(lab.lab);

        const LabPlan plan = plan_lab(lab, names);
        result.notes = plan.notes;
        result.tests.resize(names.size());
        auto grade_test = [&](std::size_t t, const std::optional<std::string>& reason) {
            TestOutcome outcome;
            outcome.lab = lab.lab;
            outcome.name = names[t];
            if (lab_status) {
                outcome.status = *lab_status;
                outcome.message = lab_message;
            } else if (reason || !any_runs) {
                outcome.status = Status::skipped;
                outcome.message = "skipped: " + reason.value_or("no rule of this lab could run");
            } else {
                outcome = run_test(program, names[t]);
            }
            const Rule* rule = plan.rule_of_test[t];
            const long score = score_test(outcome, plan.max_cents[t], rule, setup_.rubric.image_ramp);
            result.tests[t] = ScoredTest{std::move(outcome), rule ? rule->id : "", plan.max_cents[t], score};
        };
        for (std::size_t r = 0; r < lab.rules.size(); ++r) {
            std::vector<Failure>& failures = finished_[lab.lab + ":" + lab.rules[r].id];
            for (std::size_t t = 0; t < names.size(); ++t) {
                if (plan.rule_of_test[t] != &lab.rules[r]) continue;
                grade_test(t, unmet[r]);
                if (result.tests[t].outcome.status != Status::passed) failures.push_back({names[t], result.tests[t].outcome.status});
            }
        }
        for (std::size_t t = 0; t < names.size(); ++t)
            if (!plan.rule_of_test[t]) grade_test(t, std::nullopt);
        for (const ScoredTest& test : result.tests) {
            result.score_cents += test.score_cents;
            result.max_cents += test.max_cents;
            if (test.outcome.status != Status::passed) setup_.progress("  " + test.outcome.name + ": " + std::string(status_label(test.outcome.status)));
        }
        return result;
    }

private:
    // The lab's test names from its tests linked with the reference alone, for a lab whose own program cannot list them.
    std::vector<std::string> names_from_reference(const std::string& lab) {
        const BuildStep built = build_targets(folder_, {"list_" + lab});
        if (!built.ok) throw GraderFailure("building list_" + lab + " failed:\n" + first_compiler_errors(built.log, paths_));
        std::string problem;
        const TestProgram lister{lab, setup_.build / "tests" / ("list_" + lab), setup_.out / "tests" / lab, setup_.test_limits, paths_};
        std::vector<std::string> names = list_tests(lister, problem);
        if (!problem.empty()) throw GraderFailure("the reference tests of " + lab + " do not list: " + problem);
        return names;
    }

    const GradingSetup& setup_;
    const std::vector<std::string>& missing_;
    BuildFolder folder_;
    std::vector<std::pair<std::string, std::string>> paths_;
    RuleFailures finished_;
};

} // namespace

std::vector<std::pair<std::string, std::string>> shown_paths(const GradingSetup& setup) {
    return {{(setup.out / "labs").string() + "/", "labs/"},
            {setup.out.string() + "/", ""},
            {setup.build.string() + "/", "build/"},
            {setup.instructor_tree.string() + "/", ""}};
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
    GradingResult result;
    for (const LabRubric& lab : setup.rubric.labs) {
        result.labs.push_back(grader.grade(lab));
        result.score_cents += result.labs.back().score_cents;
        result.max_cents += result.labs.back().max_cents;
    }
    return result;
}

} // namespace whitted::grade
