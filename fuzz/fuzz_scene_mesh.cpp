// glTF, GLB, Collada and FBX through Assimp, as readMeshFile tells them by their content (the
// name's extension, .gltf, decides for the rest); with the node hierarchy, placing and welding.
//
// The import runs in a child process (base/ChildProcess.h), as it does for the user, and
// libFuzzer counts coverage in this process only: what guides the mutations is the parent's side
// (reading the file, telling its format, decoding the child's answer), and Assimp's parsers and
// the placing and welding in the child are fuzzed blind from the seeds. What this target checks
// is the bound: whatever the input, one InputError, with the parent's memory and time within
// libFuzzer's limits. The child's limits are capped below those (fuzz/run.sh: -timeout=10,
// -rss_limit_mb=2048), so that an import Assimp never finishes is the child's error, not a hang.
#include <vector>

#include "FuzzInput.h"
#include "base/ChildProcess.h"
#include "scene/MeshFile.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    tetglow::capChildLimits({512.0 * (1 << 20), 3});
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> warnings;
    try {
        tetglow::readMeshFile(tetglow::fuzz::writeFile("mesh.gltf", data, size), "", &warnings);
    } catch (const tetglow::InputError&) {}
    return 0;
}
