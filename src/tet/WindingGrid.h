// The last resort of a repair: where no constrained tetrahedralization of a mesh's triangles can
// be had (CGAL cannot split its crossings, TetGen fails on what they become), the inside is
// sampled instead. The cells of a regular grid whose centres the generalized winding number of
// the mesh puts inside (above 1/2) make a solid whose boundary is axis-aligned squares: nothing
// can cross it, whatever rounding does to its corners, so TetGen always gets valid input. The
// boundary is approximate, within a cell of the input's surface.
#pragma once
#include "tet/TriangleMesh.h"

namespace tetglow {

// Cells along the longest side of the mesh's bounds: the boundary lies within about 1/128 of
// the mesh's size of the input, which keeps the volume of a sphere within 1%.
inline constexpr int kWindingGridCells = 48;

// The outward boundary of the inside cells (two triangles a square face, float corners, parts
// that touch along an edge or a corner kept as they are: validateAndRepair's pinchedEdges).
// Throws InputError when no cell is inside.
TriangleMesh windingGridBoundary(const TriangleMesh& soup, int cells = kWindingGridCells);

}  // namespace tetglow
