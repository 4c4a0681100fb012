#include "render/annual/annual_calculation.h"

#include "render/annual/annual_checkpoint.h"

#include "core/daylight/perez_sky.h"
#include "core/daylight/solar_position.h"
#include "render/photometry/grid_diagnosis.h"
#include "render/photometry/irradiance_estimator.h"
#include "render/trace/warp.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <cmath>
#include <numbers>

namespace lucerna {

namespace {

constexpr double kPiD = std::numbers::pi;

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Student's t at 97.5% for the batches' degrees of freedom (2 to 32 batches).
double studentT975(int dof) {
    static constexpr double kT[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                    2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086};
    return dof >= 1 && dof <= 20 ? kT[dof - 1] : 2.04;
}

// The instant a row stands for: hour - 0.5, local standard time (SPEC.md section 6).
LocalTime instantOf(const WeatherFile& weather, const WeatherHour& h) {
    return LocalTime{weather.year(), h.month, h.day, h.hour - 1, 30, 0};
}

V3d sunTowardAt(const WeatherFile& weather, const V3d& north, const WeatherHour& h) {
    SolarPositionInput in;
    in.time = instantOf(weather, h);
    in.utcOffsetHours = weather.timeZoneHours;
    in.latitudeDeg = weather.latitudeDeg;
    in.longitudeDeg = weather.longitudeDeg;
    return directionTowardSun(solarPosition(in), north);
}

// The scene the coefficients are traced in: geometry and materials only.
SceneSnapshot darkScene(const Scene& scene) {
    Scene s = scene;
    s.lights.clear();
    s.sky.reset();
    for (Material& m : s.materials)
        if (m.type == MaterialType::Emitter) m.radiance = Rgbd(0, 0, 0);
    return std::make_shared<const Scene>(std::move(s));
}

// One hour's sky as the coefficients see it: the mean luminance of each patch (midpoint rule
// on its cells), scaled so that the patches give Evd on an open plane, and the ground.
struct HourSky {
    std::vector<float> patch;   // cd/m^2 per fine patch, then the ground
    std::vector<float> coarse;  // per Tregenza patch, then the ground
};

struct HourInputs {
    PerezInputs perez;
    V3d towardSun;
    bool daylight = false;
};

class SkyAverager {
public:
    SkyAverager(const SkyPatches& fine, const SkyPatches& coarse) : fine_(fine), coarse_(coarse) {
        coarseOf_.resize(size_t(fine.count()));
        coarseAngle_.assign(size_t(coarse.count()), 0.0);
        for (int i = 0; i < fine.count(); ++i) {
            coarseOf_[size_t(i)] = coarse.patchOf(fine.centre(i));
            coarseAngle_[size_t(coarseOf_[size_t(i)])] += fine.solidAngle(i);
        }
    }

    HourSky average(const PerezSky& sky, double groundLuminance) const {
        HourSky h;
        h.patch.assign(size_t(fine_.count()) + 1, 0.0f);
        h.coarse.assign(size_t(coarse_.count()) + 1, 0.0f);
        std::vector<double> lv(size_t(fine_.count()));
        double horizontal = 0;
        for (int i = 0; i < fine_.count(); ++i) {
            double sum = 0;
            const auto samples = fine_.samples(i);
            for (const V3d& w : samples) sum += sky.relativeLuminance(w);
            lv[size_t(i)] = sum / double(samples.size());
            horizontal += lv[size_t(i)] * fine_.projectedSolidAngle(i);
        }
        const double evd = sky.diffuseIlluminance();
        const double scale = evd > 0 && horizontal > 0 ? evd / horizontal : 0;
        std::vector<double> coarseSum(size_t(coarse_.count()), 0.0);
        for (int i = 0; i < fine_.count(); ++i) {
            const double l = lv[size_t(i)] * scale;
            h.patch[size_t(i)] = float(l);
            coarseSum[size_t(coarseOf_[size_t(i)])] += l * fine_.solidAngle(i);
        }
        for (int k = 0; k < coarse_.count(); ++k) h.coarse[size_t(k)] = float(coarseSum[size_t(k)] / coarseAngle_[size_t(k)]);
        h.patch.back() = h.coarse.back() = float(groundLuminance);
        return h;
    }

private:
    const SkyPatches& fine_;
    const SkyPatches& coarse_;
    std::vector<int> coarseOf_;
    std::vector<double> coarseAngle_;
};

// A point's sky coefficients without their zeros (most of the sky is unseen from a room).
struct SparseCoefficients {
    std::vector<int> bin;
    std::vector<float> value;
    explicit SparseCoefficients(const std::vector<float>& dense) {
        for (size_t i = 0; i < dense.size(); ++i)
            if (dense[i] != 0.0f) bin.push_back(int(i)), value.push_back(dense[i]);
    }
    float dot(const std::vector<float>& luminance) const {
        float sum = 0;
        for (size_t i = 0; i < bin.size(); ++i) sum += value[i] * luminance[size_t(bin[i])];
        return sum;
    }
};

// Disc samples: unit offsets over the sun's disc (a Fibonacci spiral, area-uniform).
std::vector<V2f> discPattern(int n) {
    std::vector<V2f> out;
    const double golden = kPiD * (3 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        const double r = std::sqrt((i + 0.5) / n), a = i * golden;
        out.emplace_back(float(r * std::cos(a)), float(r * std::sin(a)));
    }
    return out;
}

}  // namespace

Scene sceneOfHour(const Scene& scene, const WeatherFile& weather, size_t row, std::optional<double> dewPointC) {
    const WeatherHour& h = weather.hours.at(row);
    Scene s = scene;
    Site site;
    site.latitudeDeg = weather.latitudeDeg;
    site.longitudeDeg = weather.longitudeDeg;
    site.utcOffsetHours = weather.timeZoneHours;
    if (scene.site) site.north = scene.site->north, site.northGiven = scene.site->northGiven;
    s.site = site;
    SunSpec sunKeys;
    for (Light& l : s.lights)
        if (l.type == LightType::Sun && l.sun) sunKeys.angularDiameterDeg = l.sun->angularDiameterDeg,
                                               sunKeys.angularDiameterGiven = l.sun->angularDiameterGiven;
    std::erase_if(s.lights, [](const Light& l) { return l.type == LightType::Sun; });
    for (Light& l : s.lights) l.on = false;  // electric light off
    for (Material& m : s.materials)
        if (m.type == MaterialType::Emitter) m.radiance = Rgbd(0, 0, 0);
    Light sun;
    sun.name = "sun";
    sun.type = LightType::Sun;
    sunKeys.illuminanceGiven = false;
    sunKeys.time = formatLocalTime(instantOf(weather, h));
    sun.sun = sunKeys;
    s.lights.push_back(sun);
    Sky sky;
    sky.model = SkyModelType::Perez;
    sky.directNormalIrradiance = h.directNormalIrradiance;
    sky.diffuseHorizontalIrradiance = h.diffuseHorizontalIrradiance;
    sky.dewPointC = dewPointC.value_or(h.dewPointC);
    if (scene.sky) sky.groundReflectance = scene.sky->groundReflectance, sky.groundReflectanceGiven = true;
    s.sky = sky;
    return s;
}

AnnualResult computeAnnual(const Scene& scene, const std::vector<V3d>& points, const V3d& normal,
                           const WeatherFile& weather, const AnnualSettings& settings, TaskContext& ctx) {
    const auto t0 = std::chrono::steady_clock::now();
    AnnualResult r;
    const size_t n = points.size(), rows = weather.hours.size();
    r.points = n;
    const RenderScene rs(darkScene(scene), 16, 16);
    r.insideGeometry = pointsInsideGeometry(rs, points, normal);

    const SkyPatches fine(settings.coefficients.skySubdivision), coarse(1);
    const V3d north = scene.site ? scene.site->north.normalized() : Site().north;
    const SunPathGrid sunGrid(weather.latitudeDeg, north, settings.sunDeclinationStepDeg, settings.sunHourAngleStepDeg);
    const DaylightCoefficientTracer tracer(rs, fine, coarse, sunGrid, settings.coefficients);
    const IrradianceEstimator estimator(rs);
    const V3f up = V3f(float(normal.x), float(normal.y), float(normal.z)).normalized();

    // The points that measure the discretisation: spread over those outside geometry.
    std::vector<size_t> checkPoints;
    {
        std::vector<size_t> open;
        for (size_t p = 0; p < n; ++p)
            if (!r.insideGeometry[p]) open.push_back(p);
        const size_t k = std::min(open.size(), size_t(std::max(settings.checkPoints, 0)));
        for (size_t i = 0; i < k; ++i) checkPoints.push_back(open[i * open.size() / k]);
    }
    std::vector<int> recordSlot(n, -1);
    for (size_t i = 0; i < checkPoints.size(); ++i) recordSlot[checkPoints[i]] = int(i);

    // 1. The coefficients, once: those of an interrupted run of the same year read back, except
    // the discretisation's points (their records are not kept), the rest traced and kept.
    std::unique_ptr<AnnualCheckpoint> checkpoint;
    std::map<size_t, PointCoefficients> restored;
    if (!settings.checkpointDirectory.empty()) {
        const DaylightCoefficientSettings& c = settings.coefficients;
        const std::string settingsText =
            std::to_string(c.skySubdivision) + "," + std::to_string(c.paths) + "," + std::to_string(c.sunPaths) + "," +
            std::to_string(c.batches) + "," + std::to_string(c.seed) + "," + std::to_string(settings.sunDeclinationStepDeg) +
            "," + std::to_string(settings.sunHourAngleStepDeg) + "," + std::to_string(north.x) + "," + std::to_string(north.z);
        const uint64_t key = annualCheckpointKey(scene, points, normal, weather.latitudeDeg, settingsText);
        char name[64];
        std::snprintf(name, sizeof name, "/annual-%016llx.checkpoint", static_cast<unsigned long long>(key));
        r.checkpointPath = settings.checkpointDirectory + name;
        checkpoint = std::make_unique<AnnualCheckpoint>(r.checkpointPath, key);
        restored = checkpoint->open(settings.resume);
    }
    std::vector<PointCoefficients> coefficients(n);
    std::vector<PathRecords> records(checkPoints.size());
    std::vector<V3f> sensors(n);
    std::atomic<int> traced{0};
    std::atomic<size_t> resumed{0};
    ctx.parallelFor(0, int(n), [&](int p) {
        const IrradianceSensor s = estimator.lifted({V3f(points[size_t(p)]), up});
        sensors[size_t(p)] = s.position;
        const int slot = recordSlot[size_t(p)];
        if (r.insideGeometry[size_t(p)]) {
        } else if (const auto kept = restored.find(size_t(p)); kept != restored.end() && slot < 0) {
            coefficients[size_t(p)] = std::move(kept->second);
            ++resumed;
        } else {
            coefficients[size_t(p)] = tracer.trace(s.position, s.normal, uint64_t(p), slot >= 0 ? &records[size_t(slot)] : nullptr);
            if (checkpoint) checkpoint->append(size_t(p), coefficients[size_t(p)]);
        }
        ctx.setProgress(0.8 * double(++traced) / double(n));
    });
    r.tracingSeconds = secondsSince(t0);
    r.resumedPoints = resumed;
    if (ctx.isCancelled()) {
        r.cancelled = true;
        return r;
    }

    // 2. Each row's sun and sky inputs.
    const double groundReflectance = scene.sky ? scene.sky->groundReflectance : Sky().groundReflectance;
    std::vector<HourInputs> inputs(rows);
    r.hours.resize(rows);
    for (size_t row = 0; row < rows; ++row) {
        const WeatherHour& h = weather.hours[row];
        HourInputs& in = inputs[row];
        in.towardSun = sunTowardAt(weather, north, h);
        in.perez = PerezInputs{h.directNormalIrradiance, h.diffuseHorizontalIrradiance, settings.dewPointC.value_or(h.dewPointC),
                               dayOfYear(weather.year(), h.month, h.day), in.towardSun};
        in.daylight = h.directNormalIrradiance > 0 || h.diffuseHorizontalIrradiance > 0;
        r.daylightHours += in.daylight;
        const double evd = in.daylight ? PerezSky(in.perez, 0).diffuseIlluminance() : 0;
        r.hours[row] = AnnualHour{h.month, h.day, h.hour, evd};
    }

    // 3. Every hour: the sky by patches, the sun's indirect light by the nodes, its direct light
    // traced through the disc.
    std::vector<SparseCoefficients> sparse;
    sparse.reserve(n);
    for (const PointCoefficients& c : coefficients) sparse.emplace_back(c.sky);
    const SkyAverager averager(fine, coarse);
    const std::vector<V2f> disc = discPattern(settings.sunDiscSamples);
    const int batches = settings.coefficients.batches, coarseBins = coarse.count() + 1, nodes = sunGrid.nodeCount();
    const double t = studentT975(batches - 1);
    r.lux.assign(rows * n, 0.0f);
    r.directSunLux.assign(rows * n, 0.0f);
    r.errorLux.assign(rows * n, 0.0f);
    std::vector<float> statisticalRelative(rows * n, -1.0f);
    std::vector<HourSky> checkSkies(rows);  // kept only for the rows the check samples
    std::vector<uint8_t> checkRow(rows, 0);
    {
        std::vector<size_t> daylit;
        for (size_t row = 0; row < rows; ++row)
            if (inputs[row].daylight) daylit.push_back(row);
        const size_t k = std::min(daylit.size(), size_t(std::max(settings.checkHours, 0)));
        for (size_t i = 0; i < k; ++i) checkRow[daylit[(2 * i + 1) * daylit.size() / (2 * k)]] = 1;
    }
    const auto t1 = std::chrono::steady_clock::now();
    std::atomic<int> done{0};
    constexpr int kRowsPerTask = 24;
    ctx.parallelFor(0, int((rows + kRowsPerTask - 1) / kRowsPerTask), [&](int task) {
        std::vector<double> batch(static_cast<size_t>(batches));
        for (size_t row = size_t(task) * kRowsPerTask; row < std::min(rows, size_t(task + 1) * kRowsPerTask); ++row) {
            const HourInputs& in = inputs[row];
            if (!in.daylight) continue;
            const PerezSky sky(in.perez, 0);
            const bool sunUp = in.towardSun.y > 0 && sky.directNormalIlluminance() > 0;
            const double evn = sunUp ? sky.directNormalIlluminance() : 0;
            const double ground = groundReflectance * (sky.diffuseIlluminance() + evn * std::max(in.towardSun.y, 0.0)) / kPiD;
            HourSky hs = averager.average(sky, ground);
            const SunPathGrid::Stencil stencil = sunGrid.stencil(in.towardSun);
            const V3f toward(in.towardSun);
            const Frame sunFrame(toward);
            const float discRadius = float(std::tan(0.5 * 0.53 * kPiD / 180));  // section 5's default disc
            for (size_t p = 0; p < n; ++p) {
                if (r.insideGeometry[p]) continue;
                const PointCoefficients& c = coefficients[p];
                const size_t at = row * n + p;
                double indirect = 0, direct = 0;
                if (sunUp) {
                    for (int k = 0; k < 4; ++k) indirect += stencil.weight[k] * c.sunIndirect[size_t(stencil.node[k])];
                    indirect *= evn;
                    double sum = 0;
                    for (const V2f& d : disc) {
                        const V3f w = (toward + sunFrame.s * (d.x * discRadius) + sunFrame.t * (d.y * discRadius)).normalized();
                        const float cosine = w.dot(up);
                        if (cosine > 0) sum += luminance(rs.transmittance(Ray{sensors[p], w})) * cosine;
                    }
                    direct = evn * sum / double(disc.size());
                }
                const double total = sparse[p].dot(hs.patch) + indirect + direct;
                r.lux[at] = float(total);
                r.directSunLux[at] = float(direct);
                // Batch means: each batch's coarse sky and sun nodes (the direct sun is exact).
                double mean = 0;
                for (int b = 0; b < batches; ++b) {
                    const float* cs = &c.coarseSky[size_t(b) * coarseBins];
                    double x = 0;
                    for (int k = 0; k < coarseBins; ++k) x += cs[k] * hs.coarse[size_t(k)];
                    if (sunUp)
                        for (int k = 0; k < 4; ++k)
                            x += evn * stencil.weight[k] * c.sunIndirectBatches[size_t(b) * nodes + stencil.node[k]];
                    batch[size_t(b)] = x;
                    mean += x / batches;
                }
                double var = 0;
                for (double x : batch) var += (x - mean) * (x - mean);
                const double standardError = std::sqrt(var / (double(batches) * (batches - 1)));
                r.errorLux[at] = float(t * standardError);
                if (total > 1) statisticalRelative[at] = float(t * standardError / total);
            }
            if (checkRow[row]) checkSkies[row] = std::move(hs);
            ctx.setProgress(0.8 + 0.2 * double(++done) / double(rows));
        }
    });
    if (ctx.isCancelled()) {
        r.cancelled = true;
        return r;
    }

    // 4. The discretisation, on the sample: binned and interpolated against direction by
    // direction (the scene's own Perez sky, 256-ring integral) and the sun at its own position.
    // Differences relative to the point's value: the straight view, the reflected sky, the
    // sun's reflections, and their sum.
    double sumSquares[4] = {0, 0, 0, 0};
    size_t count = 0;
    for (size_t row = 0; row < rows; ++row) {
        if (!checkRow[row]) continue;
        const HourInputs& in = inputs[row];
        const PerezSky exactSky(in.perez);
        const HourSky& hs = checkSkies[row];
        const bool sunUp = in.towardSun.y > 0 && exactSky.directNormalIlluminance() > 0;
        const double evn = sunUp ? exactSky.directNormalIlluminance() : 0;
        const SunPathGrid::Stencil stencil = sunGrid.stencil(in.towardSun);
        const auto exactLuminance = [&](const V3f& w) { return w.y > 0 ? exactSky.luminance(V3d(w)) : double(hs.patch.back()); };
        for (size_t i = 0; i < checkPoints.size(); ++i) {
            const size_t p = checkPoints[i];
            const double total = r.lux[row * n + p];
            if (!(total > 1)) continue;
            const PathRecords& rec = records[i];
            double difference[3] = {0, 0, 0};
            for (size_t bin = 0; bin < rec.direct.size(); ++bin) difference[0] += rec.direct[bin] * hs.patch[bin];
            for (const PathRecords::Escape& e : rec.directCells) difference[0] -= e.weight * exactLuminance(e.direction);
            for (const PathRecords::Escape& e : rec.escapes) {
                const V3d w(e.direction);
                difference[1] += e.weight * (hs.patch[size_t(w.y > 0 ? fine.patchOf(w) : fine.count())] - exactLuminance(e.direction));
            }
            if (sunUp) {
                for (int k = 0; k < 4; ++k)
                    difference[2] += evn * stencil.weight[k] * coefficients[p].sunIndirect[size_t(stencil.node[k])];
                difference[2] -= evn * tracer.sunIndirectAt(rec, V3f(in.towardSun));
            }
            for (int k = 0; k < 3; ++k) sumSquares[k] += (difference[k] / total) * (difference[k] / total);
            const double sum = (difference[0] + difference[1] + difference[2]) / total;
            sumSquares[3] += sum * sum;
            ++count;
        }
    }
    for (int k = 0; k < 3; ++k) r.discretisationParts[k] = count ? 2 * std::sqrt(sumSquares[k] / double(count)) : 0;
    r.discretisationRelative = count ? 2 * std::sqrt(sumSquares[3] / double(count)) : 0;
    for (size_t at = 0; at < r.lux.size(); ++at) {
        const double d = r.discretisationRelative * r.lux[at];
        r.errorLux[at] = float(std::sqrt(double(r.errorLux[at]) * r.errorLux[at] + d * d));
    }
    std::erase_if(statisticalRelative, [](float x) { return x < 0; });
    if (!statisticalRelative.empty()) {
        auto mid = statisticalRelative.begin() + ptrdiff_t(statisticalRelative.size() / 2);
        std::nth_element(statisticalRelative.begin(), mid, statisticalRelative.end());
        r.statisticalRelative = *mid;
    }
    r.hoursSeconds = secondsSince(t1);
    if (checkpoint) checkpoint->remove();
    ctx.setProgress(1.0);
    return r;
}

}  // namespace lucerna
