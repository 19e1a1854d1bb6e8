// The PLY reader (every mesh shape, pbrt's plymesh): ascii and both binary byte orders, faces and strips.
#include <vector>

#include "FuzzInput.h"
#include "scene/PlyReader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> warnings;
    try {
        tetglow::parsePly(std::string(reinterpret_cast<const char*>(data), size), "mesh.ply", &warnings);
    } catch (const tetglow::InputError&) {}
    return 0;
}
