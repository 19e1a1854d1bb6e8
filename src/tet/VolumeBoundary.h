// Several closed surfaces as one input for TetGen (a piecewise linear complex): coincident
// vertices and shared triangles merged, the nesting found exactly, and for every triangle the
// regions on its two sides. Region r is the space inside surface r and outside the surfaces
// nested directly in it (its children); outside every surface is no region (-1).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "tet/TriangleMesh.h"

namespace tetglow {

struct VolumeBoundary {
    // All surfaces; each triangle wound as the first surface holding it winds it.
    TriangleMesh surface;
    // Per triangle: the region behind it (where its normal points away from) and in front.
    std::vector<std::array<int32_t, 2>> sides;
    // Per triangle: {input surface, triangle index in it} of the winding kept.
    std::vector<std::array<uint32_t, 2>> source;
    std::vector<int32_t> parent;           // per region: the region around it, -1 none
    std::vector<glm::dvec3> insidePoints;  // per region: a point strictly inside it (TetGen -A), see placeInsidePoints

    size_t regionCount() const { return parent.size(); }
};

// One region behind every triangle of one closed surface, no inside points: TetGen's input as it is.
VolumeBoundary singleRegion(const TriangleMesh& surface);

// From validated surfaces (validateAndRepair), named in messages by `names`, without inside points.
// Throws InputError when two surfaces cross or touch other than along shared triangles (naming
// both and one pair of triangles) or have the same inside.
VolumeBoundary buildVolumeBoundary(const std::vector<TriangleMesh>& surfaces, const std::vector<std::string>& names);

// Validates and repairs each surface (prepareSurface; errors prefixed with its name), then
// builds their boundary as above.
VolumeBoundary validatedBoundary(std::vector<TriangleMesh> surfaces, const std::vector<std::string>& names,
                                 bool strict = false);

// Fills boundary.insidePoints; the surfaces and names are the ones it was built from. Throws InputError
// naming a region that its children leave no room.
void placeInsidePoints(VolumeBoundary& boundary, const std::vector<TriangleMesh>& surfaces,
                       const std::vector<std::string>& names);

}  // namespace tetglow
