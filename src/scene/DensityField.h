// Evaluates a medium's density description at points (the tet vertices).
#pragma once
#include <vector>

#include "scene/SceneDescription.h"

namespace tetglow {

// Non-negative: negative values of the linear field are clamped to 0.
double evaluateDensity(const DensityDesc& density, const glm::dvec3& p);
std::vector<double> evaluateDensity(const DensityDesc& density, const std::vector<glm::dvec3>& points);

}  // namespace tetglow
