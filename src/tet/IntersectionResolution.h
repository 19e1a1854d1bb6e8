// Triangles that cross each other, split along their intersections, so that they meet only at
// shared edges and vertices: a valid constraint set for TetGen.
#pragma once
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

// `soup`: float vertices, welded and cleaned as above. Splits every intersecting pair with CGAL's
// autorefinement (exact predicates; intersection points constructed exactly, then rounded to
// double), rounds the new vertices to float for Embree, welds and cleans, and checks again
// with exact predicates: rounding can make new crossings, which the next round splits, until
// none is left. Throws InputError, with a position, if crossings remain after a few rounds.
TriangleMesh resolveIntersections(const TriangleMesh& soup);

}  // namespace tetglow
