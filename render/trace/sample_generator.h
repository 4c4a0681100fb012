#pragma once
// Sample generators (pbrt-v4's layer between random numbers and warps): where the tracers take
// their uniform numbers from. Swapping the generator changes the method without touching the
// tracer: independent random numbers, a stratified low-discrepancy sequence per pixel, or the
// primary sample space state of a Metropolis chain.

#include "core/math.h"

namespace lucerna {

class SampleGenerator {
public:
    virtual ~SampleGenerator() = default;
    // Uniform in [0, 1): the next dimension(s) of the current sample.
    virtual float next1D() = 0;
    virtual V2f next2D() = 0;
};

}  // namespace lucerna
