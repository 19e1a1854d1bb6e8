// Accumulates radiance samples per pixel (box filter) as exact fixed-point sums.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "base/Spectrum.h"
#include "render/Image.h"

namespace tetglow {

// A pixel's sum in units of 2^-60, one 128-bit integer per channel. Integer addition is
// associative, so the passes summed in any grouping (one running sum, or parts summed apart and
// merged) give the same bits; a double sum would not. Each sample is rounded once, on its own,
// to the unit (an error below 1e-18, far under a float's resolution). No overflow: a sample is
// at most kMaxSample per channel (larger ones are dropped like NaN) and a pixel has fewer than
// 2^32 samples, so |sum| < 2^32 * 2^32 * 2^60 = 2^124 < 2^127.
using FixedSum = std::array<__int128, 3>;
inline constexpr double kFixedUnit = 0x1p60;  // fixed-point units per radiance unit
inline constexpr double kMaxSample = 0x1p32;  // the largest radiance a sample may carry

class Film {
public:
    Film(int width, int height) : width_(width), height_(height), sum_(size_t(width) * height), count_(sum_.size()) {}
    int width() const { return width_; }
    int height() const { return height_; }
    size_t pixelCount() const { return sum_.size(); }
    // Non-finite samples are dropped and counted, so one bad path cannot ruin a pixel. A finite
    // sample beyond kMaxSample is counted too, and image() refuses the film: dropping it would
    // darken the image without a word (a scene's lights or emission too bright to store).
    void add(int x, int y, const RGB& L) {
        const size_t i = size_t(y) * width_ + x;
        ++count_[i];
        if (!isFinite(L)) {
            ++dropped_[i];
            return;
        }
        if (std::abs(L.x) > kMaxSample || std::abs(L.y) > kMaxSample || std::abs(L.z) > kMaxSample) {
            ++tooBright_[i];
            return;
        }
        for (int c = 0; c < 3; ++c) sum_[i][c] += static_cast<__int128>(L[c] * kFixedUnit);
    }
    // Adds the samples of another film of the same size (other passes of the same pixels):
    // exact, so the order of merging does not matter. False if the sizes differ.
    bool merge(const Film& other);
    // The mean of every pixel's own samples: after an interrupted pass some pixels have one
    // more sample than others, and each is still an unbiased estimate. Throws InputError, naming
    // the first such pixel, if a sample was beyond kMaxSample.
    Image image() const;
    uint64_t droppedSamples() const;

    // The raw state, for partial-render files (render/PartialRender.h).
    FixedSum& sum(size_t i) { return sum_[i]; }
    uint32_t& count(size_t i) { return count_[i]; }
    uint32_t& dropped(size_t i) { return dropped_[i]; }
    const FixedSum& sum(size_t i) const { return sum_[i]; }
    uint32_t count(size_t i) const { return count_[i]; }
    uint32_t dropped(size_t i) const { return dropped_[i]; }

private:
    int width_, height_;
    std::vector<FixedSum> sum_;
    std::vector<uint32_t> count_;
    std::vector<uint32_t> dropped_ = std::vector<uint32_t>(count_.size());
    std::vector<uint32_t> tooBright_ = std::vector<uint32_t>(count_.size());
};

}  // namespace tetglow
