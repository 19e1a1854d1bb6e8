// Volume's exit query asked after another number of walked tets than the renderer's one:
// 0 walks every tet, the reference the tests compare the exit query with; the benchmarks time
// each number. Nothing in src/ sets it, so it stays out of Volume's public interface.
#pragma once
#include <cstddef>

#include "media/Volume.h"

namespace tetglow {

struct ExitQueryAccess {
    static void setExitQueryAfter(Volume& volume, size_t steps) { volume.exitQueryAfter_ = steps; }
};

}  // namespace tetglow
