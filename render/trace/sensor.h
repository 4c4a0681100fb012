#pragma once
// What a film measures: the pinhole camera of SPEC.md section 1, or a set of irradiance sensors
// (the points of a calculation grid, the surfaces behind the pixels of an illuminance layer).
// Backends see only rays through raster points, directions back to raster points and the
// density of those directions, so every backend renders either kind unchanged.
//
// An irradiance sensor owns a block of k x k pixels of a (n k) x k image, block i for point i.
// The block maps onto the hemisphere of the point's normal with the cosine-weighted polar map
// (r = sqrt(u), phi = 2 pi v): a raster point uniform over the block gives a direction of density
// cos / pi, so the block's mean pixel value is E / pi, E = int L cos dw the irradiance there
// (the light arriving from delta lights, which no ray can hit, is not in it: add it exactly).

#include "render/trace/camera.h"

#include <vector>

namespace lucerna {

// A point where irradiance is measured, and the unit normal of the side it is measured on.
struct IrradianceSensor {
    V3f position;
    V3f normal;
};

class Sensor {
public:
    Sensor() = default;
    Sensor(const PinholeCamera& pinhole) : pinhole_(pinhole) {}  // NOLINT: a pinhole is a sensor
    // Irradiance sensors, pixelsPerSide^2 pixels each; normals are normalised here.
    Sensor(std::vector<IrradianceSensor> points, int pixelsPerSide);

    bool isPinhole() const { return points_.empty(); }
    int width() const { return isPinhole() ? pinhole_.width() : int(points_.size()) * side_; }
    int height() const { return isPinhole() ? pinhole_.height() : side_; }
    int pixelsPerSide() const { return side_; }
    int pointCount() const { return isPinhole() ? 1 : int(points_.size()); }
    // The sensor point whose block holds raster x (0 for the pinhole).
    int pointAt(float x) const;
    // Where point i sits, and the direction it faces (the pinhole's viewing direction).
    V3f position(int point) const { return isPinhole() ? pinhole_.position() : points_[size_t(point)].position; }
    V3f normal(int point) const { return isPinhole() ? pinhole_.forward() : points_[size_t(point)].normal; }

    // Unit-direction ray through raster point (x, y), from the point that owns it.
    Ray ray(float x, float y) const;
    // Raster point that a world direction leaving `point` maps to; false when no raster point
    // of that point's block (or the pinhole's image) sees it.
    bool rasterPoint(int point, const V3f& dir, float& x, float& y) const;
    // Solid-angle density of the direction of ray(x, y) for x, y uniform over `point`'s share of
    // the raster: 1 / (A cos^3) for the pinhole (A its image plane's area at distance 1),
    // cos / pi for an irradiance sensor; 0 outside. It is also the importance times cosine that a
    // light-tracing splat carries (bdpt_vertex.h).
    float pdfDirection(int point, const V3f& dir) const;

private:
    PinholeCamera pinhole_;
    std::vector<IrradianceSensor> points_;
    std::vector<Frame> frames_;  // one per point, +z the normal
    int side_ = 1;
};

}  // namespace lucerna
