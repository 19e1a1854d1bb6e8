// Where the tet cache lies: the render reads and writes it there, and `farm` checks that every
// node can see it.
#pragma once
#include <filesystem>
#include <string>

namespace tetglow {

// `configured` when not empty, else $TETGLOW_CACHE_DIR, else $XDG_CACHE_HOME/tetglow, else
// ~/.cache/tetglow; "" when none of them is set.
std::filesystem::path cacheDirectory(const std::string& configured = "");

}  // namespace tetglow
