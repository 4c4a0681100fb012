#pragma once
// PCG32 (O'Neill 2014): small state, good statistics, and independent streams per pixel and pass,
// which is what makes a render reproducible bit for bit with --seed and --threads 1.

#include "core/math.h"
#include "render/trace/sample_generator.h"

#include <cstdint>

namespace lucerna {

class Rng final : public SampleGenerator {
public:
    Rng(uint64_t seed = 0x853c49e6748fea9bULL, uint64_t stream = 0xda3e39cb94b95bdbULL) { seedWith(seed, stream); }

    void seedWith(uint64_t seed, uint64_t stream) {
        state_ = 0;
        inc_ = (stream << 1u) | 1u;
        nextUint();
        state_ += seed;
        nextUint();
    }

    uint32_t nextUint() {
        const uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + inc_;
        const uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
        const uint32_t rot = uint32_t(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((-rot) & 31));
    }

    // Uniform in [0, 1), never 1.
    float next1D() override { return float(nextUint() >> 8) * 0x1p-24f; }
    V2f next2D() override {
        const float a = next1D();
        return V2f(a, next1D());
    }
    double nextDouble() { return double(nextUint()) * 0x1p-32; }

private:
    uint64_t state_ = 0, inc_ = 1;
};

// Mixes several integers into one well-spread seed (SplitMix64 finaliser).
inline uint64_t hashSeed(uint64_t a, uint64_t b = 0, uint64_t c = 0) {
    uint64_t z = a * 0x9e3779b97f4a7c15ULL ^ (b + 0x632be59bd9b4e019ULL) * 0xbf58476d1ce4e5b9ULL ^
                 (c + 0x7f4a7c159e3779b9ULL) * 0x94d049bb133111ebULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

}  // namespace lucerna
