#pragma once

#include "core/math.h"
#include "render/trace/ray_offset.h"

#include <cstdint>

namespace lucerna {

// A point on a surface, as the tracers need it.
struct SurfacePoint {
    V3f p;          // world position
    V3f pError;     // absolute floating-point error bound of p, per axis
    V3f ng;         // unit geometric normal, front side (counter-clockwise winding) as in SPEC.md
    uint32_t triangle = 0;
    uint32_t material = 0;

    // Origin for a ray leaving toward w, off the surface on w's side.
    V3f spawnOrigin(const V3f& w) const { return offsetRayOrigin(p, pError, ng, w); }
};

}  // namespace lucerna
