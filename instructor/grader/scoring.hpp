// How the rubric turns test outcomes into points: which rule each test counts
// for, its share of the rule's points, prerequisites, and image partial credit.
#pragma once

#include "grader/outcome.hpp"
#include "grader/rubric.hpp"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace whitted::grade {

/// How the rubric applies to the tests one lab's program lists.
struct LabPlan {
    std::vector<const Rule*> rule_of_test; // per test, in listing order; nullptr for unmatched tests
    std::vector<long> max_cents;           // per test
    std::vector<std::string> notes;        // unknown exact names, empty globs, unmatched tests, moved points
};

/// Matches the tests to the lab's rules and shares out the points (in hundredths).
LabPlan plan_lab(const LabRubric& lab, const std::vector<std::string>& tests);

/// The two passes of a grading: every lab's visible tests, then every lab's
/// hidden tests (suites named Hidden*). Why: the student's code chooses how
/// long a hidden test takes, maybe from its hidden inputs; were it run before a
/// visible test, that time could decide which visible tests the grading's time
/// budget leaves "not run" (results.json names them), several bits of the hidden
/// inputs instead of the one bit per hidden test its pass or fail tells. Run
/// last, a hidden test's time can cut short only other hidden tests, whose
/// student sees passed or failed.
enum class Pass { visible, hidden };

/// The lab's tests (indices into `tests`) that run in `pass`, in the order they
/// run: rule by rule in the rubric's order (each rule's in listing order), then
/// those no rule matches.
std::vector<std::size_t> pass_order(const LabRubric& lab, const LabPlan& plan, const std::vector<std::string>& tests, Pass pass);

/// The rules ("lab:id") of the lab that have a test in `pass`.
std::set<std::string> rules_in_pass(const LabRubric& lab, const LabPlan& plan, const std::vector<std::string>& tests, Pass pass);

/// Throws RubricError ("file:line: ...") when a rule with a visible test
/// requires a rule with a hidden test: that visible test would have to wait for
/// the hidden pass. `visible` and `hidden` are rules_in_pass over every lab.
void check_passes(const Rubric& rubric, const std::set<std::string>& visible, const std::set<std::string>& hidden);

/// A test that did not pass, and how it ended.
struct Failure {
    std::string name;
    Status status;
};
/// The tests of each finished rule ("lab:id") that did not pass.
using RuleFailures = std::map<std::string, std::vector<Failure>>;

/// A test with its points.
struct ScoredTest {
    TestOutcome outcome;
    std::string rule; // the rubric rule's id; empty when no rule matched
    long max_cents = 0;
    long score_cents = 0;
    bool image_test = false; // its rule compares images, or it wrote image numbers
};

/// Why the rule's tests must be skipped, or nothing when every prerequisite passed.
std::optional<std::string> unmet_prerequisite(const Rule& rule, const RuleFailures& finished);

/// The points a test earns: all for a pass, a share on the image ramp for a
/// failing image comparison (the rule's ramp, else the default), else none.
long score_test(const TestOutcome& outcome, long max_cents, const Rule* rule, const ImageRamp& default_ramp);

} // namespace whitted::grade
