#pragma once
// Irradiance at points as the preview sees it, for calculation grids (grid_calculation.h): a
// hemicube of preview frames at each point (Cohen and Greenberg 1985), the top face along the
// point's normal and the upper halves of four side faces, each texel's radiance weighted by the
// cosine and the solid angle it subtends. The preview's own light comes with it: VPL indirect
// light, shadow-mapped direct light reflected by the surfaces, emitters seen directly; delta
// lights shining on the point itself are the caller's (no frame can see them); a sun with a disc
// is added directly (Preview::sunDiscIrradiance: a ray toward it), the sky seen in the frames.

#include "render/preview/preview.h"
#include "render/trace/sensor.h"

#include <array>
#include <memory>
#include <vector>

namespace lucerna {

class PreviewIrradiance {
public:
    // A preview of `scene` rendering faces of faceSize x faceSize pixels.
    PreviewIrradiance(SceneSnapshot scene, const PreviewSettings& settings, int faceSize = 32);

    // New VPLs and area-light samples (a pass of the calculation).
    void regenerate(uint64_t seed) { preview_.regenerate(seed); }
    // E (W/m^2 per channel) at the sensor from what the preview draws around it, its faces'
    // pixels sampled at (jitterX, jitterY) within each pixel.
    Rgb irradiance(const IrradianceSensor& sensor, float jitterX, float jitterY);

private:
    struct Face {
        V3f forward, up;                       // in the sensor's frame: x, y, z = tangent, bitangent, normal
        std::vector<float> weight;             // cos theta d omega per pixel, row-major
    };
    Preview preview_;
    int size_;
    std::array<Face, 5> faces_;
};

}  // namespace lucerna
