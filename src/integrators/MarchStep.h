// Ray marches take one sample per step. A step too small for the scene would run for ever: by
// the number of steps, or, below the precision of the coordinates, because t + step == t. Every
// march checks its step here before it starts.
#pragma once
#include <string>

#include "tet/TriangleMesh.h"  // Bounds3

namespace tetglow {

inline constexpr double kMaxStepsPerDiagonal = 1e6;

// InputError naming `what` unless step >= max(diagonal / kMaxStepsPerDiagonal, resolution), where
// `diagonal` is that of the box marched through and `resolution` the smallest length the march's
// coordinates still resolve.
void checkMarchStep(const std::string& what, double step, double diagonal, double resolution);

// The resolution of a march along rays from `origin` through `box`: 256 double ulps of the
// largest distance or coordinate on the way.
double resolutionOf(const Bounds3& box, const glm::dvec3& origin);

}  // namespace tetglow
