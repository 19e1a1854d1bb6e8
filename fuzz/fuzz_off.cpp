// The OFF reader (readMesh picks it by the .off extension).
#include <vector>

#include "FuzzInput.h"
#include "tet/TriangleMesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> warnings;
    try {
        tetglow::readMesh(tetglow::fuzz::writeFile("mesh.off", data, size), &warnings);
    } catch (const tetglow::InputError&) {
    }
    return 0;
}
