// Finds triangles of a mesh that intersect each other other than along the edges and vertices
// they share. TetGen cannot recover such a boundary and may crash on it.
#pragma once
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "tet/TriangleMesh.h"

namespace tetglow {

// The first intersecting pair (lowest first index), or nothing. Exact predicates; the mesh must
// already be free of degenerate triangles.
std::optional<std::pair<uint32_t, uint32_t>> findSelfIntersection(const TriangleMesh& mesh);
// Every intersecting pair (i < j), sorted; same preconditions.
std::vector<std::pair<uint32_t, uint32_t>> findSelfIntersections(const TriangleMesh& mesh);

// The closed segment pq meets the closed triangle abc (exact; p == q tests a point).
bool segmentMeetsTriangle(const glm::dvec3& p, const glm::dvec3& q, const std::array<glm::dvec3, 3>& triangle);

}  // namespace tetglow
