// The command line, parsed only: every subcommand's options and their checks, up to the point
// where the command would run (so no render runs long). The input is the arguments, NUL-separated.
#include <algorithm>
#include <string>
#include <vector>

#include "base/Error.h"
#include "cli/Commands.h"

namespace {

struct Parsed {};  // thrown once every option is parsed and checked, before any command runs

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> args;
    std::string arg;
    for (size_t i = 0; i <= size; ++i) {
        if (i == size || data[i] == '\0') {
            args.push_back(arg);
            arg.clear();
        } else {
            arg += char(data[i]);
        }
    }
    std::reverse(args.begin(), args.end());  // CLI11 takes the arguments last first
    CLI::App app{"tetglow"};
    tetglow::cli::addCommands(app);
    app.parse_complete_callback([] { throw Parsed{}; });
    try {
        app.parse(args);
    } catch (const CLI::ParseError&) {
    } catch (const Parsed&) {
    } catch (const tetglow::InputError&) {}
    return 0;
}
