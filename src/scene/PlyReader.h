// PLY meshes as pbrt-v3's "plymesh" reads them: ascii, binary_little_endian or
// binary_big_endian; vertex x, y, z (and nx, ny, nz when all three are present); face lists
// "vertex_indices" (or "vertex_index") of 3 or 4 vertices, a quad split into (0, 1, 2) and
// (3, 0, 2). Faces of other sizes are skipped with a warning, as pbrt-v3 skips them.
#pragma once
#include <string>
#include <vector>

#include "tet/TriangleMesh.h"

namespace tetglow {

struct PlyMesh {
    TriangleMesh mesh;
    std::vector<glm::dvec3> normals;  // per vertex, or empty
};

// Throws InputError "<path>: <problem>".
PlyMesh readPly(const std::string& path, std::vector<std::string>& warnings);

}  // namespace tetglow
