#include "render/Film.h"

#include <string>

#include "base/Error.h"

namespace tetglow {

bool Film::merge(const Film& other) {
    if (other.width_ != width_ || other.height_ != height_) return false;
    for (size_t i = 0; i < sum_.size(); ++i) {
        for (int c = 0; c < 3; ++c) sum_[i][c] += other.sum_[i][c];
        count_[i] += other.count_[i];
        dropped_[i] += other.dropped_[i];
        tooBright_[i] += other.tooBright_[i];
    }
    return true;
}

Image Film::image() const {
    Image image(width_, height_);
    for (size_t i = 0; i < sum_.size(); ++i) {
        if (tooBright_[i])
            throw InputError(
                "pixel (" + std::to_string(i % width_) + ", " + std::to_string(i / width_) +
                ") received radiance beyond the film's range (at most 4.29497e9 per sample): the lights or the "
                "emission are too bright; scale them down");
        if (count_[i])
            for (int c = 0; c < 3; ++c) image.pixels[i][c] = float(double(sum_[i][c]) / kFixedUnit / double(count_[i]));
    }
    return image;
}

uint64_t Film::droppedSamples() const {
    uint64_t n = 0;
    for (uint32_t d : dropped_) n += d;
    return n;
}

}  // namespace tetglow
