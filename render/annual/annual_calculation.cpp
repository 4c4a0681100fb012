#include "render/annual/annual_calculation.h"

#include "render/annual/annual_checkpoint.h"

#include "core/daylight/perez_sky.h"
#include "core/daylight/solar_position.h"
#include "render/photometry/grid_diagnosis.h"
#include "render/photometry/irradiance_estimator.h"
#include "render/trace/warp.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <cmath>
#include <numbers>
#include <span>

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
    std::optional<PerezSky> sky;  // its shape (no scale): the averager scales it by Evd
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

HourDaylight daylightOfHour(const Scene& scene, const WeatherFile& weather, size_t row, std::optional<double> dewPointC) {
    const WeatherHour& h = weather.hours.at(row);
    HourDaylight d;
    d.site.latitudeDeg = weather.latitudeDeg;
    d.site.longitudeDeg = weather.longitudeDeg;
    d.site.utcOffsetHours = weather.timeZoneHours;
    if (scene.site) d.site.north = scene.site->north, d.site.northGiven = scene.site->northGiven;
    SunSpec sunKeys;
    for (const Light& l : scene.lights)
        if (l.type == LightType::Sun && l.sun)
            sunKeys.angularDiameterDeg = l.sun->angularDiameterDeg, sunKeys.angularDiameterGiven = l.sun->angularDiameterGiven;
    sunKeys.illuminanceGiven = false;
    sunKeys.time = formatLocalTime(instantOf(weather, h));
    d.sun.name = "sun";
    d.sun.type = LightType::Sun;
    d.sun.sun = sunKeys;
    d.sky.model = SkyModelType::Perez;
    d.sky.directNormalIrradiance = h.directNormalIrradiance;
    d.sky.diffuseHorizontalIrradiance = h.diffuseHorizontalIrradiance;
    d.sky.dewPointC = dewPointC.value_or(h.dewPointC);
    if (scene.sky) d.sky.groundReflectance = scene.sky->groundReflectance, d.sky.groundReflectanceGiven = true;
    return d;
}

std::optional<size_t> weatherRow(const WeatherFile& weather, int month, int day, int hour) {
    for (size_t row = 0; row < weather.hours.size(); ++row) {
        const WeatherHour& h = weather.hours[row];
        if (h.month == month && h.day == day && h.hour == hour) return row;
    }
    return std::nullopt;
}

Scene sceneOfHour(const Scene& scene, const WeatherFile& weather, size_t row, std::optional<double> dewPointC) {
    const HourDaylight d = daylightOfHour(scene, weather, row, dewPointC);
    Scene s = scene;
    s.site = d.site;
    std::erase_if(s.lights, [](const Light& l) { return l.type == LightType::Sun; });
    for (Light& l : s.lights) l.on = false;  // electric light off
    for (Material& m : s.materials)
        if (m.type == MaterialType::Emitter) m.radiance = Rgbd(0, 0, 0);
    s.lights.push_back(d.sun);
    s.sky = d.sky;
    return s;
}

namespace {

// The steps of computeAnnual, sharing what they build.
class YearCalculation {
public:
    YearCalculation(const Scene& scene, const std::vector<V3d>& points, const V3d& normal, const WeatherFile& weather,
                    const AnnualSettings& settings, TaskContext& ctx)
        : scene_(scene), points_(points), normal_(normal), weather_(weather), settings_(settings), ctx_(ctx),
          n_(points.size()), rows_(weather.hours.size()), rs_(darkScene(scene), 16, 16),
          fine_(settings.coefficients.skySubdivision), coarse_(1),
          north_(scene.site ? scene.site->north.normalized() : Site().north),
          sunGrid_(weather.latitudeDeg, north_, settings.sunDeclinationStepDeg, settings.sunHourAngleStepDeg),
          tracer_(rs_, fine_, coarse_, sunGrid_, settings.coefficients),
          up_(V3f(float(normal.x), float(normal.y), float(normal.z)).normalized()) {
        for (const Light& l : scene.lights)
            if (l.type == LightType::Sun && l.sun) sunHalfAngleRad_ = 0.5 * l.sun->angularDiameterDeg * kPiD / 180;
    }

    AnnualResult run() {
        const auto t0 = std::chrono::steady_clock::now();
        r_.points = n_;
        r_.insideGeometry = pointsInsideGeometry(rs_, points_, normal_);
        chooseCheckPoints();
        traceCoefficients();
        r_.tracingSeconds = secondsSince(t0);
        if (anyCancelled()) return cancelled();
        if (!gatherOnRoot()) {
            r_.onRoot = false;
            return std::move(r_);
        }
        const auto t1 = std::chrono::steady_clock::now();
        readHours();
        evaluateHours();
        if (ctx_.isCancelled()) return cancelled();
        measureDiscretisation();
        r_.hoursSeconds = secondsSince(t1);
        if (checkpoint_) checkpoint_->remove();
        ctx_.setProgress(1.0);
        return std::move(r_);
    }

private:
    AnnualResult cancelled() {
        r_.cancelled = true;
        return std::move(r_);
    }

    // Whether any process was cancelled (every process asks, so that all leave or none).
    bool anyCancelled() {
        double mine = ctx_.isCancelled() ? 1 : 0;
        if (sizeOf(settings_.processes) > 1)
            for (double theirs : settings_.processes->allGather(std::span(&mine, 1))) mine = std::max(mine, theirs);
        return mine > 0;
    }

    // Whether this process traces point p: the discretisation's points are rank 0's (their
    // records stay there), the others dealt in turn.
    bool mine(size_t p) const {
        const int size = sizeOf(settings_.processes), rank = rankOf(settings_.processes);
        return recordSlot_[p] >= 0 ? rank == 0 : int(p % size_t(size)) == rank;
    }

    // A shared year: every point's coefficients to rank 0 (zeros from the processes that did not
    // trace it, so the sum is the tracer's); false on the other ranks.
    bool gatherOnRoot() {
        ProcessGroup* group = settings_.processes;
        if (sizeOf(group) <= 1) return true;
        const int batches = settings_.coefficients.batches, nodes = sunGrid_.nodeCount();
        const size_t sizes[4] = {size_t(fine_.count() + 1), size_t(batches) * size_t(coarse_.count() + 1), size_t(nodes),
                                 size_t(batches) * size_t(nodes)};
        const size_t per = sizes[0] + sizes[1] + sizes[2] + sizes[3];
        std::vector<double> flat(n_ * per, 0.0);
        const auto parts = [&](PointCoefficients& c) {
            return std::array<std::vector<float>*, 4>{&c.sky, &c.coarseSky, &c.sunIndirect, &c.sunIndirectBatches};
        };
        for (size_t p = 0; p < n_; ++p) {
            if (!mine(p) || r_.insideGeometry[p]) continue;
            size_t at = p * per;
            for (std::vector<float>* v : parts(coefficients_[p])) {
                std::copy(v->begin(), v->end(), flat.begin() + ptrdiff_t(at));
                at += v->size();
            }
        }
        group->sumToRoot(flat);
        if (group->rank() != 0) return false;
        for (size_t p = 0; p < n_; ++p) {
            if (mine(p) || r_.insideGeometry[p]) continue;
            size_t at = p * per;
            const auto v = parts(coefficients_[p]);
            for (int k = 0; k < 4; ++k) {
                v[size_t(k)]->assign(flat.begin() + ptrdiff_t(at), flat.begin() + ptrdiff_t(at + sizes[k]));
                at += sizes[k];
            }
        }
        return true;
    }

    // The points that measure the discretisation: spread over those outside geometry.
    void chooseCheckPoints() {
        std::vector<size_t> open;
        for (size_t p = 0; p < n_; ++p)
            if (!r_.insideGeometry[p]) open.push_back(p);
        const size_t k = std::min(open.size(), size_t(std::max(settings_.checkPoints, 0)));
        for (size_t i = 0; i < k; ++i) checkPoints_.push_back(open[i * open.size() / k]);
        recordSlot_.assign(n_, -1);
        for (size_t i = 0; i < checkPoints_.size(); ++i) recordSlot_[checkPoints_[i]] = int(i);
        records_.resize(checkPoints_.size());
    }

    // The checkpoint of this year (annual_checkpoint.h) and what an earlier run of it traced.
    std::map<size_t, PointCoefficients> openCheckpoint() {
        if (settings_.checkpointDirectory.empty()) return {};
        const DaylightCoefficientSettings& c = settings_.coefficients;
        const std::string settingsText =
            std::to_string(c.skySubdivision) + "," + std::to_string(c.paths) + "," + std::to_string(c.sunPaths) + "," +
            std::to_string(c.batches) + "," + std::to_string(c.seed) + "," + std::to_string(settings_.sunDeclinationStepDeg) +
            "," + std::to_string(settings_.sunHourAngleStepDeg) + "," + std::to_string(north_.x) + "," + std::to_string(north_.z);
        const uint64_t key = annualCheckpointKey(scene_, points_, normal_, weather_.latitudeDeg, settingsText);
        // Each process of a shared year keeps its own points.
        char name[96];
        std::snprintf(name, sizeof name, "/annual-%016llx-%d-of-%d.checkpoint", static_cast<unsigned long long>(key),
                      rankOf(settings_.processes), sizeOf(settings_.processes));
        r_.checkpointPath = settings_.checkpointDirectory + name;
        checkpoint_ = std::make_unique<AnnualCheckpoint>(r_.checkpointPath, key);
        return checkpoint_->open(settings_.resume);
    }

    // 1. The coefficients, once: those of an interrupted run of the same year read back, except
    // the discretisation's points (their records are not kept), the rest traced and kept.
    void traceCoefficients() {
        std::map<size_t, PointCoefficients> restored = openCheckpoint();
        const IrradianceEstimator estimator(rs_);
        coefficients_.resize(n_);
        sensors_.resize(n_);
        std::atomic<int> traced{0};
        std::atomic<size_t> resumed{0};
        ctx_.parallelFor(0, int(n_), [&](int i) {
            const size_t p = size_t(i);
            const IrradianceSensor s = estimator.lifted({V3f(points_[p]), up_});
            sensors_[p] = s.position;
            const int slot = recordSlot_[p];
            if (r_.insideGeometry[p] || !mine(p)) {
                // no light reaches it, or another process traces it: its coefficients stay empty
            } else if (const auto kept = restored.find(p); kept != restored.end() && slot < 0) {
                coefficients_[p] = std::move(kept->second);
                ++resumed;
            } else {
                coefficients_[p] = tracer_.trace(s.position, s.normal, uint64_t(p), slot >= 0 ? &records_[size_t(slot)] : nullptr);
                if (checkpoint_) checkpoint_->append(p, coefficients_[p]);
            }
            ctx_.setProgress(0.8 * double(++traced) / double(n_));
        });
        r_.resumedPoints = resumed;
    }

    // 2. Each row's sun and sky inputs, and the rows that measure the discretisation.
    void readHours() {
        inputs_.resize(rows_);
        r_.hours.resize(rows_);
        std::vector<size_t> daylit;
        for (size_t row = 0; row < rows_; ++row) {
            const WeatherHour& h = weather_.hours[row];
            HourInputs& in = inputs_[row];
            in.towardSun = sunTowardAt(weather_, north_, h);
            in.perez = PerezInputs{h.directNormalIrradiance, h.diffuseHorizontalIrradiance,
                                   settings_.dewPointC.value_or(h.dewPointC), dayOfYear(weather_.year(), h.month, h.day),
                                   in.towardSun};
            in.daylight = h.directNormalIrradiance > 0 || h.diffuseHorizontalIrradiance > 0;
            if (in.daylight) {
                daylit.push_back(row);
                in.sky.emplace(in.perez, 0);
            }
            const double evd = in.daylight ? in.sky->diffuseIlluminance() : 0;
            r_.hours[row] = AnnualHour{h.month, h.day, h.hour, evd};
        }
        r_.daylightHours = int(daylit.size());
        checkRow_.assign(rows_, 0);
        const size_t k = std::min(daylit.size(), size_t(std::max(settings_.checkHours, 0)));
        for (size_t i = 0; i < k; ++i) checkRow_[daylit[(2 * i + 1) * daylit.size() / (2 * k)]] = 1;
        checkSkies_.resize(rows_);
    }

    // The sun's light straight onto point p through its disc (a direction per disc sample), lx
    // per lx of direct normal illuminance.
    double directSun(size_t p, const V3f& toward, const std::vector<V2f>& disc) const {
        const Frame frame(toward);
        const float radius = float(std::tan(sunHalfAngleRad_));
        double sum = 0;
        for (const V2f& d : disc) {
            const V3f w = (toward + frame.s * (d.x * radius) + frame.t * (d.y * radius)).normalized();
            const float cosine = w.dot(up_);
            if (cosine > 0) sum += luminance(rs_.transmittance(Ray{sensors_[p], w})) * cosine;
        }
        return sum / double(disc.size());
    }

    // 3. Every hour: the sky by patches, the sun's reflections by the nodes, its direct light
    // traced through the disc; each value's error from the batches' spread.
    void evaluateHours() {
        std::vector<SparseCoefficients> sparse;
        sparse.reserve(n_);
        for (const PointCoefficients& c : coefficients_) sparse.emplace_back(c.sky);
        const SkyAverager averager(fine_, coarse_);
        const std::vector<V2f> disc = discPattern(sunHalfAngleRad_ > 0 ? settings_.sunDiscSamples : 1);
        const int batches = settings_.coefficients.batches, coarseBins = coarse_.count() + 1, nodes = sunGrid_.nodeCount();
        const double t = studentT975(batches - 1);
        const double groundReflectance = scene_.sky ? scene_.sky->groundReflectance : Sky().groundReflectance;
        r_.lux.assign(rows_ * n_, 0.0f);
        r_.directSunLux.assign(rows_ * n_, 0.0f);
        r_.errorLux.assign(rows_ * n_, 0.0f);
        statisticalRelative_.assign(rows_ * n_, -1.0f);
        std::atomic<int> done{0};
        constexpr int kRowsPerTask = 24;
        ctx_.parallelFor(0, int((rows_ + kRowsPerTask - 1) / kRowsPerTask), [&](int task) {
            std::vector<double> batch(static_cast<size_t>(batches));
            for (size_t row = size_t(task) * kRowsPerTask; row < std::min(rows_, size_t(task + 1) * kRowsPerTask); ++row) {
                const HourInputs& in = inputs_[row];
                if (!in.daylight) continue;
                const PerezSky& sky = *in.sky;
                const bool sunUp = in.towardSun.y > 0 && sky.directNormalIlluminance() > 0;
                const double evn = sunUp ? sky.directNormalIlluminance() : 0;
                const double ground = groundReflectance * (sky.diffuseIlluminance() + evn * std::max(in.towardSun.y, 0.0)) / kPiD;
                HourSky hs = averager.average(sky, ground);
                const SunPathGrid::Stencil stencil = sunGrid_.stencil(in.towardSun);
                for (size_t p = 0; p < n_; ++p) {
                    if (r_.insideGeometry[p]) continue;
                    const PointCoefficients& c = coefficients_[p];
                    const size_t at = row * n_ + p;
                    double reflected = 0, direct = 0;
                    if (sunUp) {
                        for (int k = 0; k < 4; ++k) reflected += stencil.weight[k] * c.sunIndirect[size_t(stencil.node[k])];
                        reflected *= evn;
                        direct = evn * directSun(p, V3f(in.towardSun), disc);
                    }
                    const double total = sparse[p].dot(hs.patch) + reflected + direct;
                    r_.lux[at] = float(total);
                    r_.directSunLux[at] = float(direct);
                    // Batch means: each batch's coarse sky and sun nodes (the straight view and
                    // the direct sun are exact, the same in every batch).
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
                    r_.errorLux[at] = float(t * standardError);
                    if (total > 1) statisticalRelative_[at] = float(t * standardError / total);
                }
                if (checkRow_[row]) checkSkies_[row] = std::move(hs);
                ctx_.setProgress(0.8 + 0.2 * double(++done) / double(rows_));
            }
        });
    }

    // 4. The discretisation, on the sample: the binned and interpolated values against the same
    // paths summed direction by direction (the scene's own Perez sky, its 256-ring integral), the
    // straight view against cells twice as fine, and the sun traced at its own position; the
    // differences relative to the point's value, as 2 x their RMS, go into each value's error.
    void measureDiscretisation() {
        double sumSquares[4] = {0, 0, 0, 0};
        size_t count = 0;
        for (size_t row = 0; row < rows_; ++row) {
            if (!checkRow_[row] || checkSkies_[row].patch.empty()) continue;
            const HourInputs& in = inputs_[row];
            const PerezSky exactSky(in.perez);
            const HourSky& hs = checkSkies_[row];
            const bool sunUp = in.towardSun.y > 0 && exactSky.directNormalIlluminance() > 0;
            const double evn = sunUp ? exactSky.directNormalIlluminance() : 0;
            const SunPathGrid::Stencil stencil = sunGrid_.stencil(in.towardSun);
            const auto exactLuminance = [&](const V3f& w) { return w.y > 0 ? exactSky.luminance(V3d(w)) : double(hs.patch.back()); };
            for (size_t i = 0; i < checkPoints_.size(); ++i) {
                const size_t p = checkPoints_[i];
                const double total = r_.lux[row * n_ + p];
                if (!(total > 1)) continue;
                const PathRecords& rec = records_[i];
                double difference[3] = {0, 0, 0};  // straight view, reflected sky, the sun's reflections
                for (size_t bin = 0; bin < rec.direct.size(); ++bin) difference[0] += rec.direct[bin] * hs.patch[bin];
                for (const PathRecords::Escape& e : rec.directCells) difference[0] -= e.weight * exactLuminance(e.direction);
                for (const PathRecords::Escape& e : rec.escapes) {
                    const V3d w(e.direction);
                    difference[1] += e.weight * (hs.patch[size_t(w.y > 0 ? fine_.patchOf(w) : fine_.count())] - exactLuminance(e.direction));
                }
                if (sunUp) {
                    for (int k = 0; k < 4; ++k)
                        difference[2] += evn * stencil.weight[k] * coefficients_[p].sunIndirect[size_t(stencil.node[k])];
                    difference[2] -= evn * tracer_.sunIndirectAt(rec, V3f(in.towardSun));
                }
                for (int k = 0; k < 3; ++k) sumSquares[k] += (difference[k] / total) * (difference[k] / total);
                const double sum = (difference[0] + difference[1] + difference[2]) / total;
                sumSquares[3] += sum * sum;
                ++count;
            }
        }
        for (int k = 0; k < 3; ++k) r_.discretisationParts[k] = count ? 2 * std::sqrt(sumSquares[k] / double(count)) : 0;
        r_.discretisationRelative = count ? 2 * std::sqrt(sumSquares[3] / double(count)) : 0;
        for (size_t at = 0; at < r_.lux.size(); ++at) {
            const double d = r_.discretisationRelative * r_.lux[at];
            r_.errorLux[at] = float(std::sqrt(double(r_.errorLux[at]) * r_.errorLux[at] + d * d));
        }
        std::erase_if(statisticalRelative_, [](float x) { return x < 0; });
        if (!statisticalRelative_.empty()) {
            auto mid = statisticalRelative_.begin() + ptrdiff_t(statisticalRelative_.size() / 2);
            std::nth_element(statisticalRelative_.begin(), mid, statisticalRelative_.end());
            r_.statisticalRelative = *mid;
        }
    }

    const Scene& scene_;
    const std::vector<V3d>& points_;
    V3d normal_;
    const WeatherFile& weather_;
    const AnnualSettings& settings_;
    TaskContext& ctx_;
    size_t n_, rows_;
    RenderScene rs_;
    SkyPatches fine_, coarse_;
    V3d north_;
    SunPathGrid sunGrid_;
    DaylightCoefficientTracer tracer_;
    V3f up_;
    double sunHalfAngleRad_ = 0.5 * 0.53 * kPiD / 180;  // section 5's default disc, else the scene's sun's

    AnnualResult r_;
    std::unique_ptr<AnnualCheckpoint> checkpoint_;
    std::vector<size_t> checkPoints_;
    std::vector<int> recordSlot_;
    std::vector<PathRecords> records_;
    std::vector<PointCoefficients> coefficients_;
    std::vector<V3f> sensors_;
    std::vector<HourInputs> inputs_;
    std::vector<uint8_t> checkRow_;
    std::vector<HourSky> checkSkies_;  // kept only for the rows the check samples
    std::vector<float> statisticalRelative_;
};

}  // namespace

AnnualResult computeAnnual(const Scene& scene, const std::vector<V3d>& points, const V3d& normal,
                           const WeatherFile& weather, const AnnualSettings& settings, TaskContext& ctx) {
    return YearCalculation(scene, points, normal, weather, settings, ctx).run();
}

}  // namespace lucerna
