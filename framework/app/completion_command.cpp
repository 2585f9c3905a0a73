// `whitted completion bash`: a bash completion script, made from the commands
// and options as they are registered, so it never falls behind them.
// Use: source <(whitted completion bash)
#include "commands.hpp"
#include "exit_codes.hpp"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <string>

namespace whitted {
namespace {

// Every long option of a command (and its short ones), as one line of words.
std::string option_words(const CLI::App& command) {
    std::string words;
    for (const CLI::Option* option : command.get_options()) {
        for (const std::string& name : option->get_lnames()) words += (words.empty() ? "--" : " --") + name;
        for (const std::string& name : option->get_snames()) words += (words.empty() ? "-" : " -") + name;
    }
    return words;
}

// The script: the first word that is not an option names the command; an
// option is completed from that command's options, anything else as a file name.
std::string bash_script(const CLI::App& root) {
    const std::string program = std::filesystem::path(root.get_name()).filename().string();
    std::string function = "_";
    for (const char c : program) function += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    const std::vector<const CLI::App*> commands = root.get_subcommands([](const CLI::App*) { return true; });
    std::string command_names;
    for (const CLI::App* command : commands) command_names += command->get_name() + " ";
    std::string cases = "        '') words='" + command_names + option_words(root) + "' ;;\n";
    for (const CLI::App* command : commands)
        cases += "        " + command->get_name() + ") words='" + option_words(*command) + "' ;;\n";
    return "# bash completion for " + program + ": source <(" + program + " completion bash)\n" +
           function + "() {\n"
           "    local cur=${COMP_WORDS[COMP_CWORD]} command='' words='' i\n"
           "    for ((i = 1; i < COMP_CWORD; i++)); do\n"
           "        if [[ ${COMP_WORDS[i]} != -* ]]; then command=${COMP_WORDS[i]}; break; fi\n"
           "    done\n"
           "    case $command in\n" +
           cases +
           "    esac\n"
           "    COMPREPLY=()\n"
           "    # Commands and options from the list; file names (complete -o default) for the rest.\n"
           "    if [[ -z $command || $cur == -* ]]; then COMPREPLY=($(compgen -W \"$words\" -- \"$cur\")); fi\n"
           "}\n"
           "complete -o default -F " + function + " " + program + "\n";
}

} // namespace

Command add_completion_command(CLI::App& app) {
    CLI::App* command = app.add_subcommand("completion", "Print a script that completes commands, options and file "
                                                         "names when you press Tab in bash.");
    // Unbound: bash, the one shell, is all it can be once CLI11 has checked it.
    command->add_option("shell", "The shell: bash (the only one for now)")->required()->check(CLI::IsMember({"bash"}));
    command->footer("Use: source <(whitted completion bash), in a terminal or in ~/.bashrc.\n"
                    "Exit code: 0 script printed, 2 a bad option or the output cannot be written, 3 whitted itself failed.");
    const CLI::App* root = &app;
    return {command, [root] {
                const std::string script = bash_script(*root);
                const bool written = std::fputs(script.c_str(), stdout) >= 0 && std::fflush(stdout) == 0;
                return written ? exit_code::success : exit_code::bad_input;
            }};
}

} // namespace whitted
