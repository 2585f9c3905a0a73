#include "stage_choice.hpp"

#include "whitted/lab_status.hpp"
#include "whitted/lab_table.hpp"

#include <cstdio>
#include <string>
#include <vector>

namespace whitted {
namespace {

// Lists the labs that are not done yet, one per line.
std::string missing_labs(const std::vector<LabStatus>& labs, int up_to) {
    std::string text;
    for (const LabStatus& lab : labs)
        if (lab.number <= up_to && !lab.done)
            text += "  lab " + std::to_string(lab.number) + " (" + lab.title + "): " + lab.message + "\n";
    return text;
}

} // namespace

// The stage to render: the one asked for, or the highest whose labs are all
// done. Explains what is missing instead of failing inside the render.
std::optional<int> choose_stage(std::optional<int> asked, std::optional<Pass> pass) {
    const std::vector<LabStatus> labs = probe_labs();
    const int ready = highest_complete_stage(labs);
    if (pass) {
        // A pass calls the labs up to its own; secondary rays follow --stage.
        const PassInfo& info = pass_info(*pass);
        const int min_stage = stage_number(info.min_stage);
        if (asked && *asked < min_stage) {
            std::fprintf(stderr, "whitted: --pass %s shows what labs 1 to %d compute, so it needs --stage %d or more\n",
                         std::string(info.name).c_str(), min_stage, min_stage);
            return std::nullopt;
        }
        if (ready < min_stage) {
            std::fprintf(stderr, "whitted: --pass %s calls the code of labs 1 to %d, and these are not done yet:\n%s",
                         std::string(info.name).c_str(), min_stage, missing_labs(labs, min_stage).c_str());
            return std::nullopt;
        }
    }
    if (asked) {
        if (*asked <= ready) return asked;
        const std::string needed = *asked == 1 ? "lab 1" : "labs 1 to " + std::to_string(*asked);
        std::fprintf(stderr, "whitted: stage %d needs %s, and these are not done yet:\n%s", *asked,
                     needed.c_str(), missing_labs(labs, *asked).c_str());
        if (ready > 0) std::fprintf(stderr, "Finish them, or render an earlier stage with --stage %d.\n", ready);
        return std::nullopt;
    }
    if (ready == 0) {
        std::fprintf(stderr, "whitted: nothing can be rendered before lab 1 is done:\n%s", missing_labs(labs, 1).c_str());
        return std::nullopt;
    }
    if (ready < kLabCount) {
        std::fprintf(stderr, "note: rendering stage %d (labs 1 to %d); these labs are not done yet:\n%s", ready, ready,
                     missing_labs(labs, kLabCount).c_str());
    }
    return ready;
}

void add_stage_option(CLI::App& command, std::optional<int>& stage) {
    command.add_option("--stage", stage,
                       "Use the features of labs 1..K only: " + stage_list() + " (default: the highest stage whose labs are done)")
        ->check(CLI::Range(1, kLabCount));
}

} // namespace whitted
