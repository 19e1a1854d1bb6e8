// Which closed surface lies inside which: exact, from the surfaces alone (no tets needed).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "tet/TriangleMesh.h"

namespace tetglow {

enum class PointSide { Inside, Outside, OnSurface };

// p against a closed, outward-wound surface, exactly: crossings of a segment from p to a point
// far outside, counted with exact predicates; a segment through an edge or a vertex (an exact
// zero) is replaced by another, so no crossing is ever guessed.
PointSide classifyPoint(const TriangleMesh& surface, const glm::dvec3& p);

// The nesting of closed surfaces that touch at most along shared vertices, edges and triangles
// (the caller has checked that they do not cross). `vertexIds[i][v]` is a common id of vertex v
// of surface i: equal ids are the same point. parent[i] is the innermost surface holding
// surface i, or -1. Throws InputError, naming both surfaces, when two have the same inside.
std::vector<int32_t> findNesting(const std::vector<TriangleMesh>& surfaces,
                                 const std::vector<std::vector<uint32_t>>& vertexIds,
                                 const std::vector<std::string>& names);

}  // namespace tetglow
