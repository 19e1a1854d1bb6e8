// The JSON scene loader: syntax, nesting, every key's checks, and the meshes a scene names
// (box.obj beside the scene is a valid closed mesh, so seeds reach the mesh and medium keys).
#include "FuzzInput.h"
#include "scene/SceneLoader.h"
#include "tet/Shapes.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    tetglow::writeObj(tetglow::box(), tetglow::fuzz::folder() + "/box.obj");
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        tetglow::loadScene(tetglow::fuzz::writeFile("scene.json", data, size));
    } catch (const tetglow::InputError&) {}
    return 0;
}
