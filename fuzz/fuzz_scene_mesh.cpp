// glTF, GLB, Collada and FBX through Assimp, as readMeshFile tells them by their content (the
// name's extension, .gltf, decides for the rest); with the node hierarchy, placing and welding.
#include <vector>

#include "FuzzInput.h"
#include "scene/MeshFile.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> warnings;
    try {
        tetglow::readMeshFile(tetglow::fuzz::writeFile("mesh.gltf", data, size), "", &warnings);
    } catch (const tetglow::InputError&) {
    }
    return 0;
}
