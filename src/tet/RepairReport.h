// What the repair of a broken mesh did (see InteriorRepair.h), for the summary line, --json and
// the spanned faces in a VTK file.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace tetglow {

struct RepairReport {
    bool applied = false;  // false: the mesh passed validation and took the exact path
    std::string reason;    // the validation failure that started the repair
    size_t degenerateDropped = 0, duplicatesDropped = 0, flippedTriangles = 0;
    size_t holeEdges = 0, nonManifoldEdges = 0, crossingPairs = 0, partsUnioned = 0;
    size_t unsplitTriangles = 0;  // crossing triangles CGAL could not split, left out of the constraints
    size_t latticePoints = 0;     // points added around the holes (none around small holes and cracks)
    std::string unsplitReason;
    // Why the boundary is the winding number's labels on a grid (WindingGrid.h) instead of the
    // input's triangles: the exact repair, or TetGen on its result, failed ("" when not).
    std::string approximateReason;
    struct Hole {
        glm::dvec3 centre{0};  // area-weighted centroid of the faces spanning it
        double area = 0;
        size_t faces = 0;
    };
    std::vector<Hole> holes;  // connected sets of spanned faces
    double spannedArea = 0, boundaryArea = 0;
    double minWinding = 0, maxWinding = 0;  // over the tets' centroids
    // A corner of each (at most kMaxPositions of each kind are kept).
    std::vector<glm::dvec3> crossingAt, flippedAt, duplicateAt, degenerateAt;
    // Triangles of the repaired surface that are tet faces across a hole, not input triangles.
    std::vector<uint32_t> spannedTriangles;

    static constexpr size_t kMaxPositions = 100;
    std::string summary() const;  // one line
};

}  // namespace tetglow
