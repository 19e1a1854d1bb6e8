#include "scene/SceneFingerprint.h"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <filesystem>

#include "base/Hash.h"
#include "base/InputFile.h"
#include "scene/SceneWriter.h"

namespace tetglow {

std::string sceneFingerprint(const SceneDesc& scene) {
    namespace fs = std::filesystem;
    static std::atomic<int> serial{0};
    const fs::path dir = fs::temp_directory_path() /
                         ("tetglow-fingerprint-" + std::to_string(::getpid()) + "-" + std::to_string(serial++));
    fs::create_directories(dir);
    SceneDesc copy = scene;  // the writer's copy is judged by content only: no paths
    copy.path.clear();
    copy.output.clear();
    copy.inputs.clear();
    for (MediumDesc& m : copy.media) m.label.clear();  // a name changes no pixel
    uint64_t hash = kFnvOffset;
    try {
        const std::string json = (dir / "scene.json").string();
        std::vector<std::string> files = writeScene(copy, json);
        files.insert(files.begin(), json);
        for (const auto& file : files) {
            const std::string bytes = readInputFile(file, kMaxMeshFileBytes, "a scene's file");
            hash = fnv1a(hash, bytes.data(), bytes.size());
        }
    } catch (...) {
        fs::remove_all(dir);
        throw;
    }
    fs::remove_all(dir);
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", (unsigned long long)hash);
    return hex;
}

}  // namespace tetglow
