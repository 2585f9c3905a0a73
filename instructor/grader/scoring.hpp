// How the rubric turns test outcomes into points: which rule each test counts
// for, its share of the rule's points, prerequisites, and image partial credit.
#pragma once

#include "grader/outcome.hpp"
#include "grader/rubric.hpp"

#include <map>
#include <optional>
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
