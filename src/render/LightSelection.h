// Which light next-event estimation samples at a point: each with probability proportional to
// Light::importance there (an unoccluded estimate of what it sends to the point), instead of
// uniformly, so that a dim environment does not take half the samples from a bright lamp.
#pragma once
#include <memory>
#include <vector>

#include "render/Light.h"

namespace tetglow {

struct LightChoice {
    const Light* light = nullptr;  // null where no light can reach p
    double pmf = 0;
};

LightChoice chooseLight(const std::vector<std::unique_ptr<Light>>& lights, const glm::dvec3& p, double u);
// The probability that chooseLight at p returns `light` (for MIS weights).
double choicePmf(const std::vector<std::unique_ptr<Light>>& lights, const Light& light, const glm::dvec3& p);

}  // namespace tetglow
