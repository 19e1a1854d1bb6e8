// The interior of a mesh that does not separate inside from outside (holes, crossing parts,
// flipped or duplicated faces, non-manifold edges): Jacobson, Kavan and Sorkine-Hornung 2013.
// The input's triangles, their crossings split exactly, constrain a Delaunay tetrahedralization
// of a box around them; every tet is inside where the generalized winding number of the input
// at its centroid exceeds 1/2, and where that is uncertain (within 1/4 of 1/2, away from the
// input's triangles) a minimum cut trades it against the area of the faces spanning a hole
// (InsideLabels.h). The medium's boundary is then the input's triangles (or their
// pieces) wherever the input has a surface, and tet faces across its holes.
#pragma once
#include "tet/MeshValidation.h"
#include "tet/RepairClock.h"

namespace tetglow {

// Replaces `mesh` by the closed, outward boundary of its inside tets (float vertices, no
// crossings: it then passes validateAndRepair, parts that touch along an edge kept as they are,
// pinchedEdges). Throws InputError when the mesh encloses no volume: no tet is inside, as for a
// flat sheet, whose winding number stays below 1/2 on both sides. A curved open shell (a dome)
// encloses the lens between it and the surface spanning its rim, where its winding number exceeds 1/2.
// Each stage reports to `clock` as it ends, and RepairTimeout stops the repair when its bound is
// reached (also inside the stages that take long: TetGen on the box, the winding numbers).
RepairReport repairInterior(TriangleMesh& mesh, const RepairClock& clock = RepairClock());

// validateAndRepair; where that refuses the mesh (other than for non-finite coordinates or no
// triangles), repairInterior and then validateAndRepair, unless `strict`: then the refusal,
// with every problem found counted and located. Where the repair fails other than for a mesh
// that encloses no volume (or when it takes longer than `timeLimit` seconds), approximateSurface.
ValidationReport prepareSurface(TriangleMesh& mesh, bool strict, double timeLimit = kRepairTimeLimit);

// Replaces `mesh` by the boundary of the grid cells its winding number puts inside
// (windingGridBoundary), validated, with `reason` (why the exact path failed) and every problem
// of the input (surveyProblems) in the report's repair.approximateReason.
ValidationReport approximateSurface(TriangleMesh& mesh, const std::string& reason);

// Every problem validation refuses, counted, each kind with the position of its first case
// ("" for a valid mesh). Positions must be finite.
std::string surveyProblems(const TriangleMesh& mesh);

}  // namespace tetglow
