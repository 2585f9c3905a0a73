// `whitted labs`: the labs of the course and which of them are done.
#include "commands.hpp"
#include "exit_codes.hpp"
#include "whitted/lab_status.hpp"

#include <cstdio>
#include <memory>
#include <string>

namespace whitted {
namespace {

// The lab table as tab-separated fields (number, stem, title), for scripts: it
// calls no lab code, so a lab that crashes or hangs cannot stop a script.
int print_table() {
    for (const LabInfo& lab : kLabs)
        std::printf("%d\t%s\t%s\n", lab.number, std::string(lab.stem).c_str(), std::string(lab.title).c_str());
    return exit_code::success;
}

// One line per lab: number, file, title, and done or what is missing.
int print_labs() {
    for (const LabStatus& lab : probe_labs()) {
        const std::string file = "labs/" + lab.name + ".cpp";
        const std::string status = lab.done ? "done" : "not done: " + lab.message;
        std::printf("lab %-2d %-26s %-13s %s\n", lab.number, file.c_str(), lab.title.c_str(), status.c_str());
    }
    return exit_code::success;
}

} // namespace

Command add_labs_command(CLI::App& app) {
    CLI::App* command = app.add_subcommand("labs", "List the labs, their files, and which are done (a function that still "
                                                   "throws \"is not implemented yet\" means not done).");
    auto tsv = std::make_shared<bool>(false);
    command->add_flag("--tsv", *tsv, "Only the table, as tab-separated fields for scripts: number, file stem, title");
    command->footer("Exit code: 0 list printed (whether or not the labs are done), 2 a bad option, 3 whitted itself failed.");
    return {command, [tsv] { return *tsv ? print_table() : print_labs(); }};
}

} // namespace whitted
