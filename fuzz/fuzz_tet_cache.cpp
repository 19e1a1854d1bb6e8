// The tet cache reader. Each input is read as it is, then once more with its checksum recomputed
// (as a forger would), so that the content checks behind the checksum are fuzzed too. A mesh the
// reader accepts must be safe to use: its volume and every surface neighbour are computed.
#include <cstring>

#include "FuzzInput.h"
#include "base/Hash.h"
#include "tet/TetMesh.h"

namespace {

void readAndUse(const std::string& bytes) {
    uint64_t key = 0;
    if (bytes.size() >= 16) std::memcpy(&key, bytes.data() + 8, sizeof key);  // the key it claims, so that reads go on
    tetglow::TetMesh mesh;
    if (tetglow::readTetMesh(mesh, key, tetglow::fuzz::writeFile("entry.tet", bytes.data(), bytes.size())) !=
        tetglow::CacheRead::Used)
        return;
    volatile double volume = mesh.volume();
    (void)volume;
    for (uint32_t s = 0; s < mesh.surface.size(); ++s)
        for (int k = 0; k < 3; ++k) mesh.surfaceAcross(s, mesh.surface[s][k], mesh.surface[s][(k + 1) % 3]);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string bytes(reinterpret_cast<const char*>(data), size);
    readAndUse(bytes);
    if (bytes.size() >= 24) {
        const uint64_t sum = tetglow::fnv1a(tetglow::kFnvOffset, bytes.data() + 24, bytes.size() - 24);
        std::memcpy(bytes.data() + 16, &sum, sizeof sum);
        readAndUse(bytes);
    }
    return 0;
}
