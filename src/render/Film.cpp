#include "render/Film.h"

namespace tetglow {

Image Film::image() const {
    Image image(width_, height_);
    for (size_t i = 0; i < sum_.size(); ++i)
        if (count_[i]) image.pixels[i] = glm::vec3(sum_[i] / double(count_[i]));
    return image;
}

uint64_t Film::droppedSamples() const {
    uint64_t n = 0;
    for (uint32_t d : dropped_) n += d;
    return n;
}

}  // namespace tetglow
