// The OBJ reader, on the bytes as readMeshFile hands them over.
#include <vector>

#include "FuzzInput.h"
#include "scene/ObjReader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> warnings;
    try {
        tetglow::parseObj(std::string(reinterpret_cast<const char*>(data), size), tetglow::fuzz::folder() + "/mesh.obj",
                          &warnings);
    } catch (const tetglow::InputError&) {}
    return 0;
}
