// How far an image is from its converged self, estimated from the image alone: its passes split
// into two interleaved half-images, and their difference measures the noise.
#pragma once
#include <cstdint>
#include <optional>

#include "render/Film.h"

namespace tetglow {

// The split: the even passes make the first half, the odd ones the second.
inline bool inFirstHalf(int pass) { return pass % 2 == 0; }

// The relative MSE of `all`'s image against the converged image, in the metric of compare()
// (render/Image.h): the mean over pixels and channels of (a - b)^2 / (b^2 + kRelMseFloor), with
// the image itself in place of the unknown b. `half` holds the samples of the passes inFirstHalf.
// It measures variance only: the error every pass shares (a biased integrator's bias, such as the
// photon integrator's blur) cancels in the difference. Computed in one serial loop over the
// exact sums, so it is the same number at any thread count. None before each half has a sample.
std::optional<double> estimateRelMse(const Film& all, const Film& half);

// The same estimate over any set of pixels (a tile's, for adaptive sampling): their terms summed
// one pixel at a time, in the caller's order.
struct RelMseSum {
    double sum = 0;
    size_t terms = 0;
    void addPixel(const Film& all, const Film& half, size_t i);
    std::optional<double> mean() const { return terms ? std::optional(sum / double(terms)) : std::nullopt; }
};

}  // namespace tetglow
