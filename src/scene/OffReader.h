// OFF meshes: "OFF", the vertex, face and edge counts, the vertices, then each face as its
// vertex count and 0-based indices, triangulated; '#' starts a comment.
#pragma once
#include <string>

#include "tet/TriangleMesh.h"

namespace tetglow {

// OFF text read from `path` (named in messages). Throws InputError naming file and line.
TriangleMesh parseOff(const std::string& text, const std::string& path);

}  // namespace tetglow
