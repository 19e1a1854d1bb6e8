// Triangles that overlap in their common plane (a letter's bottom face on a ground quad, two
// boxes' faces pressed together) or touch one another's plane along an edge or at a corner
// without crossing it, split along each other's edges: CGAL 5.5's autorefinement gives up on
// most such contacts ("non-handled triple intersection").
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "tet/TriangleMesh.h"

namespace tetglow {

// Replaces every set of coplanar triangles that cross one another (pairs from `crossings`, as
// findSelfIntersections gives them), and every triangle that another touches in its plane, by a
// triangulation of their union in which each of their edges, and each edge or corner touching
// them, is a union of edges or a vertex: the exact constrained Delaunay triangulation in the
// plane, keeping the faces inside one of them, its new vertices lifted exactly onto the plane
// and rounded to double. Overlapping area is covered once. Triangles that cross transversally
// are left to CGAL. The rest of `soup` is unchanged; new vertices are appended, so the caller
// welds. Returns whether it replaced anything.
bool splitCoplanarOverlaps(TriangleMesh& soup, const std::vector<std::pair<uint32_t, uint32_t>>& crossings);

}  // namespace tetglow
