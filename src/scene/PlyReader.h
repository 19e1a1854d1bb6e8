// PLY meshes: ascii, binary_little_endian or binary_big_endian; vertex x, y, z (and nx, ny, nz
// when all three are present); a "face" element's lists "vertex_indices" (or "vertex_index") as
// polygons, fanned into triangles, and a "tristrips" element's lists as triangle strips. Other
// elements and properties are read past.
#pragma once
#include <string>

#include "scene/MeshFile.h"

namespace tetglow {

// The PLY file `data` read from `path`. Throws InputError "<path>: <problem>".
MeshFile parsePly(const std::string& data, const std::string& path);

}  // namespace tetglow
