#include "tet/MeshingMemory.h"

#include <string>

#include "base/ChildProcess.h"
#include "base/Error.h"
#include "base/Memory.h"

namespace tetglow {
namespace {

// Bytes per triangle, peak resident. This process: 0.48 to 0.57 KB measured (`tetrahedralize` of
// a closed sphere of 0.2 M and of 2 M triangles, and of 50000 tiny disjoint tetrahedra), 0.76 KB
// reported on a mesh of 2 M tiny triangles. TetGen's child: 2.3 to 2.4 KB measured on the same
// meshes, while that mesh of tiny triangles ran past the child's limit, 12.6 GB: over 6.3 KB.
// The estimate takes the worst seen, so that a refusal comes at once and not after minutes.
constexpr double kHereBytesPerTriangle = 1000;
constexpr double kTetGenBytesPerTriangle = 7000;

}  // namespace

MeshingMemory meshingMemory(size_t triangles) {
    return {kHereBytesPerTriangle * double(triangles), kTetGenBytesPerTriangle * double(triangles)};
}

void checkMeshingMemory(size_t triangles) {
    const MeshingMemory m = meshingMemory(triangles);
    const double child = defaultChildMemory();
    std::string over;
    if (m.tetgen > child)
        over = "more than TetGen's limit of " + gigabytes(child) + " (half of " + memoryLimitText() + ")";
    else if (m.here + m.tetgen > memoryLimit())
        over = "more than " + memoryLimitText();
    else
        return;
    throw InputError(std::to_string(triangles) + " triangles need about " + gigabytes(m.here + m.tetgen) +
                     " to tetrahedralize (" + gigabytes(m.here) + " here, " + gigabytes(m.tetgen) + " in TetGen), " +
                     over + ": use a simpler mesh");
}

}  // namespace tetglow
