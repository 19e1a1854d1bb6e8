#pragma once
#include <glm/vec3.hpp>

namespace tetglow {

struct Ray {
    glm::dvec3 o, d;  // d need not be unit length; t is in units of d
    glm::dvec3 at(double t) const { return o + d * t; }
};

}  // namespace tetglow
