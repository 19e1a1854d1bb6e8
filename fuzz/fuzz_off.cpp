// The OFF reader, on the bytes as readMeshFile hands them over.
#include "FuzzInput.h"
#include "scene/OffReader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        tetglow::parseOff(std::string(reinterpret_cast<const char*>(data), size), "mesh.off");
    } catch (const tetglow::InputError&) {}
    return 0;
}
