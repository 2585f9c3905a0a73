#include "grader/lab_fences.hpp"

#include "grader/elf_symbols.hpp"
#include "grader/submission.hpp"

#include <cxxabi.h>

#include <cstdlib>
#include <memory>

namespace whitted::grade {
namespace {

/// A rule: the functions whose demangled names start with `prefix` are fenced for `lab` (0: every lab).
struct FenceRule {
    int lab;
    std::string_view prefix;
    std::string_view why;
};

constexpr std::string_view kFenceOwnBvh = "it is the framework's own bounding volume hierarchy, which lab 10 asks you to write";
constexpr std::string_view kFenceSceneQuery =
    "the scene's queries walk the framework's hierarchy: that walk is what bvh_closest_hit() and bvh_occluded() are";
constexpr std::string_view kFenceGrading = "it is part of the grading itself";

// What each lab's code may not call. Everything else the public headers
// declare, it may: the earlier labs' functions, the framework's types and
// helpers (intersect(), Tracer, Scene's data, sampling, ...).
constexpr FenceRule kFenceRules[] = {
    {0, "whitted::Bvh::", kFenceOwnBvh},
    {0, "whitted::WideBvh::", kFenceOwnBvh},
    {0, "whitted::UniformGrid::", "it is the framework's own uniform grid, an answer to lab 10's queries"},
    {0, "whitted::framework_bvh_tree(", kFenceOwnBvh},
    {0, "whitted::closest_hit_cost(", "it is the yardstick lab 10's walks are measured with"},
    {0, "whitted::occluded_cost(", "it is the yardstick lab 10's walks are measured with"},
    {0, "whitted::Scene::query_cost(", "it is the yardstick lab 10's walks are measured with"},
    {0, "whitted::link::", kFenceGrading},
    {0, "whitted::remote_scene_queries(", kFenceGrading},
    {10, "whitted::Scene::closest_hit(", kFenceSceneQuery},
    {10, "whitted::Scene::closest_hits(", kFenceSceneQuery},
    {10, "whitted::Scene::occluded(", kFenceSceneQuery},
    {10, "whitted::Scene::occluded_rays(", kFenceSceneQuery},
    {10, "whitted::closest_hit(", "lab 1's closest_hit() tests every primitive it is given: a walk tests the primitives "
                                  "of the leaves it reaches, one by one, with intersect()"},
    {10, "whitted::intersect_box(", "it is the framework's box primitive, whose slab test is box_entry()'s answer"},
    {7, "whitted::sample_position(", "it places a pixel's samples as pixel_color() is to place them (for whitted trace)"},
};

/// The demangled name of a symbol of the kit (the instructor's own), or the name itself.
std::string demangled_symbol(const std::string& symbol) {
    int status = 0;
    const std::unique_ptr<char, void (*)(void*)> text(abi::__cxa_demangle(symbol.c_str(), nullptr, nullptr, &status), std::free);
    return status == 0 && text ? std::string(text.get()) : symbol;
}

/// The lab number of a lab name ("10_bvh" -> 10), 0 for none.
int lab_number_of(const std::string& lab) {
    int number = 0;
    for (const char c : lab) {
        if (c < '0' || c > '9') break;
        number = number * 10 + (c - '0');
    }
    return number;
}

constexpr std::size_t kMaxKitFileBytes = std::size_t{1} << 30;

} // namespace

LabFences::LabFences(const WorkerKit& kit) {
    std::vector<std::string> defined;
    for (const std::filesystem::path& library : kit.libraries) {
        const std::vector<std::string> symbols = archive_defined_symbols(read_regular_file(library, kMaxKitFileBytes));
        defined.insert(defined.end(), symbols.begin(), symbols.end());
    }
    for (const auto& [lab, object] : kit.remote_objects) {
        const ObjectSymbols symbols = elf_object_symbols(read_regular_file(object, kMaxKitFileBytes));
        defined.insert(defined.end(), symbols.defined.begin(), symbols.defined.end());
    }
    for (const std::string& symbol : defined) {
        const std::string function = demangled_symbol(symbol);
        for (const FenceRule& rule : kFenceRules)
            if (function.starts_with(rule.prefix)) fenced_[symbol].push_back({rule.lab, function, std::string(rule.why)});
    }
}

std::vector<FencedCall> LabFences::refused(const std::string& lab, std::string_view object) const {
    const int number = lab_number_of(lab);
    std::set<std::string> seen;
    std::vector<FencedCall> calls;
    for (const std::string& symbol : elf_object_symbols(object).undefined) {
        const auto found = fenced_.find(symbol);
        if (found == fenced_.end()) continue;
        for (const Fenced& fence : found->second)
            if ((fence.lab == 0 || fence.lab == number) && seen.insert(fence.function).second)
                calls.push_back({fence.function, fence.why});
    }
    return calls;
}

std::string LabFences::describe(const std::string& lab, const std::vector<FencedCall>& calls) {
    std::string text;
    for (const FencedCall& call : calls)
        text += "labs/" + lab + ".cpp calls " + call.function + ", which grading does not let lab " +
                std::to_string(lab_number_of(lab)) + " use: " + call.why + ".\n";
    return text;
}

} // namespace whitted::grade
