// The STL reader: ASCII and binary (told apart by the size), with the welding of equal positions.
#include "FuzzInput.h"
#include "scene/StlReader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        tetglow::parseStl(std::string(reinterpret_cast<const char*>(data), size), "mesh.stl");
    } catch (const tetglow::InputError&) {}
    return 0;
}
