// Simple shapes built from parameters: scene primitives, validation geometry, test meshes.
#pragma once
#include "tet/TriangleMesh.h"

namespace tetglow {

// Closed and outward-wound.
TriangleMesh box(const glm::dvec3& lo = glm::dvec3(0), const glm::dvec3& hi = glm::dvec3(1));
// The icosahedron subdivided `subdivisions` times, vertices on the sphere: 20 * 4^s triangles.
TriangleMesh icosphere(int subdivisions, double radius = 1, const glm::dvec3& centre = glm::dvec3(0));
// Two vertex sets in one mesh.
TriangleMesh merge(const TriangleMesh& a, const TriangleMesh& b);

// Open shapes for surfaces and lights, facing along cross(edge0, edge1) and `normal`.
TriangleMesh quad(const glm::dvec3& corner, const glm::dvec3& edge0, const glm::dvec3& edge1);
TriangleMesh disk(const glm::dvec3& centre, const glm::dvec3& normal, double radius, int sides = 64);

}  // namespace tetglow
