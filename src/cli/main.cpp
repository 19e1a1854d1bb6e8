// The `tetglow` command: one subcommand per job. Input errors exit with 1, usage errors with 2;
// every error is one line on stderr.
#include <cstdio>
#include <exception>
#include <new>

#include "cli/Commands.h"
#include "tet/TriangleMesh.h"

namespace {

int fail(int code, const std::string& message) {
    std::fprintf(stderr, "tetglow: error: %s\n", tetglow::shorten(tetglow::oneLine(message), 400).c_str());
    return code;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"tetglow: participating media inside closed triangle meshes"};
    tetglow::cli::addCommands(app);
    try {
        if (const std::string unknown = tetglow::cli::unknownArgument(app, argc, argv); !unknown.empty())
            return fail(2, unknown);
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help
        return fail(2, e.what());
    } catch (const std::bad_alloc&) {
        return fail(
            1,
            "out of memory: the scene or the options ask for more memory than this machine has (see docs/USAGE.md, "
            "\"Limits\")");
    } catch (const std::exception& e) {
        return fail(1, e.what());
    }
    return 0;
}
