// Owen-scrambled, shuffled Sobol points with hashing (Burley 2020, "Practical Hash-based Owen
// Scrambling"): the first two dimensions of Sobol's sequence form a (0,2)-sequence in base 2,
// so every aligned block of 2^k consecutive points is a (0,k,2)-net: each elementary interval
// of area 2^-k holds exactly one point. Higher dimensions are padded with more such pairs,
// each with its own shuffle of the index and its own scrambles, as pbrt-v4's PaddedSobolSampler
// and Cycles do: every pair is a well stratified 2D set and distinct pairs are independent.
#pragma once
#include <cstdint>

namespace tetglow {

inline uint32_t reverseBits(uint32_t v) {
    v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
    v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
    v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
    v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
    return (v >> 16) | (v << 16);
}

// Sobol's first dimension is the van der Corput sequence, reverseBits(index). Its second's
// generator matrix is Pascal's triangle mod 2, whose columns follow from the first by c ^= c >> 1.
// Owen scrambling works on reversed bits, so these tables hold the columns' sums reversed
// (reversal distributes over xor): reverseBits of the second dimension, with no reversal to undo.
// Shuffled indices use all 32 bits, so the product with the matrix is taken a byte at a time.
struct SobolDimension1Table {
    uint32_t byte[4][256];
};
constexpr SobolDimension1Table makeReversedSobolDimension1Table() {
    uint32_t columns[32] = {};
    uint32_t c = 1u << 31;
    for (int i = 0; i < 32; ++i, c ^= c >> 1)
        for (int bit = 0; bit < 32; ++bit)
            if ((c >> bit) & 1) columns[i] |= 1u << (31 - bit);
    SobolDimension1Table table{};
    for (int b = 0; b < 4; ++b)
        for (int value = 0; value < 256; ++value)
            for (int i = 0; i < 8; ++i)
                if ((value >> i) & 1) table.byte[b][value] ^= columns[8 * b + i];
    return table;
}
inline constexpr SobolDimension1Table kReversedSobolDimension1 = makeReversedSobolDimension1Table();

// reverseBits of Sobol's second dimension at `index`.
inline uint32_t reversedSobolDimension1(uint32_t index) {
    const auto& t = kReversedSobolDimension1.byte;
    return t[0][index & 255] ^ t[1][(index >> 8) & 255] ^ t[2][(index >> 16) & 255] ^ t[3][index >> 24];
}

// Laine and Karras's hash-based permutation, with Burley's constants: each output bit depends
// only on the same and the lower input bits, so it is a nested permutation of binary intervals.
// On reversed bits, reverseBits(laineKarrasPermutation(reverseBits(v), seed)), it is an Owen
// scramble of a point's 32 bits (the higher bits decide how the lower ones flip), or a shuffle of
// sample indices that maps every aligned block of 2^k indices onto another one.
inline uint32_t laineKarrasPermutation(uint32_t v, uint32_t seed) {
    v += seed;
    v ^= v * 0x6c50b47cu;
    v ^= v * 0xb82f1e52u;
    v ^= v * 0xc7afe638u;
    v ^= v * 0x8d22f6e6u;
    return v;
}

}  // namespace tetglow
