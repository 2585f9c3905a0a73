#include "grader/rubric.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace whitted::grade {
namespace {

using nlohmann::json;

// Finds where things are in the rubric text, for messages (nlohmann's values carry no positions).
class Locator {
public:
    Locator(const std::string& text, std::string file) : text_(text), file_(std::move(file)) {}

    // The offset of `"key": "value"` (or of `"key":` for an empty value) at or after `from`, else `from`.
    std::size_t find(const std::string& key, const std::string& value, std::size_t from) const {
        std::string quoted_value;
        if (!value.empty())
            quoted_value.append("\"").append(std::regex_replace(value, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)")).append("\"");
        const std::regex entry("\"" + key + "\"\\s*:\\s*" + quoted_value);
        std::smatch match;
        const auto begin = text_.begin() + static_cast<std::ptrdiff_t>(std::min(from, text_.size()));
        if (std::regex_search(begin, text_.end(), match, entry)) return from + static_cast<std::size_t>(match.position(0));
        return from;
    }
    int line_at(std::size_t offset) const {
        return 1 + static_cast<int>(std::count(text_.begin(), text_.begin() + static_cast<std::ptrdiff_t>(std::min(offset, text_.size())), '\n'));
    }
    [[noreturn]] void fail(std::size_t offset, const std::string& message) const {
        throw RubricError(file_ + ":" + std::to_string(line_at(offset)) + ": " + message);
    }

private:
    const std::string& text_;
    std::string file_;
};

bool is_comment(const std::string& key) { return key == "comment" || (!key.empty() && key[0] == '_'); }

void check_keys(const json& object, const std::set<std::string>& allowed, const std::string& what, const Locator& at,
                std::size_t offset) {
    if (!object.is_object()) at.fail(offset, what + " must be a JSON object");
    for (const auto& [key, value] : object.items())
        if (!allowed.count(key) && !is_comment(key)) {
            std::string list;
            for (const std::string& name : allowed) list += (list.empty() ? "" : ", ") + name;
            at.fail(offset, what + " has an unknown key \"" + key + "\" (known: " + list + ")");
        }
}

long to_cents(const json& value, const std::string& what, const Locator& at, std::size_t offset) {
    if (!value.is_number() || value.get<double>() < 0) at.fail(offset, what + " must be a number >= 0");
    const double hundredths = value.get<double>() * 100.0;
    if (std::abs(hundredths - std::round(hundredths)) > 1e-6) at.fail(offset, what + " may have at most two decimals");
    return std::lround(hundredths);
}

ImageRamp parse_ramp(const json& value, ImageRamp ramp, const std::string& what, const Locator& at, std::size_t offset) {
    check_keys(value, {"full_below", "zero_at", "most"}, what, at, offset);
    for (auto [key, field] : {std::pair{"full_below", &ramp.full_below}, {"zero_at", &ramp.zero_at}, {"most", &ramp.most}}) {
        if (!value.contains(key)) continue;
        if (!value[key].is_number()) at.fail(offset, what + "." + key + " must be a number");
        *field = value[key].get<double>();
    }
    if (!(0.0 <= ramp.full_below && ramp.full_below < ramp.zero_at && ramp.zero_at <= 1.0))
        at.fail(offset, what + " needs 0 <= full_below < zero_at <= 1");
    if (!(0.0 <= ramp.most && ramp.most <= 1.0)) at.fail(offset, what + ".most must be between 0 and 1");
    return ramp;
}

Rule parse_rule(const json& value, const LabRubric& lab, const std::set<std::string>& earlier, const ImageRamp& ramp,
                const Locator& at, std::size_t offset) {
    if (!value.is_object() || !value.contains("id") || !value["id"].is_string() || value["id"].get<std::string>().empty())
        at.fail(offset, "lab " + lab.lab + ": every rule needs an \"id\" (a non-empty string)");
    Rule rule;
    rule.id = value["id"];
    offset = at.find("id", rule.id, offset);
    rule.line = at.line_at(offset);
    const std::string what = "lab " + lab.lab + ", rule \"" + rule.id + "\"";
    check_keys(value, {"id", "tests", "exclude", "points", "points_each", "requires", "optional", "image"}, what, at, offset);
    if (earlier.count(lab.lab + ":" + rule.id)) at.fail(offset, what + " is defined twice");
    if (!value.contains("tests") || !value["tests"].is_array() || value["tests"].empty())
        at.fail(offset, what + " needs \"tests\": a non-empty list of test names or globs");
    for (const json& pattern : value["tests"]) {
        if (!pattern.is_string() || pattern.get<std::string>().empty()) at.fail(offset, what + ": every test pattern must be a non-empty string");
        rule.tests.push_back(pattern);
    }
    for (const json& pattern : value.value("exclude", json::array())) {
        if (!pattern.is_string() || pattern.get<std::string>().empty()) at.fail(offset, what + ": every exclude pattern must be a non-empty string");
        rule.exclude.push_back(pattern);
    }
    if (value.contains("points") == value.contains("points_each"))
        at.fail(offset, what + " needs exactly one of \"points\" (split over its tests) and \"points_each\"");
    if (value.contains("points")) rule.points_cents = to_cents(value["points"], what + ": points", at, offset);
    if (value.contains("points_each")) rule.each_cents = to_cents(value["points_each"], what + ": points_each", at, offset);
    if (value.contains("optional")) {
        if (!value["optional"].is_boolean()) at.fail(offset, what + ": optional must be true or false");
        rule.optional = value["optional"];
        if (rule.optional && rule.each_cents) at.fail(offset, what + ": an optional rule needs \"points\", not \"points_each\"");
    }
    for (const json& required : value.value("requires", json::array())) {
        if (!required.is_string()) at.fail(offset, what + ": requires must list rule names");
        std::string name = required;
        if (name.rfind("*:", 0) == 0) { // "*:unit": that rule of every lab listed before this one
            const std::string id = name.substr(2);
            std::set<std::string> labs;
            for (const std::string& other : earlier) labs.insert(other.substr(0, other.find(':')));
            labs.erase(lab.lab);
            if (labs.empty()) at.fail(offset, what + " requires \"" + name + "\", but no lab is listed before it");
            for (const std::string& other : labs) {
                if (!earlier.count(other + ":" + id)) at.fail(offset, what + " requires \"" + name + "\", but lab " + other + " has no rule \"" + id + "\"");
                rule.requires_rules.push_back(other + ":" + id);
            }
            continue;
        }
        if (name.find(':') == std::string::npos) name = lab.lab + ":" + name;
        if (!earlier.count(name)) at.fail(offset, what + " requires \"" + required.get<std::string>() + "\", which is not a rule listed before it");
        rule.requires_rules.push_back(name);
    }
    if (value.contains("image")) {
        if (value["image"].is_boolean()) {
            if (value["image"].get<bool>()) rule.image = ramp;
        } else {
            rule.image = parse_ramp(value["image"], ramp, what + ": image", at, offset);
        }
    }
    return rule;
}

} // namespace

double ImageRamp::credit(double failing_fraction) const {
    const double t = (zero_at - failing_fraction) / (zero_at - full_below);
    return most * std::clamp(t, 0.0, 1.0);
}

Rubric parse_rubric(const std::string& text, const std::string& file_name, const std::vector<std::string>& known_labs) {
    const Locator at(text, file_name);
    json root;
    try {
        root = json::parse(text);
    } catch (const json::parse_error& error) {
        const std::string what = error.what();
        at.fail(error.byte > 0 ? error.byte - 1 : 0, "not valid JSON: " + what.substr(what.find(':') + 2));
    }
    Rubric rubric;
    rubric.file = file_name;
    check_keys(root, {"labs", "image_ramp"}, "the rubric", at, 0);
    if (root.contains("image_ramp")) rubric.image_ramp = parse_ramp(root["image_ramp"], {}, "image_ramp", at, at.find("image_ramp", "", 0));
    if (!root.contains("labs") || !root["labs"].is_array() || root["labs"].empty()) at.fail(0, "the rubric needs \"labs\": a non-empty list");

    std::set<std::string> earlier_rules, seen_labs;
    std::size_t offset = 0;
    for (const json& value : root["labs"]) {
        LabRubric lab;
        check_keys(value, {"lab", "title", "rules"}, "a lab entry", at, offset);
        if (!value.contains("lab") || !value["lab"].is_string()) at.fail(offset, "a lab entry needs \"lab\": the lab's name");
        lab.lab = value["lab"];
        offset = at.find("lab", lab.lab, offset);
        lab.line = at.line_at(offset);
        if (std::find(known_labs.begin(), known_labs.end(), lab.lab) == known_labs.end()) {
            std::string list;
            for (const std::string& name : known_labs) list += (list.empty() ? "" : ", ") + name;
            at.fail(offset, "unknown lab \"" + lab.lab + "\" (known: " + list + ")");
        }
        if (!seen_labs.insert(lab.lab).second) at.fail(offset, "lab " + lab.lab + " is listed twice");
        if (!value.contains("title") || !value["title"].is_string() || value["title"].get<std::string>().empty())
            at.fail(offset, "lab " + lab.lab + " needs a \"title\"");
        lab.title = value["title"];
        if (!value.contains("rules") || !value["rules"].is_array() || value["rules"].empty())
            at.fail(offset, "lab " + lab.lab + " needs \"rules\": a non-empty list");
        std::size_t rule_offset = offset;
        for (const json& rule_value : value["rules"]) {
            lab.rules.push_back(parse_rule(rule_value, lab, earlier_rules, rubric.image_ramp, at, rule_offset));
            rule_offset = at.find("id", lab.rules.back().id, rule_offset) + 1;
            earlier_rules.insert(lab.lab + ":" + lab.rules.back().id);
        }
        rubric.labs.push_back(std::move(lab));
        offset += 1;
    }
    for (const std::string& name : known_labs)
        if (!seen_labs.count(name)) at.fail(0, "the rubric has no entry for lab " + name);
    return rubric;
}

Rubric load_rubric(const std::filesystem::path& file, const std::vector<std::string>& known_labs) {
    std::ifstream in(file);
    if (!in) throw RubricError(file.string() + ": cannot open the rubric");
    std::stringstream text;
    text << in.rdbuf();
    return parse_rubric(text.str(), file.string(), known_labs);
}

bool rule_matches(const Rule& rule, const std::string& name) {
    auto matches = [&](const std::string& pattern) { return pattern_matches(pattern, name); };
    return std::any_of(rule.tests.begin(), rule.tests.end(), matches) && std::none_of(rule.exclude.begin(), rule.exclude.end(), matches);
}

bool is_exact_name(const std::string& pattern) {
    return pattern.find('.') != std::string::npos && pattern.find_first_of("*?") == std::string::npos;
}

bool pattern_matches(const std::string& pattern_text, const std::string& name) {
    const std::string pattern = pattern_text.find('.') == std::string::npos ? pattern_text + ".*" : pattern_text;
    // Glob matching with backtracking to the last '*'.
    std::size_t p = 0, n = 0, star = std::string::npos, resume = 0;
    while (n < name.size()) {
        if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
            ++p, ++n;
        } else if (p < pattern.size() && pattern[p] == '*') {
            star = p++;
            resume = n;
        } else if (star != std::string::npos) {
            p = star + 1;
            n = ++resume;
        } else {
            return false;
        }
    }
    while (p < pattern.size() && pattern[p] == '*') ++p;
    return p == pattern.size();
}

} // namespace whitted::grade
