#include "render/preview/hemicube_irradiance.h"

#include "render/trace/camera.h"

#include <cmath>

namespace lucerna {

namespace {
Camera faceCamera(const V3f& position, const V3f& forward, const V3f& up, int size) {
    Camera c;
    c.position = V3d(position.x, position.y, position.z);
    c.target = c.position + V3d(forward.x, forward.y, forward.z);
    c.up = V3d(up.x, up.y, up.z);
    c.fovYDeg = 90;
    c.width = c.height = size;
    return c;
}
}  // namespace

PreviewIrradiance::PreviewIrradiance(SceneSnapshot scene, const PreviewSettings& settings, int faceSize)
    : size_(std::max(2, faceSize)) {
    preview_.setSettings(settings);
    preview_.setSunDiscShown(false);  // irradiance() adds its light
    preview_.setScene(std::move(scene), size_, size_);
    // The faces in the frame of a sensor with normal +z: the top, then the four sides (their
    // upper halves face +z).
    const V3f z(0, 0, 1);
    faces_ = {Face{z, V3f(0, 1, 0), {}}, Face{V3f(1, 0, 0), z, {}}, Face{V3f(-1, 0, 0), z, {}},
              Face{V3f(0, 1, 0), z, {}}, Face{V3f(0, -1, 0), z, {}}};
    // Weights cos theta d omega from the pixel centres, d omega = (2 / size)^2 cos^3 of the angle
    // to the face's axis; scaled so that they add up to pi, the integral of cos theta over the
    // hemisphere (a uniform sky then gives E = pi L exactly; the discretisation is below 0.1%
    // at 32 pixels).
    double total = 0;
    for (Face& f : faces_) {
        const PinholeCamera camera(faceCamera(V3f(0, 0, 0), f.forward, f.up, size_), size_, size_);
        f.weight.assign(size_t(size_) * size_t(size_), 0.0f);
        const float pixelArea = (2.0f / float(size_)) * (2.0f / float(size_));
        for (int y = 0; y < size_; ++y)
            for (int x = 0; x < size_; ++x) {
                const V3f d = camera.direction(float(x) + 0.5f, float(y) + 0.5f);
                const float c = d.dot(f.forward);
                const float w = std::max(0.0f, d.z) * pixelArea * c * c * c;
                f.weight[size_t(y) * size_t(size_) + size_t(x)] = w;
                total += w;
            }
    }
    const float scale = float(kPi / total);
    for (Face& f : faces_)
        for (float& w : f.weight) w *= scale;
}

Rgb PreviewIrradiance::irradiance(const IrradianceSensor& sensor, float jitterX, float jitterY) {
    const Frame frame(sensor.normal.normalized());
    Rgb E(0, 0, 0);
    for (const Face& f : faces_) {
        preview_.setCamera(faceCamera(sensor.position, frame.toWorld(f.forward), frame.toWorld(f.up), size_));
        const Image image = preview_.render(jitterX, jitterY);
        for (size_t i = 0; i < f.weight.size() && i < image.pixels.size(); ++i)
            if (f.weight[i] > 0.0f && isFinite(image.pixels[i])) E += image.pixels[i] * f.weight[i];
    }
    // The sun's disc, far smaller than a face's pixel, directly (the faces do not show it).
    return E + preview_.sunDiscIrradiance(sensor.position, sensor.normal.normalized());
}

}  // namespace lucerna
