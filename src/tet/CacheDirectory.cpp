#include "tet/CacheDirectory.h"

#include <cstdlib>

namespace tetglow {

std::filesystem::path cacheDirectory(const std::string& configured) {
    if (!configured.empty()) return configured;
    if (const char* d = std::getenv("TETGLOW_CACHE_DIR"); d && *d) return d;
    if (const char* d = std::getenv("XDG_CACHE_HOME"); d && *d) return std::filesystem::path(d) / "tetglow";
    if (const char* d = std::getenv("HOME"); d && *d) return std::filesystem::path(d) / ".cache" / "tetglow";
    return {};
}

}  // namespace tetglow
