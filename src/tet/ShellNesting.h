// Which closed shells of a mesh contain which: the nesting that decides, with each shell's
// winding, where a mesh of several shells is inside.
#pragma once
#include <cstdint>
#include <vector>

#include "tet/TriangleMesh.h"

namespace tetglow {

// For each shell (its triangles in `shells`), the other shells that contain it: those whose
// exact winding number at a point of it is above 1/2 in magnitude. Shells may touch at corners
// and edges but not cross, so one point of a shell decides. Only shells whose bounds hold that
// point are summed, found in a grid of the shells' bounds, so disjoint shells cost about their
// triangles, not shells x triangles.
std::vector<std::vector<uint32_t>> containingShells(const TriangleMesh& mesh,
                                                    const std::vector<std::vector<uint32_t>>& shells);

}  // namespace tetglow
