// Random numbers that depend only on where they are used (pixel, sample, photon), never on
// which thread uses them: the same seed gives the same image at any thread count.
#pragma once
#include <cstdint>

#include "sampling/Sobol.h"

namespace tetglow {

// A bijective 64-bit mix (splitmix64's finaliser): neighbouring keys give unrelated seeds.
inline uint64_t mixBits(uint64_t v) {
    v ^= v >> 30;
    v *= 0xbf58476d1ce4e5b9ull;
    v ^= v >> 27;
    v *= 0x94d049bb133111ebull;
    return v ^ (v >> 31);
}

// PCG32 (O'Neill 2014): small state, good statistics, independent streams. A pixel sample's
// generator (pixelSample) serves its first numbers from a padded Owen-scrambled Sobol sequence
// instead, so that the samples of a pixel are stratified over the pixel and the path's first
// events while the code that draws them stays the same.
class Rng {
public:
    // Dimensions served by Sobol points in a pixel sample: the pixel and the first events of
    // a path, where stratification pays. Deeper events see a point's dimensions mixed over
    // many paths of different lengths, which independent numbers serve as well, for less.
    static constexpr uint32_t kSobolDimensions = 32;

    // One stream per (seed, key), e.g. key = pixel index, stream = sample index.
    Rng(uint64_t seed, uint64_t key, uint64_t stream = 0)
        : state_(0), inc_((mixBits(stream ^ mixBits(seed)) << 1) | 1) {
        next();
        state_ += mixBits(seed * 0x9e3779b97f4a7c15ull + key);
        next();
    }

    // Sample `index` of pixel `pixel`: dimensions 2j, 2j+1 are the (0,2)-sequence's point at
    // `index` shuffled and scrambled by a hash of (seed, pixel, j); the first 2^k samples of a
    // pixel are a (0,k,2)-net in every such pair. Then the PCG stream of (seed, pixel, index).
    static Rng pixelSample(uint64_t seed, uint64_t pixel, uint32_t index) {
        Rng rng(seed, pixel, index);
        rng.sobolKey_ = mixBits(mixBits(seed ^ 0x5851f42d4c957f2dull) + pixel);
        rng.reversedIndex_ = reverseBits(index);
        rng.sobolDimensions_ = kSobolDimensions;
        return rng;
    }

    uint32_t next() {
        const uint64_t old = state_;
        state_ = old * 6364136223846793005ull + inc_;
        const auto xorshifted = uint32_t(((old >> 18) ^ old) >> 27);
        const auto rot = uint32_t(old >> 59);
        return (xorshifted >> rot) | (xorshifted << ((32 - rot) & 31));
    }
    // Uniform in [0, 1): 53 random bits, or a Sobol point's 32.
    double uniform() {
        if (dimension_ < sobolDimensions_) [[unlikely]]
            return sobolUniform();
        const uint64_t hi = next(), lo = next();
        return double(((hi << 32) | lo) >> 11) * 0x1.0p-53;
    }

private:
    // Out of line, so that uniform() stays small enough to inline for the PCG numbers.
    [[gnu::noinline]] double sobolUniform() {
        if (dimension_++ % 2) return pairSecond_;
        const uint64_t hash = mixBits(sobolKey_ + dimension_);
        // An Owen scramble, or the index's shuffle, is reverseBits(laineKarrasPermutation(
        // reverseBits(v), seed)) (Sobol.h). Its inner reversal is done already: the index is kept
        // reversed, the second dimension's table is, and the first dimension, reverseBits(index),
        // reversed again is the index itself.
        const uint32_t index = reverseBits(laineKarrasPermutation(reversedIndex_, uint32_t(hash)));
        pairSecond_ =
            reverseBits(laineKarrasPermutation(reversedSobolDimension1(index), uint32_t(mixBits(hash)))) * 0x1.0p-32;
        return reverseBits(laineKarrasPermutation(index, uint32_t(hash >> 32))) * 0x1.0p-32;
    }

    uint64_t state_, inc_;
    uint64_t sobolKey_ = 0;
    uint32_t reversedIndex_ = 0;  // the sample's index, its bits reversed
    uint32_t dimension_ = 0, sobolDimensions_ = 0;
    double pairSecond_ = 0;  // the pair's second coordinate, drawn with its first
};

}  // namespace tetglow
