// The pbrt-v3 parser: directives, parameter lists, transforms, Include and plymesh (part.pbrt and
// tri.ply beside the scene exist, so that both paths are reached).
#include <vector>

#include "FuzzInput.h"
#include "scene/PbrtParser.h"

namespace {

constexpr char kPart[] = "AttributeBegin\nLightSource \"point\" \"rgb I\" [1 1 1]\nAttributeEnd\n";
constexpr char kPly[] =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    tetglow::fuzz::writeFile("part.pbrt", kPart, sizeof kPart - 1);
    tetglow::fuzz::writeFile("tri.ply", kPly, sizeof kPly - 1);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> warnings;
    try {
        tetglow::loadPbrtScene(tetglow::fuzz::writeFile("scene.pbrt", data, size), &warnings);
    } catch (const tetglow::InputError&) {}
    return 0;
}
