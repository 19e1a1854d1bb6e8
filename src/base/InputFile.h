// Input files, read whole, for every reader. Only a regular file no larger than its limit is
// read: a FIFO or a device (/dev/zero) would block or never end, and a huge file would take the
// machine's memory. The limits are documented in docs/FORMAT.md and docs/USAGE.md.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace tetglow {

inline constexpr uint64_t kMiB = uint64_t(1) << 20;
inline constexpr uint64_t kMaxSceneFileBytes = 64 * kMiB;    // a JSON scene, a pbrt file, each Include
inline constexpr uint64_t kMaxMeshFileBytes = 1024 * kMiB;   // any mesh (also pbrt's plymesh), with the files it names
inline constexpr uint64_t kMaxImageFileBytes = 1024 * kMiB;  // an OpenEXR image read by diff
inline constexpr uint64_t kMaxCacheFileBytes = 4096 * kMiB;  // a tet cache entry

// The bytes of the file at `path`, at most `maxBytes` of them. Throws InputError, one line:
//   "<path>: no such file", "<path>: is a directory, not a file", "<path>: is a FIFO, not a
//   regular file" (or a character device, ...), "<path>: 70 MiB, larger than the 64 MiB limit
//   for a scene file", "<path>: cannot open: <reason>".
// `what` names the kind of file in the size message ("a scene file", "a mesh").
std::string readInputFile(const std::string& path, uint64_t maxBytes, const char* what);

// Records in the current InputLog a file read on this thread's behalf by a child process.
void noteInputFile(const std::string& path);

// While one lives, the path of every file readInputFile opens on this thread is recorded in it
// (the innermost log, when they nest): a loader learns every file a scene pulls in (Includes,
// meshes, plymesh), and commands refuse outputs that would overwrite any of them.
class InputLog {
public:
    InputLog();
    ~InputLog();
    InputLog(const InputLog&) = delete;
    InputLog& operator=(const InputLog&) = delete;
    const std::vector<std::string>& files() const { return files_; }

private:
    friend std::string readInputFile(const std::string&, uint64_t, const char*);
    friend void noteInputFile(const std::string&);
    std::vector<std::string> files_;
    InputLog* outer_;
};

}  // namespace tetglow
