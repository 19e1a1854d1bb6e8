// PLY meshes: ascii, binary_little_endian or binary_big_endian; vertex x, y, z (and nx, ny, nz
// when all three are present); a "face" element's lists "vertex_indices" (or "vertex_index") as
// polygons, triangulated (tet/PolygonTriangulation.h), and a "tristrips" element's lists as
// triangle strips. Other elements and properties are read past; header lines other than
// format, element, property and end_header are skipped (with a warning unless they are a comment
// or obj_info), as Blender and Assimp skip them.
#pragma once
#include <string>
#include <vector>

#include "scene/MeshFile.h"

namespace tetglow {

// The PLY file `data` read from `path`. Throws InputError "<path>: <problem>"; warnings go to
// `warnings`.
MeshFile parsePly(const std::string& data, const std::string& path, std::vector<std::string>* warnings = nullptr);

}  // namespace tetglow
