#pragma once
// The pinhole camera of SPEC.md section 1: raster (x, y) in [0, W] x [0, H], y down, looks along
// f + (2x/W - 1)(W/H) t r + (1 - 2y/H) t u with t = tan(fov_y / 2).

#include "core/scene/scene.h"
#include "render/trace/embree_scene.h"

namespace lucerna {

class PinholeCamera {
public:
    PinholeCamera() = default;
    PinholeCamera(const Camera& c, int width, int height) : width_(width), height_(height) {
        const V3d f = (c.target - c.position).normalized();
        const V3d r = f.cross(c.up).normalized();
        const V3d u = r.cross(f);
        const double t = std::tan(radians(c.fovYDeg) * 0.5);
        origin_ = toFloat(c.position);
        forward_ = toFloat(f);
        right_ = toFloat(r * (t * double(width) / double(height)));
        up_ = toFloat(u * t);
    }

    int width() const { return width_; }
    int height() const { return height_; }
    const V3f& position() const { return origin_; }
    const V3f& forward() const { return forward_; }

    // Unit direction through raster point (x, y).
    V3f direction(float x, float y) const {
        const float sx = 2.0f * x / float(width_) - 1.0f;
        const float sy = 1.0f - 2.0f * y / float(height_);
        return (forward_ + right_ * sx + up_ * sy).normalized();
    }
    Ray ray(float x, float y) const { return Ray{origin_, direction(x, y)}; }

    // Raster point that a world direction projects to; false when it is behind the camera or
    // outside the image. For light tracing and splatting.
    bool rasterPoint(const V3f& dir, float& x, float& y) const {
        const float cz = dir.dot(forward_);
        if (cz <= 0.0f) return false;
        const float sx = dir.dot(right_) / (right_.length2() * cz);
        const float sy = dir.dot(up_) / (up_.length2() * cz);
        x = (sx + 1.0f) * 0.5f * float(width_);
        y = (1.0f - sy) * 0.5f * float(height_);
        return x >= 0 && x < float(width_) && y >= 0 && y < float(height_);
    }

    // Solid-angle-to-pixel-area factor: the importance W_e of a pinhole camera for a unit-area
    // image plane at distance 1 is 1 / (A cos^4), A the plane's area in these units.
    float imagePlaneArea() const { return 4.0f * right_.length() * up_.length(); }

private:
    int width_ = 1, height_ = 1;
    V3f origin_, forward_, right_, up_;
};

}  // namespace lucerna
