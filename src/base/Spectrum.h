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
// Channels equal to an earlier one (grey media, and often two of three) take its value: the same
// bits for one exponential fewer.
inline RGB exp(const RGB& c) {
    const double x = std::exp(c.x), y = c.y == c.x ? x : std::exp(c.y);
    return {x, y, c.z == c.x ? x : c.z == c.y ? y : std::exp(c.z)};
}

}  // namespace tetglow
