#include "render/photometry/sensor_render.h"

#include "render/engine/backend_table.h"

#include <numbers>
#include <stdexcept>

namespace lucerna {

PreparedSensors prepareSensors(const RenderScene& scene, const std::vector<IrradianceSensor>& sensors,
                               bool throughPanes) {
    const IrradianceEstimator estimator(scene);
    PreparedSensors out;
    out.lifted.reserve(sensors.size());
    out.deltaLux.reserve(sensors.size());
    for (const IrradianceSensor& s : sensors) {
        out.deltaLux.push_back(kLumensPerWatt * double(luminance(estimator.deltaLightsIrradiance(s, throughPanes))));
        out.lifted.push_back(estimator.lifted(s));
    }
    return out;
}

SensorRender::SensorRender(const RenderScene& scene, const std::string& backend,
                           const std::vector<IrradianceSensor>& sensors, int pixelsPerSide, uint64_t seed,
                           const std::map<std::string, std::string>& options) {
    const BackendInfo* info = findBackend(backend);
    if (!info) throw std::runtime_error("no backend " + backend);
    PreparedSensors prepared = prepareSensors(scene, sensors, /*throughPanes=*/true);
    deltaLux_ = std::move(prepared.deltaLux);
    sensor_ = std::make_shared<const Sensor>(std::move(prepared.lifted), pixelsPerSide);
    RenderSettings rs;
    rs.seed = seed;
    rs.sensor = sensor_;
    rs.options = options;
    backend_ = info->make(scene.snapshot(), rs);
}

std::vector<double> SensorRender::lux(bool withDeltaLights) const {
    const Image image = backend_->film().image();
    const int side = sensor_->pixelsPerSide();
    std::vector<double> lux = withDeltaLights ? deltaLux_ : std::vector<double>(deltaLux_.size(), 0.0);
    for (size_t i = 0; i < lux.size(); ++i) {
        double sum = 0;
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) sum += double(luminance(image.at(int(i) * side + x, y)));
        lux[i] += kLumensPerWatt * std::numbers::pi * sum / double(side * side);
    }
    return lux;
}

}  // namespace lucerna
