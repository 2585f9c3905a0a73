// The grading rubric (instructor/rubric.json): points per lab and per group of
// tests, image partial credit, and prerequisites.
//
// The file, where it is parsed (every key, with what it means):
//   {
//     "image_ramp": RAMP,                 optional default for image tests (below)
//     "labs": [ LAB, ... ]                graded in this order
//   }
//   LAB:  { "lab": "03_blinn_phong" | "integration", "title": "Lab 3: Blinn-Phong", "rules": [ RULE, ... ] }
//   RULE: { "id": "unit",                 unique within the lab; others name it "unit" or "03_blinn_phong:unit"
//           "tests": ["Shading.*", ...],  exact "Suite.Test" names, or globs with * and ?; a pattern
//                                         without a dot means the whole suite ("Hidden*" = "Hidden*.*")
//           "exclude": ["Hidden*"],       optional: patterns of tests the rule leaves to later rules
//           "points": 6,                  split evenly over the tests the rule matches (hundredths), or
//           "points_each": 0.5,           ... the same points for every matched test
//           "requires": ["unit"],         optional: rules whose tests must all pass first, else this
//                                         rule's tests are skipped with the reason; "*:unit" names
//                                         the rule "unit" of every lab listed before this one
//           "optional": true,             optional: may match no test; its points then go to the lab's
//                                         other rules, in proportion (hidden tests that are not written yet)
//           "image": true | RAMP }        optional: the tests compare images; partial credit on the ramp
//   RAMP: { "full_below": 0.02, "zero_at": 0.10, "most": 0.75 }
//         a failing image test with a fraction f of failing pixels earns
//         most * clamp((zero_at - f) / (zero_at - full_below), 0, 1) of its points.
// Each test counts for the first rule (in file order) that matches it; tests
// that no rule matches are run and reported, for 0 points.
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace whitted::grade {

/// A problem with the rubric file; the message starts with "file:line: ".
struct RubricError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct ImageRamp {
    double full_below = 0.02;  // the image gate's own limit on failing pixels
    double zero_at = 0.10;
    double most = 0.75; // a failing image never earns more than this share
    /// The share of the points for a failing image with this fraction of failing pixels.
    double credit(double failing_fraction) const;
};

struct Rule {
    std::string id;
    std::vector<std::string> tests;   // patterns
    std::vector<std::string> exclude; // patterns
    long points_cents = 0;          // total, split over the matched tests
    std::optional<long> each_cents; // or this for each matched test
    std::vector<std::string> requires_rules; // "unit" or "lab:unit", resolved to "lab:unit"
    bool optional = false;
    std::optional<ImageRamp> image;
    int line = 0; // in the rubric file, for messages
};

struct LabRubric {
    std::string lab;
    std::string title;
    std::vector<Rule> rules;
    int line = 0;
};

struct Rubric {
    std::string file; // as given, for messages
    ImageRamp image_ramp;
    std::vector<LabRubric> labs;
};

/// Parses and checks the rubric text; `known_labs` are the lab names it may use.
Rubric parse_rubric(const std::string& text, const std::string& file_name, const std::vector<std::string>& known_labs);

/// Reads and parses a rubric file.
Rubric load_rubric(const std::filesystem::path& file, const std::vector<std::string>& known_labs);

/// Whether a test name matches a rubric pattern.
bool pattern_matches(const std::string& pattern, const std::string& test_name);

/// Whether the rule takes the test: a pattern matches it and no exclusion does.
bool rule_matches(const Rule& rule, const std::string& test_name);

/// Whether a pattern names exactly one test (no wildcards, has a dot).
bool is_exact_name(const std::string& pattern);

} // namespace whitted::grade
