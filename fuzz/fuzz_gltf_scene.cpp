// The glTF scene reader: the GLB container, the JSON's scene objects and extensions, the buffers
// (data: URIs, and part.bin beside the input, which a seed may name), accessors, node hierarchy.
#include "FuzzInput.h"
#include "scene/SceneLoader.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    // A tetrahedron: 4 float positions, 12 32-bit indices.
    const float positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const uint32_t indices[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    std::string bin(reinterpret_cast<const char*>(positions), sizeof positions);
    bin.append(reinterpret_cast<const char*>(indices), sizeof indices);
    tetglow::fuzz::writeFile("part.bin", bin.data(), bin.size());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        tetglow::loadScene(tetglow::fuzz::writeFile("scene.gltf", data, size));
    } catch (const tetglow::InputError&) {}
    return 0;
}
