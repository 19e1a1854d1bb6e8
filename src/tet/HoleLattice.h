// Points TetGen inserts around each hole of a repaired soup, so that the winding number at the
// centroids of small tets places the surface that spans it (see holeLattice).
#pragma once
#include <vector>

#include <glm/vec3.hpp>

#include "tet/PartWinding.h"
#include "tet/SoupEdges.h"
#include "tet/TriangleMesh.h"

namespace tetglow {

// Points TetGen inserts around each hole (rim edges connected through their corners): a lattice
// filling a ball around the rim, so that the tets across the hole are small enough for the
// winding number at their centroids to place the spanning surface, and none reaches from far
// inside through the hole to the box. Refining the whole box instead (-q) costs many times the
// clean path. The lattice is as fine as the rim's edges but at most kLatticeAcross points
// across a ball, kLatticeBudget points in all; offset so that it misses the planes of
// axis-aligned faces, rounded to float like every vertex of the repaired surface, and only
// strictly inside `box` (a ball may reach past the padded box TetGen fills). A hole
// less than kSmallHole rim edges across gets none: the tets between its rim vertices span it
// flat, where lattice points beside the surface would let tets poke out of it. Nor does a
// crack, rims that run both ways along the same curve, as where a CAD exporter tessellates
// each face of a solid on its own (T-junctions): its rim's vector area is next to nothing
// (below kCrack of its length times its edges' length, where an open hole has at least half
// that length times its radius), and the winding number beside it is whole.
std::vector<glm::dvec3> holeLattice(const TriangleMesh& soup, const EdgeMap& edges, const PartWinding& winding,
                                    const Bounds3& box, const glm::dvec3& offset);

}  // namespace tetglow
