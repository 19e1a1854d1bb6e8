// Random numbers that depend only on where they are used (pixel, sample, photon), never on
// which thread uses them: the same seed gives the same image at any thread count.
#pragma once
#include <cstdint>

namespace tetglow {

// A bijective 64-bit mix (splitmix64's finaliser): neighbouring keys give unrelated seeds.
inline uint64_t mixBits(uint64_t v) {
    v ^= v >> 30, v *= 0xbf58476d1ce4e5b9ull;
    v ^= v >> 27, v *= 0x94d049bb133111ebull;
    return v ^ (v >> 31);
}

// PCG32 (O'Neill 2014): small state, good statistics, independent streams.
class Rng {
public:
    // One stream per (seed, key), e.g. key = pixel index, stream = sample index.
    Rng(uint64_t seed, uint64_t key, uint64_t stream = 0)
        : state_(0), inc_((mixBits(stream ^ mixBits(seed)) << 1) | 1) {
        next();
        state_ += mixBits(seed * 0x9e3779b97f4a7c15ull + key);
        next();
    }

    uint32_t next() {
        const uint64_t old = state_;
        state_ = old * 6364136223846793005ull + inc_;
        const auto xorshifted = uint32_t(((old >> 18) ^ old) >> 27);
        const auto rot = uint32_t(old >> 59);
        return (xorshifted >> rot) | (xorshifted << ((32 - rot) & 31));
    }
    // Uniform in [0, 1), 53 random bits.
    double uniform() {
        const uint64_t hi = next(), lo = next();
        return double(((hi << 32) | lo) >> 11) * 0x1.0p-53;
    }

private:
    uint64_t state_, inc_;
};

}  // namespace tetglow
