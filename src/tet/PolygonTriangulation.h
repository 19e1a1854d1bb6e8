// Polygons of a mesh file (OBJ, OFF and PLY faces) as triangles: a convex polygon as its fan
// (v0 vk vk+1), a concave one by ear clipping in its plane, the plane's normal being Newell's
// (the polygon's vector area, defined for polygons that are not quite flat). The tests are exact
// (orient2d on the coordinates projected by dropping the normal's largest axis), so a polygon is
// clipped into triangles that neither overlap nor leave gaps, as Assimp and Blender triangulate.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace tetglow {

// The concave polygons clipped into ears have at most this many corners (clipping costs the
// corners times the reflex corners); convex ones of any size are fanned.
inline constexpr size_t kMaxConcavePolygonCorners = 20000;

// The triangles of `polygon` (indices into `positions`, each in range, at least 3), appended to
// `triangles` with the polygon's winding. A polygon whose outline crosses or touches itself has
// no triangulation without overlap: an InputError starting with `where` ("file:line: ").
void triangulatePolygon(const std::vector<glm::dvec3>& positions, const std::vector<uint32_t>& polygon,
                        std::vector<std::array<uint32_t, 3>>& triangles, const std::string& where);

}  // namespace tetglow
