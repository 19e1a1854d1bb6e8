// A stored photon: 32 bytes, so that millions fit in cache-friendly arrays.
#pragma once
#include <cstdint>

#include <glm/vec3.hpp>

namespace tetglow {

struct Photon {
    glm::vec3 position;
    glm::vec3 power;     // flux carried, per RGB channel
    uint32_t direction;  // incoming direction (the photon travels along it), octahedral 2 x 16 bit
    float radius;        // beam estimate: the photon's disc radius (0 until assigned)
};
static_assert(sizeof(Photon) == 32);

}  // namespace tetglow
