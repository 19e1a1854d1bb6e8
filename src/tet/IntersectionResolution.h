// Triangles that cross each other, split along their intersections, so that they meet only at
// shared edges and vertices: a valid constraint set for TetGen.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "tet/TriangleMesh.h"

namespace tetglow {

// Removes exactly repeated and zero-area triangles and merges duplicate faces (the same three
// corners in any order; the first kept), then the vertices no triangle uses. Positions must
// already be welded.
struct SoupCleaning {
    size_t degenerate = 0, duplicates = 0;
    std::vector<glm::dvec3> degenerateAt, duplicateAt;  // a corner of each one dropped
};
SoupCleaning dropDegenerateAndDuplicates(TriangleMesh& soup);

// The constraint surface of a repair: no two of its triangles cross.
struct ResolvedSurface {
    TriangleMesh surface;
    // Crossing triangles that could not be split and were left out of `surface` (the boundary
    // near them then follows the tets the winding number labels), and why.
    size_t unsplit = 0;
    std::string unsplitReason;
};

// `soup`: float vertices, welded and cleaned as above; `crossings`: its findSelfIntersections
// (SelfIntersection.h), which the caller has already. Splits every intersecting pair with CGAL's
// autorefinement (exact predicates; intersection points constructed exactly, then rounded to
// double), rounds the new vertices to float for Embree, welds and cleans, and checks again
// with exact predicates: rounding can make new crossings, which the next round splits.
// Coplanar overlaps and contacts in a triangle's plane are split first (splitCoplanarOverlaps).
// Where CGAL fails, splitting would take minutes (too many points where three triangles cross)
// or crossings remain after a few rounds, the triangles still crossing are left out, so that
// the rest stays exact.
ResolvedSurface resolveIntersections(const TriangleMesh& soup, std::vector<std::pair<uint32_t, uint32_t>> crossings);

}  // namespace tetglow
