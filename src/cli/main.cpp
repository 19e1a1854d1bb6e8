// The `tetglow` command: one subcommand per job. Input errors exit with 1, usage errors with 2.
#include <cstdio>
#include <exception>

#include "cli/Commands.h"
#include "tet/TriangleMesh.h"

int main(int argc, char** argv) {
    CLI::App app{"tetglow: participating media inside closed triangle meshes"};
    tetglow::cli::addCommands(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    } catch (const tetglow::InputError& e) {
        std::fprintf(stderr, "tetglow: error: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "tetglow: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
