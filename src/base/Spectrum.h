// Light is carried as linear RGB in double precision.
#pragma once
#include <algorithm>
#include <cmath>

#include <glm/vec3.hpp>

namespace tetglow {

using RGB = glm::dvec3;

inline double maxComponent(const RGB& c) { return std::max({c.x, c.y, c.z}); }
inline double minComponent(const RGB& c) { return std::min({c.x, c.y, c.z}); }
inline double average(const RGB& c) { return (c.x + c.y + c.z) / 3; }
inline bool isBlack(const RGB& c) { return c.x == 0 && c.y == 0 && c.z == 0; }
inline bool isFinite(const RGB& c) { return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z); }
inline RGB exp(const RGB& c) { return {std::exp(c.x), std::exp(c.y), std::exp(c.z)}; }

}  // namespace tetglow
