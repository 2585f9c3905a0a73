// The rubric: what it accepts, how it says what is wrong, and how it shares out points.
#include "grader/rubric.hpp"
#include "grader/scoring.hpp"
#include "grader/submission.hpp"

#include <gtest/gtest.h>

#include <numeric>

using namespace whitted::grade;

namespace {

const std::vector<std::string> kLabs = {"01_ray_casting", "integration"};

std::string error_of(const std::string& text) {
    try {
        parse_rubric(text, "rubric.json", kLabs);
    } catch (const RubricError& error) {
        return error.what();
    }
    return "no error";
}

const char* kValid = R"({
  "labs": [
    { "lab": "01_ray_casting", "title": "Lab 1",
      "rules": [
        { "id": "unit", "tests": ["*"], "exclude": ["Hidden*", "Lab1Image"], "points": 10 },
        { "id": "hidden", "tests": ["Hidden*"], "points": 2, "optional": true },
        { "id": "image", "tests": ["Lab1Image"], "points": 4, "requires": ["unit"], "image": { "most": 0.5 } }
      ] },
    { "lab": "integration", "title": "Integration",
      "rules": [ { "id": "all", "tests": ["Integration.*"], "points_each": 1.5, "requires": ["01_ray_casting:unit"] } ] }
  ]
})";

long total(const LabPlan& plan) { return std::accumulate(plan.max_cents.begin(), plan.max_cents.end(), 0L); }

} // namespace

TEST(Rubric, ValidFileParsesWithResolvedPrerequisites) {
    const Rubric rubric = parse_rubric(kValid, "rubric.json", kLabs);
    ASSERT_EQ(rubric.labs.size(), 2u);
    EXPECT_EQ(rubric.labs[0].rules[2].requires_rules, std::vector<std::string>{"01_ray_casting:unit"});
    EXPECT_EQ(rubric.labs[0].rules[2].line, 7);
    ASSERT_TRUE(rubric.labs[0].rules[2].image.has_value());
    EXPECT_EQ(rubric.labs[0].rules[2].image->most, 0.5);
    EXPECT_EQ(rubric.labs[1].rules[0].each_cents, 150);
}

TEST(Rubric, ErrorsNameTheFileAndLine) {
    std::string text = kValid;
    text.replace(text.find("\"points\": 4"), 11, "\"point\": 4");
    EXPECT_EQ(error_of(text).rfind("rubric.json:7: lab 01_ray_casting, rule \"image\" has an unknown key \"point\"", 0), 0u) << error_of(text);
    EXPECT_EQ(error_of("{ \"labs\": [ }").rfind("rubric.json:1: not valid JSON", 0), 0u) << error_of("{ \"labs\": [ }");
}

TEST(Rubric, ErrorsForWrongContent) {
    auto with = [](const std::string& from, const std::string& to) {
        std::string text = kValid;
        text.replace(text.find(from), from.size(), to);
        return error_of(text);
    };
    EXPECT_NE(with("\"01_ray_casting\", \"title\"", "\"07_caustics\", \"title\"").find("unknown lab \"07_caustics\""), std::string::npos);
    EXPECT_NE(with("\"requires\": [\"unit\"]", "\"requires\": [\"image\"]").find("not a rule listed before it"), std::string::npos);
    EXPECT_NE(with("\"points\": 10", "\"points\": 10, \"points_each\": 1").find("exactly one of"), std::string::npos);
    EXPECT_NE(with("\"points\": 10", "\"points\": 1.005").find("two decimals"), std::string::npos);
    EXPECT_NE(with("\"id\": \"hidden\"", "\"id\": \"unit\"").find("defined twice"), std::string::npos);
    EXPECT_NE(with("{ \"most\": 0.5 }", "{ \"zero_at\": 0.001 }").find("full_below < zero_at"), std::string::npos);
    EXPECT_NE(error_of(R"({"labs": [{"lab": "integration", "title": "I", "rules": [{"id": "a", "tests": ["*"], "points": 1}]}]})")
                  .find("no entry for lab 01_ray_casting"),
              std::string::npos);
}

// "*:unit" is the rule "unit" of every lab before: a new lab needs no edit of the integration tier.
TEST(Rubric, AStarPrerequisiteNamesThatRuleOfEveryEarlierLab) {
    std::string text = kValid;
    const std::string from = "\"requires\": [\"01_ray_casting:unit\"]";
    text.replace(text.find(from), from.size(), "\"requires\": [\"*:unit\"]");
    const Rubric rubric = parse_rubric(text, "rubric.json", kLabs);
    EXPECT_EQ(rubric.labs[1].rules[0].requires_rules, std::vector<std::string>{"01_ray_casting:unit"});
    text.replace(text.find("\"*:unit\""), 8, "\"*:units\"");
    EXPECT_NE(error_of(text).find("lab 01_ray_casting has no rule \"units\""), std::string::npos) << error_of(text);
}

// The project rubric's integration tier requires every lab's unit tests, whatever the labs.
TEST(Rubric, TheProjectIntegrationRequiresEveryLabsUnitRule) {
    std::vector<std::string> labs = lab_names();
    labs.push_back("integration");
    const Rubric rubric = load_rubric(std::string(WHITTED_SOURCE_DIR) + "/instructor/rubric.json", labs);
    std::vector<std::string> expected;
    for (std::size_t i = 0; i + 1 < labs.size(); ++i) expected.push_back(labs[i] + ":unit");
    EXPECT_EQ(rubric.labs.back().rules[0].requires_rules, expected);
}

// The rubric grades the labs of the lab table, in its order, then the integration tier.
TEST(Rubric, TheProjectRubricIsValidAndWorthOneHundredPoints) {
    std::vector<std::string> labs = lab_names();
    labs.push_back("integration");
    const Rubric rubric = load_rubric(std::string(WHITTED_SOURCE_DIR) + "/instructor/rubric.json", labs);
    ASSERT_EQ(rubric.labs.size(), labs.size());
    for (std::size_t i = 0; i < labs.size(); ++i) EXPECT_EQ(rubric.labs[i].lab, labs[i]);
    long cents = 0;
    for (const LabRubric& lab : rubric.labs)
        for (const Rule& rule : lab.rules) cents += rule.points_cents;
    EXPECT_EQ(cents, 10000);
}

// A lab's pictures, visible and hidden, are graded only once its unit tests pass: a picture made by
// lab files that answer with constants (which fail every unit test) can come close to the reference
// (one point light in place of an area light, say) and must not earn partial credit.
TEST(Rubric, TheProjectRubricGradesEveryPictureOnlyAfterTheUnitTests) {
    std::vector<std::string> labs = lab_names();
    labs.push_back("integration");
    const Rubric rubric = load_rubric(std::string(WHITTED_SOURCE_DIR) + "/instructor/rubric.json", labs);
    for (const LabRubric& lab : rubric.labs) {
        if (lab.lab == "integration") continue;
        int pictures = 0;
        for (const Rule& rule : lab.rules) {
            const bool hidden = rule.tests == std::vector<std::string>{"Hidden*"};
            if (hidden) {
                EXPECT_FALSE(rule.exclude.empty()) << lab.lab << ": the hidden rule must leave the hidden picture to a rule that requires unit";
            }
            if (!rule.image) continue;
            ++pictures;
            EXPECT_EQ(rule.requires_rules, std::vector<std::string>{lab.lab + ":unit"}) << lab.lab << ", rule " << rule.id;
        }
        EXPECT_EQ(pictures, 2) << lab.lab << ": its picture and its hidden picture";
    }
}

TEST(Rubric, PatternsAreGlobsAndABareSuiteMeansAllItsTests) {
    EXPECT_TRUE(pattern_matches("Sphere", "Sphere.Hits"));
    EXPECT_FALSE(pattern_matches("Sphere", "SphereX.Hits"));
    EXPECT_TRUE(pattern_matches("Hidden*", "HiddenShading.Highlight"));
    EXPECT_TRUE(pattern_matches("*.Hit?", "Sphere.Hits"));
    EXPECT_TRUE(pattern_matches("Sphere.Hits", "Sphere.Hits"));
    EXPECT_FALSE(pattern_matches("Sphere.Hit", "Sphere.Hits"));
    EXPECT_TRUE(is_exact_name("Sphere.Hits"));
    EXPECT_FALSE(is_exact_name("Sphere.*"));
}

TEST(Scoring, PointsAreSplitInHundredthsAndOptionalRulesPassTheirsOn) {
    const Rubric rubric = parse_rubric(kValid, "rubric.json", kLabs);
    const LabPlan plan = plan_lab(rubric.labs[0], {"A.One", "A.Two", "B.Three", "Lab1Image.Matches"});
    // The optional rule's 2 points go 10:4 to the others: unit 10 + 1.43 = 11.43 over three tests, image 4 + 0.57.
    EXPECT_EQ(plan.max_cents, (std::vector<long>{381, 381, 381, 457}));
    EXPECT_EQ(total(plan), 1600);
    ASSERT_EQ(plan.notes.size(), 1u);
    EXPECT_NE(plan.notes[0].find("2.00 points went to the lab's other rules"), std::string::npos);
}

TEST(Scoring, UnknownNamesAndUnmatchedTestsAreReported) {
    Rubric rubric = parse_rubric(kValid, "rubric.json", kLabs);
    const LabPlan plan = plan_lab(rubric.labs[1], {"Integration.Classic", "Other.Test"});
    EXPECT_EQ(plan.max_cents, (std::vector<long>{150, 0}));
    EXPECT_EQ(plan.rule_of_test[1], nullptr);
    ASSERT_EQ(plan.notes.size(), 1u);
    EXPECT_NE(plan.notes[0].find("Other.Test matches no rubric rule"), std::string::npos);

    rubric.labs[1].rules[0].tests = {"Integration.Clasic"};
    const LabPlan typo = plan_lab(rubric.labs[1], {"Integration.Classic"});
    EXPECT_NE(typo.notes.at(0).find("unknown test name \"Integration.Clasic\""), std::string::npos);
}

TEST(Scoring, PrerequisitesSkipWithTheFirstFailureAsReason) {
    const Rubric rubric = parse_rubric(kValid, "rubric.json", kLabs);
    const Rule& image = rubric.labs[0].rules[2];
    EXPECT_FALSE(unmet_prerequisite(image, {{"01_ray_casting:unit", {}}}).has_value());
    const RuleFailures failures = {{"01_ray_casting:unit", {{"Sphere.Hits", Status::crash}, {"Plane.Hits", Status::failed}}}};
    EXPECT_EQ(unmet_prerequisite(image, failures).value(),
              "needs every test of 01_ray_casting:unit to pass first; Sphere.Hits: crash (and 1 more)");
    Rule integration = image;
    integration.requires_rules = {"01_ray_casting:unit", "02_shadows:unit", "03_blinn_phong:unit"};
    const RuleFailures several = {{"01_ray_casting:unit", {}},
                                  {"02_shadows:unit", {{"SpawnRay.Grazing", Status::not_implemented}}},
                                  {"03_blinn_phong:unit", {{"Shading.Highlight", Status::compile_error}}}};
    EXPECT_EQ(unmet_prerequisite(integration, several).value(),
              "needs every test of 02_shadows:unit, 03_blinn_phong:unit to pass first; SpawnRay.Grazing: not implemented");
}

TEST(Scoring, FailingImagesEarnPartialCreditOnTheRamp) {
    const Rubric rubric = parse_rubric(kValid, "rubric.json", kLabs);
    const Rule& image = rubric.labs[0].rules[2]; // most 0.5, full_below 0.02 (the default), zero_at 0.10
    TestOutcome outcome;
    outcome.status = Status::failed;
    outcome.image = ImageNumbers{};
    outcome.image->failing_fraction = 0.06; // half way down the ramp: (0.10 - 0.06) / (0.10 - 0.02)
    EXPECT_EQ(score_test(outcome, 400, &image, rubric.image_ramp), 100);
    outcome.image->failing_fraction = 0.5;
    EXPECT_EQ(score_test(outcome, 400, &image, rubric.image_ramp), 0);
    outcome.status = Status::passed;
    EXPECT_EQ(score_test(outcome, 400, &image, rubric.image_ramp), 400);
    outcome.status = Status::crash;
    EXPECT_EQ(score_test(outcome, 400, &image, rubric.image_ramp), 0);
}

// Hidden tests run in a pass of their own after every visible test, so that their time cannot decide which visible
// tests the budget leaves unrun; within a pass, rule by rule in the rubric's order, unmatched tests last.
TEST(Scoring, HiddenTestsRunInAPassAfterTheVisibleOnes) {
    const Rubric rubric = parse_rubric(kValid, "rubric.json", kLabs);
    const std::vector<std::string> tests = {"HiddenSphere.Far", "Lab1Image.Matches", "Sphere.Hits", "HiddenLab1Image.Matches",
                                            "Plane.Hits"};
    const LabPlan plan = plan_lab(rubric.labs[0], tests);
    EXPECT_EQ(pass_order(rubric.labs[0], plan, tests, Pass::visible), (std::vector<std::size_t>{2, 4, 1}));
    EXPECT_EQ(pass_order(rubric.labs[0], plan, tests, Pass::hidden), (std::vector<std::size_t>{0, 3}));
    EXPECT_EQ(rules_in_pass(rubric.labs[0], plan, tests, Pass::visible), (std::set<std::string>{"01_ray_casting:unit", "01_ray_casting:image"}));
    EXPECT_EQ(rules_in_pass(rubric.labs[0], plan, tests, Pass::hidden), std::set<std::string>{"01_ray_casting:hidden"});
    // A test no rule matches runs last in its own pass.
    const std::vector<std::string> integration = {"HiddenOther.Test", "Other.Test", "Integration.Classic"};
    const LabPlan unmatched = plan_lab(rubric.labs[1], integration);
    EXPECT_EQ(pass_order(rubric.labs[1], unmatched, integration, Pass::visible), (std::vector<std::size_t>{2, 1}));
    EXPECT_EQ(pass_order(rubric.labs[1], unmatched, integration, Pass::hidden), std::vector<std::size_t>{0});
}

// A visible test cannot wait for hidden ones: a rubric whose rule with visible tests requires one with hidden tests is
// refused, naming the rule; the project's rubric has none.
TEST(Scoring, AVisibleRuleCannotRequireAHiddenOne) {
    std::string text = kValid;
    text.replace(text.find("\"requires\": [\"unit\"]"), 20, "\"requires\": [\"hidden\"]");
    const Rubric rubric = parse_rubric(text, "rubric.json", kLabs);
    const std::set<std::string> visible = {"01_ray_casting:unit", "01_ray_casting:image"}, hidden = {"01_ray_casting:hidden"};
    try {
        check_passes(rubric, visible, hidden);
        ADD_FAILURE() << "no error";
    } catch (const RubricError& error) {
        EXPECT_EQ(std::string(error.what()).rfind("rubric.json:7: rule 01_ray_casting:image has visible tests and requires "
                                                  "01_ray_casting:hidden, which has hidden tests",
                                                  0),
                  0u)
            << error.what();
    }
    EXPECT_NO_THROW(check_passes(parse_rubric(kValid, "rubric.json", kLabs), visible, hidden));
    EXPECT_NO_THROW(check_passes(rubric, {"01_ray_casting:unit"}, hidden)) << "the image rule has no visible test here";
}
