#pragma once
// Sample generators (pbrt-v4's layer between random numbers and warps): where the tracers take
// their uniform numbers from. Swapping the generator changes the method without touching the
// tracer: independent random numbers, a stratified low-discrepancy sequence per pixel, or the
// primary sample space state of a Metropolis chain.

#include "core/math.h"

namespace lucerna {

// The parts of a bidirectional sample. Metropolis samplers keep each part on its own coordinates
// (pbrt-v3's MLTSampler streams), so that a kernel that changes one part leaves the numbers of
// the others in place; other generators ignore the distinction.
enum class SampleStream { Camera = 0, Light = 1, Connection = 2 };
inline constexpr int kSampleStreams = 3;

class SampleGenerator {
public:
    virtual ~SampleGenerator() = default;
    // The following numbers belong to `stream` (each stream continues where it left off).
    virtual void beginStream(SampleStream) {}
    // Uniform in [0, 1): the next dimension(s) of the current sample.
    virtual float next1D() = 0;
    virtual V2f next2D() = 0;
};

}  // namespace lucerna
