#pragma once
// An emissive triangle as the light sampler sees it: one-sided (SPEC.md), of uniform radiance.

#include "core/math.h"

#include <cstdint>

namespace lucerna {

struct EmitterTriangle {
    uint32_t triangle = 0;   // index into the render scene's triangles
    V3f p0, p1, p2;
    V3f normal;              // unit, front side
    float area = 0;          // scene units^2
    Rgb radiance;            // W sr^-1 m^-2, front side only
};

}  // namespace lucerna
