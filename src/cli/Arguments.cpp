// Argument checks that CLI11 makes late or words badly.
#include <cstdlib>

#include "cli/Commands.h"

namespace tetglow::cli {
namespace {

bool isNumber(const std::string& s) {
    char* end = nullptr;
    std::strtod(s.c_str(), &end);
    return !s.empty() && *end == '\0';
}

std::string subcommandNames(const CLI::App& app) {
    std::string names;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
        names += (names.empty() ? "" : ", ") + sub->get_name();
    return names;
}

}  // namespace

std::string unknownArgument(CLI::App& app, int argc, char** argv) {
    CLI::App* command = &app;
    std::string path = "tetglow";
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--") break;
        if (arg.size() > 1 && arg[0] == '-' && !isNumber(arg)) {
            const std::string name = arg.substr(0, arg.find('='));
            if (name == "--help" || name == "-h") return "";  // CLI11 prints the help
            if (!command->get_option_no_throw(name)) {
                // A value that starts with '-' ("--up -z") reads as an option unless joined by '='.
                const CLI::Option* before = i > 1 && std::string(argv[i - 1]).find('=') == std::string::npos
                                                ? command->get_option_no_throw(argv[i - 1])
                                                : nullptr;
                if (before && before->get_type_size_min() > 0)
                    return before->get_name() + ": '" + shorten(arg) + "' reads as an option: write " +
                           before->get_name() + "=" + shorten(arg);
                return "unknown option '" + shorten(name) + "' (the options: '" + path + " --help')";
            }
            continue;
        }
        // The first word where a subcommand is required names it.
        if (command->get_require_subcommand_min() == 0) continue;
        CLI::App* sub = nullptr;
        for (CLI::App* s : command->get_subcommands([](CLI::App*) { return true; }))
            if (s->check_name(arg)) sub = s;
        if (!sub)
            return "unknown subcommand '" + shorten(arg) + "' of '" + path + "'; one of: " + subcommandNames(*command);
        command = sub;
        path += " " + sub->get_name();
    }
    if (command->get_require_subcommand_min() > 0)
        return "'" + path + "' needs a subcommand: one of " + subcommandNames(*command);
    return "";
}

}  // namespace tetglow::cli
