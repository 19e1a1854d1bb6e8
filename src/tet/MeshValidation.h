// Checks and repairs a triangle mesh before TetGen sees it. Every failure is an InputError whose
// one-line message names the problem and the first offending face, edge or vertex.
#pragma once
#include <string>
#include <vector>

#include "tet/RepairReport.h"
#include "tet/TriangleMesh.h"

namespace tetglow {

struct ValidationReport {
    size_t weldedVertices = 0;       // exact duplicate positions merged
    size_t unusedVertices = 0;       // vertices no triangle references, removed
    size_t flippedTriangles = 0;     // inward or inconsistent winding, fixed
    size_t oppositePairs = 0;        // faces that cancel (cancelOppositeFaces), removed
    size_t components = 0;           // closed shells
    size_t droppedShells = 0;        // shells with inside on both sides (nested, wound alike)
    double volume = 0;               // enclosed volume after repair
    std::vector<std::string> notes;  // what was repaired, one line each
    RepairReport repair;             // a broken mesh's repair (see InteriorRepair.h)
};

// In order: finite coordinates; positions snapped to float (Embree's precision, so Embree and
// the tets see bit-identical vertices); exact duplicate vertices welded; unused vertices
// removed; no degenerate (repeated or collinear corners) or duplicate triangles; every edge
// shared by exactly two triangles; no self-intersections; each shell wound consistently and
// outward from the inside it bounds, inside being where the winding number of the mesh as given
// exceeds 1/2 (fixed, not rejected; a shell with inside on both sides is dropped); positive
// volume. With `pinchedEdges`, an edge may also have an even number of triangles, at least
// four: closed parts that touch along it, as a repaired surface has them (a clean mesh with such
// an edge is refused, and repaired); such a surface is the boundary of a set of cells (tets,
// grid cells), each face wound outward from its cell, and keeps its winding and every shell: a
// shell through a pinched edge need not close on its own, so nesting cannot be judged by shells.
ValidationReport validateAndRepair(TriangleMesh& mesh, bool pinchedEdges = false);

// "(x, y, z)", as messages give positions.
std::string formatPosition(const glm::dvec3& p);

// Its steps, for repairs that go further (see InteriorRepair):
// InputError unless every coordinate is finite and within float range, and the mesh is one
// float coordinates can shape (precisionProblem).
void checkFinite(const TriangleMesh& mesh);
// Why float coordinates (the tets', Embree's) cannot shape a mesh with these bounds, or "": it is
// under kSmallestMesh across (its corners would be denormal or zero), or it spans fewer than
// kFloatStepsAcross float steps where it lies (every corner would snap to a few points).
std::string precisionProblem(const Bounds3& box);
inline constexpr double kSmallestMesh = 1e-30, kFloatStepsAcross = 128;
struct WeldCounts {
    size_t welded = 0, unused = 0;
};
// Snaps positions to float, merges identical positions and drops unreferenced vertices.
WeldCounts weldVertices(TriangleMesh& mesh);
// Two faces with the same three corners (once welded) wound opposite ways add nothing to the
// generalized winding number, so the solid is the same without them; a volume mesh saved as
// every cell's faces has each inner face twice, so. Removes every such pair (of a face there
// more often one way, the first ones that way stay), and likewise the two pairs of triangles
// that make one flat convex quad wound both ways along different diagonals, then the vertices
// only they used; returns the number of pairs of triangles. A mesh without such pairs is left
// exactly as it is.
size_t cancelOppositeFaces(TriangleMesh& mesh);
// Exactly collinear corners (a zero-area triangle).
bool collinear(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

}  // namespace tetglow
