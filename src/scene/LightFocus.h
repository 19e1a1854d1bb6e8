// Where a small light's emission comes from, for sampling scattering points along a ray near it
// (Equiangular): its centre and, for a spot light, a cone that holds every point it lights.
#pragma once
#include <optional>
#include <utility>

#include <glm/vec3.hpp>

#include "base/Ray.h"

namespace tetglow {

struct LightCone {
    glm::dvec3 apex, axis;  // axis unit
    double cosAngle;        // of the half angle, > 0
    // The part of [a, b] of the ray o + t d inside the cone (its forward nappe, convex, so one
    // interval), or null where none is.
    std::optional<std::pair<double, double>> clip(const Ray& ray, double a, double b) const;
    bool contains(const glm::dvec3& p) const;
};

struct LightFocus {
    glm::dvec3 centre;
    std::optional<LightCone> cone;  // nothing outside it is lit
};

}  // namespace tetglow
