// tetglow convert SCENE -o OUT.json: a scene (pbrt-v3, glTF 2.0 or JSON) as a tetglow JSON scene, its
// meshes as OBJ files beside it, so that rendering either file gives the same image.
#include <cstdio>
#include <filesystem>

#include "cli/Commands.h"
#include "scene/SceneLoader.h"
#include "scene/SceneWriter.h"

namespace tetglow::cli {
namespace {

struct Options {
    std::string scene, output, camera;
};

void run(const Options& o) {
    namespace fs = std::filesystem;
    if (fs::path(o.output).extension() != ".json") throw InputError(o.output + ": the output must be a .json file");
    prepareOutput(o.output, {o.scene});  // before the work; once more against every file the scene read
    const SceneDesc scene = loadScene(o.scene, o.camera);
    prepareOutput(o.output, scene.inputs);
    const auto meshes = writeScene(scene, o.output);
    std::printf("%s and %zu mesh files: %zu lights, %zu surfaces, %zu media\n", o.output.c_str(), meshes.size(),
                scene.lights.size(), scene.surfaces.size(), scene.media.size());
}

}  // namespace

void addConvertCommand(CLI::App& app) {
    auto o = std::make_shared<Options>();
    auto* cmd = app.add_subcommand(
        "convert", "Write a scene (pbrt-v3, glTF 2.0 or JSON) as a tetglow JSON scene with OBJ meshes beside it");
    cmd->add_option("scene", o->scene, "Scene file (pbrt-v3, glTF 2.0 or JSON, see docs/FORMAT.md)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", o->output, "The JSON scene to write")->required()->check(kNonEmpty);
    cmd->add_option("--camera", o->camera, "glTF scene: the camera node to look through (default: the first)")
        ->check(kNonEmpty);
    cmd->callback([o] { run(*o); });
}

}  // namespace tetglow::cli
