// STL meshes, ASCII ("solid" ... "facet normal" ... "outer loop" ... three "vertex x y z" ...
// "endloop" "endfacet" ... "endsolid", one or more solids) and binary (an 80-byte header, a
// little-endian uint32 triangle count n, then n records of 50 bytes: normal, three vertices as
// floats, a 2-byte attribute). A binary file's header may itself start with "solid", so a file
// is binary when its size is exactly 84 + 50 n. STL repeats each vertex in every triangle that
// uses it: equal positions become one vertex, so that triangles share their edges. The normals
// are ignored (the winding decides the outside).
#pragma once
#include <string>

#include "tet/TriangleMesh.h"

namespace tetglow {

// Whether `data` has the size of a binary STL with the triangle count in its header.
bool isBinaryStl(const std::string& data);

// The STL file `data` read from `path`. Throws InputError "<path>: <problem>" (with the line for ASCII).
TriangleMesh parseStl(const std::string& data, const std::string& path);

}  // namespace tetglow
