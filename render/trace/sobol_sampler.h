#pragma once
// A per-pixel low-discrepancy sample generator: the first dimensions of each sample come in pairs
// from the (0,2)-sequence formed by Sobol's first two dimensions, each pair with its own Owen
// scrambling and index shuffle (Burley 2020, "Practical Hash-based Owen Scrambling"), so that
// the samples of one pixel stratify every pair (camera jitter, the first light sample, the first
// BSDF sample, ...). Later dimensions come from PCG32 ("padding", as pbrt's PaddedSobolSampler).
//
// Unbiased like independent sampling, with less variance at any sample count, and best at powers
// of two. Deterministic in (seed, pixel, sample index).

#include "render/trace/rng.h"
#include "render/trace/sample_generator.h"

#include <cstdint>

namespace lucerna {

namespace sobol {

inline uint32_t reverseBits(uint32_t x) {
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
    return x;
}

// Burley's improved Laine-Karras hash: an Owen scramble of the bits in reversed order.
inline uint32_t laineKarras(uint32_t x, uint32_t seed) {
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

inline uint32_t nestedUniformScramble(uint32_t x, uint32_t seed) {
    return reverseBits(laineKarras(reverseBits(x), seed));
}

// Sobol dimension 1, which with dimension 0 (van der Corput: the index's bits reversed) makes a
// (0,2)-sequence: a linear map over GF(2) of the index bits (its generator matrix has the columns
// v_k, v_0 = 2^31, v_k+1 = v_k ^ (v_k >> 1)); evaluated byte by byte from tables, since the
// shuffled indices use all 32 bits.
struct Dimension1Tables {
    uint32_t byte[4][256];
    constexpr Dimension1Tables() : byte{} {
        uint32_t columns[32] = {};
        uint32_t v = 1u << 31;
        for (int k = 0; k < 32; ++k, v ^= v >> 1) columns[k] = v;
        for (int b = 0; b < 4; ++b)
            for (uint32_t x = 0; x < 256; ++x) {
                uint32_t r = 0;
                for (int k = 0; k < 8; ++k)
                    if (x & (1u << k)) r ^= columns[8 * b + k];
                byte[b][x] = r;
            }
    }
};
inline constexpr Dimension1Tables kDimension1Tables;

inline uint32_t dimension1(uint32_t i) {
    const auto& t = kDimension1Tables.byte;
    return t[0][i & 255u] ^ t[1][(i >> 8) & 255u] ^ t[2][(i >> 16) & 255u] ^ t[3][i >> 24];
}

inline float toUnit(uint32_t x) { return float(x >> 8) * 0x1p-24f; }

}  // namespace sobol

class SobolSampler final : public SampleGenerator {
public:
    // Dimensions drawn from the scrambled sequence; the rest from PCG32.
    static constexpr uint32_t kStratifiedDimensions = 16;

    SobolSampler(uint64_t pixelSeed, uint32_t sampleIndex)
        : seed_(pixelSeed), index_(sampleIndex), padding_(pixelSeed, sampleIndex) {}

    float next1D() override {
        if (dimension_ >= kStratifiedDimensions) return padding_.next1D();
        const uint32_t s = dimensionSeed();
        ++dimension_;
        // Owen-scrambled van der Corput: nestedUniformScramble(reverseBits(i)) = reverseBits(laineKarras(i)).
        return sobol::toUnit(sobol::reverseBits(sobol::laineKarras(shuffledIndex(s), s ^ 0x9e3779b9u)));
    }

    V2f next2D() override {
        if (dimension_ + 1 >= kStratifiedDimensions) return padding_.next2D();
        const uint32_t s = dimensionSeed();
        dimension_ += 2;
        const uint32_t i = shuffledIndex(s);
        return V2f(sobol::toUnit(sobol::reverseBits(sobol::laineKarras(i, s ^ 0x9e3779b9u))),
                   sobol::toUnit(sobol::nestedUniformScramble(sobol::dimension1(i), s ^ 0x7f4a7c15u)));
    }

private:
    uint32_t dimensionSeed() const { return uint32_t(hashSeed(seed_, dimension_)); }
    // Burley's shuffle: each dimension (pair) visits the sequence in its own random order.
    uint32_t shuffledIndex(uint32_t s) const { return sobol::nestedUniformScramble(index_, s); }

    uint64_t seed_;
    uint32_t index_;
    uint32_t dimension_ = 0;
    Rng padding_;
};

}  // namespace lucerna
