#include "grader/scoring.hpp"
#include "grader/text.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace whitted::grade {
namespace {

// Splits `cents` over `count` shares: equal, the first ones one hundredth more when it does not divide.
std::vector<long> split_evenly(long cents, std::size_t count) {
    std::vector<long> shares(count, count ? cents / static_cast<long>(count) : 0);
    for (std::size_t i = 0; count && i < static_cast<std::size_t>(cents % static_cast<long>(count)); ++i) ++shares[i];
    return shares;
}

// Splits `cents` over the weights in proportion (largest remainders first, ties to the earlier).
std::vector<long> split_in_proportion(long cents, const std::vector<long>& weights) {
    const long total = std::accumulate(weights.begin(), weights.end(), 0L);
    std::vector<long> shares(weights.size(), 0);
    if (total <= 0) return shares;
    std::vector<std::pair<long, std::size_t>> remainders;
    long given = 0;
    for (std::size_t i = 0; i < weights.size(); ++i) {
        shares[i] = cents * weights[i] / total;
        given += shares[i];
        remainders.push_back({-(cents * weights[i] % total), i});
    }
    std::sort(remainders.begin(), remainders.end());
    for (std::size_t k = 0; given < cents; ++k, ++given) ++shares[remainders[k % remainders.size()].second];
    return shares;
}

} // namespace

LabPlan plan_lab(const LabRubric& lab, const std::vector<std::string>& tests) {
    LabPlan plan;
    plan.rule_of_test.assign(tests.size(), nullptr);
    plan.max_cents.assign(tests.size(), 0);
    for (std::size_t t = 0; t < tests.size(); ++t)
        for (const Rule& rule : lab.rules) {
            if (rule_matches(rule, tests[t])) {
                plan.rule_of_test[t] = &rule;
                break;
            }
        }

    // The rule points, with those of optional rules that matched nothing moved to the others.
    std::vector<long> rule_cents;
    long moved = 0;
    std::vector<std::size_t> counts(lab.rules.size(), 0);
    for (std::size_t r = 0; r < lab.rules.size(); ++r) {
        const Rule& rule = lab.rules[r];
        counts[r] = std::count(plan.rule_of_test.begin(), plan.rule_of_test.end(), &rule);
        for (const std::string& pattern : rule.tests) {
            const bool any = std::any_of(tests.begin(), tests.end(), [&](const std::string& t) { return pattern_matches(pattern, t); });
            if (any || rule.optional) continue;
            plan.notes.push_back(is_exact_name(pattern)
                                     ? "rubric line " + std::to_string(rule.line) + ": unknown test name \"" + pattern + "\" in rule " + rule.id
                                     : "rubric line " + std::to_string(rule.line) + ": \"" + pattern + "\" in rule " + rule.id + " matches no test");
        }
        const bool empty = counts[r] == 0;
        if (empty && rule.optional) moved += rule.points_cents;
        else if (empty && !rule.each_cents && rule.points_cents > 0)
            plan.notes.push_back("rule " + rule.id + " matches no test: its " + format_points(rule.points_cents) + " points are lost from the maximum");
        rule_cents.push_back(empty || rule.each_cents ? 0 : rule.points_cents);
    }
    if (moved > 0) {
        const std::vector<long> extra = split_in_proportion(moved, rule_cents);
        for (std::size_t r = 0; r < rule_cents.size(); ++r) rule_cents[r] += extra[r];
        plan.notes.push_back("optional rules without tests: their " + format_points(moved) + " points went to the lab's other rules");
    }

    for (std::size_t r = 0; r < lab.rules.size(); ++r) {
        const Rule& rule = lab.rules[r];
        const std::vector<long> shares = split_evenly(rule_cents[r], counts[r]);
        std::size_t k = 0;
        for (std::size_t t = 0; t < tests.size(); ++t)
            if (plan.rule_of_test[t] == &rule) plan.max_cents[t] = rule.each_cents ? *rule.each_cents : shares[k++];
    }
    for (std::size_t t = 0; t < tests.size(); ++t)
        if (!plan.rule_of_test[t]) plan.notes.push_back("test " + tests[t] + " matches no rubric rule: run, for 0 points");
    return plan;
}

std::vector<std::size_t> pass_order(const LabRubric& lab, const LabPlan& plan, const std::vector<std::string>& tests, Pass pass) {
    const auto in_pass = [&](std::size_t t) { return is_hidden(tests[t]) == (pass == Pass::hidden); };
    std::vector<std::size_t> order;
    for (const Rule& rule : lab.rules)
        for (std::size_t t = 0; t < tests.size(); ++t)
            if (plan.rule_of_test[t] == &rule && in_pass(t)) order.push_back(t);
    for (std::size_t t = 0; t < tests.size(); ++t)
        if (!plan.rule_of_test[t] && in_pass(t)) order.push_back(t);
    return order;
}

std::set<std::string> rules_in_pass(const LabRubric& lab, const LabPlan& plan, const std::vector<std::string>& tests, Pass pass) {
    std::set<std::string> rules;
    for (const std::size_t t : pass_order(lab, plan, tests, pass))
        if (plan.rule_of_test[t]) rules.insert(lab.lab + ":" + plan.rule_of_test[t]->id);
    return rules;
}

void check_passes(const Rubric& rubric, const std::set<std::string>& visible, const std::set<std::string>& hidden) {
    for (const LabRubric& lab : rubric.labs)
        for (const Rule& rule : lab.rules)
            for (const std::string& required : rule.requires_rules)
                if (visible.count(lab.lab + ":" + rule.id) && hidden.count(required))
                    throw RubricError(rubric.file + ":" + std::to_string(rule.line) + ": rule " + lab.lab + ":" + rule.id +
                                      " has visible tests and requires " + required +
                                      ", which has hidden tests: hidden tests run after every visible test (so that their "
                                      "time cannot decide which visible tests run), and a visible test cannot wait for them");
}

std::optional<std::string> unmet_prerequisite(const Rule& rule, const RuleFailures& finished) {
    std::string unmet;
    const std::vector<Failure>* first = nullptr;
    for (const std::string& required : rule.requires_rules) {
        const auto found = finished.find(required);
        if (found == finished.end() || found->second.empty()) continue;
        unmet += (unmet.empty() ? "" : ", ") + required;
        if (!first) first = &found->second;
    }
    if (!first) return std::nullopt;
    std::string reason = "needs every test of " + unmet + " to pass first; " + first->front().name + ": " +
                         std::string(status_label(first->front().status));
    if (first->size() > 1) reason += " (and " + std::to_string(first->size() - 1) + " more)";
    return reason;
}

long score_test(const TestOutcome& outcome, long max_cents, const Rule* rule, const ImageRamp& default_ramp) {
    if (outcome.status == Status::passed) return max_cents;
    if (outcome.status != Status::failed || !outcome.image) return 0;
    const ImageRamp& ramp = rule && rule->image ? *rule->image : default_ramp;
    return std::lround(max_cents * ramp.credit(outcome.image->failing_fraction));
}

} // namespace whitted::grade
