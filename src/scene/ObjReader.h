// Wavefront OBJ meshes: the vertices (v) and the polygons (f) between them, triangulated; the
// other attributes (normals, texture coordinates, groups, materials) do not change the shape.
#pragma once
#include <string>
#include <vector>

#include "tet/TriangleMesh.h"

namespace tetglow {

// OBJ text read from `path` (named in messages; the mtllib is looked for beside it). readMesh
// (scene/MeshFile.h) reads the file and picks the reader. Throws InputError naming file and line.
// Warnings (such as a missing mtllib) go to `warnings`.
TriangleMesh parseObj(const std::string& text, const std::string& path, std::vector<std::string>* warnings);

}  // namespace tetglow
