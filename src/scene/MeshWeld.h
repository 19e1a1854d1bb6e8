// Formats that store each triangle's corners apart (STL, the split vertices of glTF and FBX
// meshes, where a seam in the normals or texture coordinates duplicates a position) leave
// triangles that share no vertex; a medium's surface needs them joined along their edges.
#pragma once
#include "tet/TriangleMesh.h"

namespace tetglow {

// Makes positions that are exactly equal (0 and -0 alike) one vertex (the first of them).
void weldEqualPositions(TriangleMesh& mesh);

}  // namespace tetglow
