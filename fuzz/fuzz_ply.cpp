// The PLY reader behind pbrt's plymesh: ascii and both binary byte orders.
#include <vector>

#include "FuzzInput.h"
#include "scene/PlyReader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> warnings;
    try {
        tetglow::readPly(tetglow::fuzz::writeFile("mesh.ply", data, size), warnings);
    } catch (const tetglow::InputError&) {
    }
    return 0;
}
