// Which light next-event estimation samples at a point: each with probability proportional to
// Light::importance there (an unoccluded estimate of what it sends to the point), instead of
// uniformly, so that a dim environment does not take half the samples from a bright lamp.
// With `mis` (the caller counts the emitters its phase/BSDF rays hit, weighted by MIS) the
// constant environment is not chosen at all: those rays sample it at least as well as uniform
// directions do (by the phase function, or the cosine), and its share of the samples only added
// the choice's own noise to the other lights' (measured on blub.json: twice the variance).
#pragma once
#include <memory>
#include <vector>

#include "scene/Light.h"

namespace tetglow {

struct LightChoice {
    const Light* light = nullptr;  // null where no light can reach p
    double pmf = 0;
};

LightChoice chooseLight(const std::vector<std::unique_ptr<Light>>& lights, const glm::dvec3& p, bool mis, double u);
// The probability that chooseLight at p returns `light` (for MIS weights).
double choicePmf(const std::vector<std::unique_ptr<Light>>& lights, const Light& light, const glm::dvec3& p, bool mis);

}  // namespace tetglow
