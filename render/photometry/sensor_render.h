#pragma once
// A backend rendering irradiance sensors (sensor.h) instead of the camera: the bdpt, mir, mlt
// and cmlt machinery for calculation grids and the illuminance layer. The delta lights, which
// no ray of a backend can hit, are summed exactly at each sensor and added to what the backend
// measures; the backend sees the sensors from just above their surfaces.

#include "core/task_system.h"
#include "render/backend/backend.h"
#include "render/photometry/irradiance_estimator.h"

#include <memory>
#include <string>
#include <vector>

namespace lucerna {

// What a backend or the preview needs of sensors: each moved off the surface it may lie on
// (IrradianceEstimator::lifted), and the illuminance (lux) the delta lights give it exactly
// (through glass panes with throughPanes: the backends, which carry the rest of that light through
// the glass on their light paths).
struct PreparedSensors {
    std::vector<IrradianceSensor> lifted;
    std::vector<double> deltaLux;
};
PreparedSensors prepareSensors(const RenderScene& scene, const std::vector<IrradianceSensor>& sensors,
                               bool throughPanes = false);

class SensorRender {
public:
    // The backend named `backend` (one that measures sensors; not the preview) over `sensors`,
    // with seed `seed` and the backend's options. Throws std::runtime_error for an unknown
    // backend, std::invalid_argument for a bad option.
    SensorRender(const RenderScene& scene, const std::string& backend, const std::vector<IrradianceSensor>& sensors,
                 int pixelsPerSide, uint64_t seed, const std::map<std::string, std::string>& options = {});

    void prepare(TaskContext& ctx) { backend_->prepare(ctx); }
    void renderPass(TaskContext& ctx, int pass) { backend_->renderPass(ctx, pass); }
    int pixelsPerSensor() const { return sensor_->pixelsPerSide() * sensor_->pixelsPerSide(); }
    // Illuminance (lux) at each sensor so far: 683 Y of pi times its block's mean pixel (E / pi,
    // sensor.h), plus the delta lights' exact part unless left out.
    std::vector<double> lux(bool withDeltaLights = true) const;

private:
    std::shared_ptr<const Sensor> sensor_;
    std::vector<double> deltaLux_;
    std::unique_ptr<Backend> backend_;
};

}  // namespace lucerna
