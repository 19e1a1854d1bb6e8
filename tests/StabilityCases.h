// Shapes and lines on which boundary methods break: a convex polyhedron (so the truth is a few
// exact plane tests), lines exactly through its vertices and edges or grazing its faces, thin
// plates, sliver tets.
#pragma once
#include <string>
#include <vector>

#include "tet/TetMesh.h"
#include "tet/TetTraversal.h"

namespace tetglow::test {

// The tets of `mesh`, tetrahedralized afresh (no cache).
TetTraversal tetsOf(const TriangleMesh& mesh);
// Expects tetrahedralizing `mesh` strictly (no repair) to fail with an InputError whose message
// contains `problem`.
void expectTetsRefuse(const TriangleMesh& mesh, const std::string& problem);

// A tilted, stretched icosahedron subdivided `subdivisions` times: convex, not aligned with its box.
TriangleMesh tiltedPolyhedron(int subdivisions = 1);
// A 1 x 1 x `thickness` box under a shear that leaves no face axis-aligned, so that its bounding
// box is mostly empty. For a power-of-two thickness down to 2^-20 every corner is an exact
// float: the faces stay exactly planar and the plate exactly convex.
TriangleMesh thinPlate(double thickness);
// Tets whose shape quality (volume over longest edge cubed, 1 for a regular tet) is below
// `quality` while no edge is shorter than a third of the longest: flat, not needle-like.
std::vector<uint32_t> slivers(const TetMesh& mesh, double quality);

struct NamedLine {
    std::string kind;
    Ray ray;  // unit direction, origin outside the shape
};
// For a convex mesh: axis-aligned lines exactly through every vertex and every edge midpoint
// (exact for float vertices), lines grazing faces at 1e-2 to 1e-8 radians, and lines touching
// the shape at a vertex only.
std::vector<NamedLine> degenerateLines(const TriangleMesh& convex);

}  // namespace tetglow::test
