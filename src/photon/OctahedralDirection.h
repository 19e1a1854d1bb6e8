// Unit directions in 32 bits (Photon::direction): the octahedral map (Cigolle et al. 2014,
// "A Survey of Efficient Representations for Independent Unit Vectors") folds the sphere onto
// [-1, 1]^2, stored as two 16-bit snorms. Snorm keeps 0 and +-1 exact, so the axes round-trip
// exactly; elsewhere the angular error stays below 1e-4 rad.
#pragma once
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/packing.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace tetglow {

namespace octahedral {
// The lower hemisphere's triangles fold out over the corners of the square, and back.
inline glm::vec2 fold(glm::vec2 p) {
    return {(1 - std::abs(p.y)) * std::copysign(1.0f, p.x), (1 - std::abs(p.x)) * std::copysign(1.0f, p.y)};
}
}  // namespace octahedral

inline uint32_t packDirection(glm::vec3 unit) {
    glm::vec2 p = glm::vec2(unit.x, unit.y) / (std::abs(unit.x) + std::abs(unit.y) + std::abs(unit.z));
    if (unit.z < 0) p = octahedral::fold(p);
    return glm::packSnorm2x16(p);
}

inline glm::vec3 unpackDirection(uint32_t packed) {
    glm::vec2 p = glm::unpackSnorm2x16(packed);
    const float z = 1 - std::abs(p.x) - std::abs(p.y);
    if (z < 0) p = octahedral::fold(p);
    return glm::normalize(glm::vec3(p, z));
}

}  // namespace tetglow
