#include "render/Film.h"

#include <cstdio>
#include <limits>
#include <string>

#include <glm/common.hpp>

#include "tet/TriangleMesh.h"  // InputError

namespace tetglow {

Image Film::image() const {
    Image image(width_, height_);
    for (size_t i = 0; i < sum_.size(); ++i) {
        if (!count_[i]) continue;
        const RGB mean = sum_[i] / double(count_[i]);
        // The image stores floats: a larger mean would become +Inf without a word.
        if (maxComponent(glm::abs(mean)) > std::numeric_limits<float>::max()) {
            char value[32];
            std::snprintf(value, sizeof value, "%.6g", maxComponent(glm::abs(mean)));
            throw InputError("pixel (" + std::to_string(i % width_) + ", " + std::to_string(i / width_) + ") is " + value +
                             ", beyond the image's 32-bit float range (at most 3.40282e38): the lights or the emission are too bright");
        }
        image.pixels[i] = glm::vec3(mean);
    }
    return image;
}

uint64_t Film::droppedSamples() const {
    uint64_t n = 0;
    for (uint32_t d : dropped_) n += d;
    return n;
}

}  // namespace tetglow
