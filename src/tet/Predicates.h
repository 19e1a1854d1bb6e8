// Shewchuk's adaptive exact predicates, as exported by libtet (predicates.cxx).
#pragma once
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace tetglow {

// > 0 when d lies below the plane through a, b, c (a, b, c counter-clockwise seen from above):
// Shewchuk's sign convention, exact.
double orient3d(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d);
// > 0 when a, b, c are counter-clockwise, exact.
double orient2d(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c);

}  // namespace tetglow
