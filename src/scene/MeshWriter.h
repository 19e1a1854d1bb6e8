// A triangle mesh written in the format its file name's extension names, for the commands that
// write meshes of their own (`generate`): .obj (text, tet/TriangleMesh.h's writeObj), .ply
// (binary little-endian, float positions) or .stl (binary). Any other extension is an InputError
// before anything is written, so that a file never holds another format than its name says.
#pragma once
#include <string>

#include "tet/TriangleMesh.h"

namespace tetglow {

// InputError "<path>: ..." unless the extension is one writeMeshFile writes.
void checkMeshExtension(const std::string& path);

// `comment`: lines, each ending in '\n', that say where the mesh came from: OBJ's "# " lines, PLY's
// "comment " lines; an STL keeps what fits its 80-byte header of the first line.
void writeMeshFile(const TriangleMesh& mesh, const std::string& path, const std::string& comment);

}  // namespace tetglow
