// Accumulates radiance samples per pixel (box filter) in double precision.
#pragma once
#include <cstdint>
#include <vector>

#include "photon/Spectrum.h"
#include "render/Image.h"

namespace tetglow {

class Film {
public:
    Film(int width, int height) : width_(width), height_(height), sum_(size_t(width) * height), count_(sum_.size()) {}
    int width() const { return width_; }
    int height() const { return height_; }
    // Non-finite samples are dropped and counted, so one bad path cannot ruin a pixel.
    void add(int x, int y, const RGB& L) {
        const size_t i = size_t(y) * width_ + x;
        ++count_[i];
        if (isFinite(L)) sum_[i] += L;
        else ++dropped_[i];
    }
    // The mean of every pixel's own samples: after an interrupted pass some pixels have one
    // more sample than others, and each is still an unbiased estimate.
    Image image() const;
    uint64_t droppedSamples() const;

private:
    int width_, height_;
    std::vector<RGB> sum_;
    std::vector<uint32_t> count_;
    std::vector<uint32_t> dropped_ = std::vector<uint32_t>(count_.size());
};

}  // namespace tetglow
