#include "render/progressive/bdpt/bdpt_tracer.h"

#include "render/trace/sensor_direct.h"

namespace lucerna {

namespace {
// Counts the numbers a caller reads.
class CountingGenerator final : public SampleGenerator {
public:
    explicit CountingGenerator(SampleGenerator& inner) : inner_(inner) {}
    float next1D() override {
        ++count;
        return inner_.next1D();
    }
    V2f next2D() override {
        count += 2;
        return inner_.next2D();
    }
    int count = 0;

private:
    SampleGenerator& inner_;
};
}  // namespace

BdptTracer::BdptTracer(const RenderScene& scene, const BdptSettings& settings)
    : scene_(scene), settings_(settings), densities_(scene) {
    camera_.reserve(16);
    light_.reserve(16);
}

PathVertex BdptTracer::cameraVertex(int point) const {
    PathVertex c;
    c.kind = VertexKind::Camera;
    c.light = uint32_t(point);
    c.sp.p = scene_.camera().position(point);
    c.sp.pError = V3f(0, 0, 0);
    c.sp.ng = scene_.camera().normal(point);
    c.beta = Rgb(1, 1, 1);
    return c;
}

bool BdptTracer::connectible(const PathVertex& v) const {
    if (v.kind == VertexKind::Camera || v.kind == VertexKind::AreaLight) return true;
    if (v.kind != VertexKind::Surface || v.delta) return false;
    const ShadingMaterial& mat = scene_.material(v.sp.material);
    return !mat.isDelta() && !mat.isEmitter();
}

void BdptTracer::randomWalk(Ray ray, Rgb beta, float pdfDir, int maxAdded, bool cameraSide, SampleGenerator& rng,
                            std::vector<PathVertex>& path, const std::optional<SurfacePoint>* firstHit) const {
    const float beta0 = maxComponent(beta);
    if (maxAdded <= 0 || !(beta0 > 0.0f)) return;
    for (int bounces = 0;;) {
        Rgb through(1, 1, 1);
        const auto hit = bounces == 0 && firstHit ? *firstHit : scene_.intersect(ray, nullptr, &through);
        beta *= through;  // glazing crossed on the way (a primary hit given by the caller crossed none)
        if (!hit) {
            if (cameraSide && scene_.lights().environment()) path.push_back(escapedVertex(ray, beta, pdfDir));
            break;
        }
        if (isBlack(beta)) break;
        PathVertex v;
        v.kind = VertexKind::Surface;
        v.sp = *hit;
        v.wo = -ray.direction.normalized();
        v.beta = beta;
        v.pdfFwd = VertexDensities::toArea(pdfDir, path.back(), v);
        const ShadingMaterial& mat = scene_.material(hit->material);
        // Emitters reflect nothing: the walk ends there. A camera subpath keeps the vertex for
        // the s = 0 strategy; a light subpath has no use for it.
        if (mat.isEmitter()) {
            if (cameraSide) path.push_back(v);
            break;
        }
        path.push_back(v);
        if (++bounces >= maxAdded) break;

        const Frame frame(shadingNormal(mat, v.sp.ng, v.wo));
        const V3f woLocal = frame.toLocal(v.wo);
        BsdfSample bs;
        const V2f u = rng.next2D();
        const float uLobe = rng.next1D();
        if (!bsdfSample(mat, woLocal, u, uLobe, bs)) break;
        float pdfRev = 0.0f;
        if (bs.isDelta) {
            // A delta lobe has no density another strategy could match: both sides get 0.
            path.back().delta = true;
            pdfDir = 0.0f;
        } else {
            pdfDir = bs.pdf;
            pdfRev = bsdfPdf(mat, bs.wi, woLocal);  // the same lobe, walked the other way
        }
        const size_t n = path.size();
        if (n >= 2) path[n - 2].pdfRev = VertexDensities::toArea(pdfRev, path[n - 1], path[n - 2]);
        beta *= bs.weight;  // symmetric BSDFs (no eta^2, geometric normals): no adjoint correction
        if (isBlack(beta) || !isFinite(beta)) break;
        // No roulette at a delta bounce: its throughput does not fall (glass keeps 1), so a
        // roulette there would only inflate it, by 1 / 0.95 a bounce: a camera subpath held
        // 96 bounces in the glass ball of the caustic scene by total internal reflection came
        // out 137 times too bright, and a Metropolis chain that finds such a path stalls on it.
        // A walk trapped for good ends at maxDepth.
        if (bounces >= settings_.rouletteStartDepth && !bs.isDelta) {
            // Relative to the subpath's start, so that light subpaths (whose beta carries the
            // light's power) are rouletted like camera subpaths.
            const float survive = std::min(0.95f, maxComponent(beta) / beta0);
            if (rng.next1D() >= survive) break;
            beta /= survive;
        }
        const V3f wi = frame.toWorld(bs.wi);
        ray = Ray{hit->spawnOrigin(wi), wi};
    }
}

PathVertex BdptTracer::escapedVertex(const Ray& ray, const Rgb& beta, float pdfDir) const {
    PathVertex v;
    v.kind = VertexKind::EnvironmentLight;
    const V3f dir = ray.direction.normalized();
    v.sp.p = scene_.lights().farAlong(ray.origin, dir);
    v.sp.pError = V3f(0, 0, 0);
    v.sp.ng = -dir;
    v.wo = -dir;
    v.beta = beta;
    v.pdfFwd = pdfDir;  // per unit solid angle (toArea leaves densities toward infinity so)
    v.light = scene_.lights().environmentIndex();
    return v;
}

void BdptTracer::traceCameraSubpath(float x, float y, const std::optional<SurfacePoint>* primaryHit,
                                    SampleGenerator& rng) {
    const int point = scene_.camera().pointAt(x);
    camera_.push_back(cameraVertex(point));
    const Ray ray = scene_.camera().ray(x, y);
    randomWalk(ray, Rgb(1, 1, 1), densities_.cameraPdfDirection(point, ray.direction), settings_.maxDepth + 1, true, rng,
               camera_, primaryHit);
}

void BdptTracer::traceLightSubpath(SampleGenerator& rng) {
    const LightSampler& lights = scene_.lights();
    EmissionSample es;
    const V2f uPosition = rng.next2D(), uDirection = rng.next2D();
    const float uSelect = rng.next1D();
    if (!lights.sampleEmission(uPosition, uDirection, uSelect, es) || !(es.pdfPosition > 0.0f)) return;
    PathVertex v0;
    v0.sp = es.surface();
    v0.light = es.light;
    if (es.environment) {
        v0.kind = VertexKind::EnvironmentLight;
        v0.sp.ng = es.direction;  // its pdfFwd needs the first hit: below
    } else if (es.triangle != 0xffffffffu) {
        v0.kind = VertexKind::AreaLight;
        v0.sp.material = 0;
        v0.pdfFwd = es.pdfPosition;
    } else if (es.deltaDirection) {
        v0.kind = VertexKind::DirectionalLight;
    } else {
        const DeltaLight& l = lights.deltaLights()[es.light - lights.emitters().size()];
        v0.kind = l.type == LightType::Spot        ? VertexKind::SpotLight
                  : l.type == LightType::Luminaire ? VertexKind::Luminaire
                                                   : VertexKind::PointLight;
    }
    // beta of a light vertex is 1 / (its selection-and-position density); the emission itself
    // enters as the vertex's "BSDF" when it is connected (s = 1, t = 1 only), and as es.power
    // once the particle leaves.
    v0.beta = Rgb(1.0f / es.pdfPosition);
    light_.push_back(v0);
    const V3f origin = v0.kind == VertexKind::AreaLight ? v0.sp.spawnOrigin(es.direction) : es.position;
    randomWalk(Ray{origin, es.direction}, es.power, es.pdfDirection, settings_.maxDepth, false, rng, light_);
    // Parallel particles: the first hit's density is the disk's, projected (pbrt-v3 16.3.2).
    if ((v0.kind == VertexKind::DirectionalLight || v0.atInfinity()) && light_.size() >= 2)
        light_[1].pdfFwd = densities_.pdfLight(light_[0], light_[1]);
    if (v0.atInfinity() && light_.size() >= 2) light_[0].pdfFwd = densities_.pdfLightOrigin(light_[0], &light_[1]);
}

void SampledPaths::path(const StrategyRecord& r, std::vector<PathVertex>& out) const {
    out.clear();
    if (r.t == 1) out.push_back(r.sampled);
    else out.insert(out.end(), camera.begin(), camera.begin() + r.t);
    if (r.s == 1) out.push_back(r.sampled);
    else
        for (int i = r.s - 1; i >= 0; --i) out.push_back(light[size_t(i)]);
}

Rgb BdptTracer::connect(int s, int t, bool weighted, SampleGenerator& rng, float& rasterX, float& rasterY,
                        StrategyRecord* record) const {
    Rgb L(0, 0, 0);
    PathVertex sampled;
    const PathVertex* sampledPtr = nullptr;
    if (s == 0) {
        const PathVertex& pt = camera_[t - 1];
        if (pt.atInfinity()) {
            L = pt.beta * densities_.emitted(pt, pt.sp.ng);
        } else {
            if (pt.kind != VertexKind::Surface || !scene_.material(pt.sp.material).isEmitter()) return L;
            L = pt.beta * densities_.emitted(pt, pt.wo);
        }
    } else if (t == 1) {
        const PathVertex& qs = light_[s - 1];
        if (!connectible(qs) || qs.kind == VertexKind::Camera) return L;
        const Sensor& camera = scene_.camera();
        // One sensor point, uniformly (no number is drawn for the pinhole's single one).
        const int point = camera.pointCount() == 1
                              ? 0
                              : std::min(camera.pointCount() - 1, int(rng.next1D() * float(camera.pointCount())));
        sampled = cameraVertex(point);
        sampledPtr = &sampled;
        const V3f d = sampled.p() - qs.p();
        const float dist2 = d.length2();
        if (!(dist2 > 0.0f)) return L;
        const V3f w = d / std::sqrt(dist2);  // from the light vertex to the sensor point
        if (!camera.rasterPoint(point, -w, rasterX, rasterY)) return L;
        const Rgb f = qs.kind == VertexKind::AreaLight ? densities_.emitted(qs, w) : densities_.bsdf(qs, w);
        // beta f |cos| G We: the camera's cosine is in We cos (1 / (A cos^3) for the pinhole).
        L = qs.beta * f * (std::abs(qs.sp.ng.dot(w)) * densities_.cameraImportance(point, -w) / dist2);
        if (isBlack(L)) return L;
        const V3f from = qs.sp.spawnOrigin(w);
        L *= scene_.transmittance(Ray{from, sampled.p() - from, 0.0f, kShadowRayEnd});
        if (isBlack(L)) return L;
    } else if (s == 1) {
        const PathVertex& pt = camera_[t - 1];
        if (!connectible(pt)) return L;
        LightSample ls;
        const V2f u = rng.next2D();
        const float uSelect = rng.next1D();
        if (!scene_.lights().sample(pt.sp, u, uSelect, ls, receivingNormal(pt, camera_[t - 2]))) return L;
        const LightSampler& lights = scene_.lights();
        sampled.light = ls.light;
        sampled.sp.p = ls.position;
        sampled.sp.pError = V3f(0, 0, 0);
        if (lights.isEnvironment(ls.light)) {
            sampled.kind = VertexKind::EnvironmentLight;
            sampled.sp.ng = -ls.wi;
            sampled.pdfFwd = densities_.pdfLightOrigin(sampled, &pt);
        } else if (ls.light < lights.emitters().size()) {
            const EmitterTriangle& e = lights.emitters()[ls.light];
            sampled.kind = VertexKind::AreaLight;
            sampled.sp.ng = e.normal;
            sampled.sp.triangle = e.triangle;
            sampled.pdfFwd = densities_.pdfLightOrigin(sampled);
        } else {
            const DeltaLight& l = lights.deltaLights()[ls.light - lights.emitters().size()];
            sampled.kind = l.type == LightType::Point       ? VertexKind::PointLight
                           : l.type == LightType::Spot      ? VertexKind::SpotLight
                           : l.type == LightType::Luminaire ? VertexKind::Luminaire
                                                            : VertexKind::DirectionalLight;
            sampled.sp.ng = l.direction;
            if (l.type == LightType::Directional)  // somewhere up the light's beam, outside the scene
                sampled.sp.p = scene_.lights().farAlong(pt.p(), ls.wi);
        }
        sampledPtr = &sampled;
        L = pt.beta * densities_.bsdf(pt, ls.wi) * ls.value * (std::abs(pt.sp.ng.dot(ls.wi)) / ls.pdf);
        if (isBlack(L)) return L;
        L *= scene_.transmittance(ls.shadowRay);
        if (isBlack(L)) return L;
    } else {
        const PathVertex &qs = light_[s - 1], &pt = camera_[t - 1];
        if (!connectible(qs) || !connectible(pt)) return L;
        const V3f d = pt.p() - qs.p();
        const float dist2 = d.length2();
        if (!(dist2 > 0.0f)) return L;
        const V3f w = d / std::sqrt(dist2);
        // beta_s f_s G f_t beta_t with G = |cos_s| |cos_t| / d^2 (eq. 10.8).
        const float g = std::abs(qs.sp.ng.dot(w)) * std::abs(pt.sp.ng.dot(w)) / dist2;
        L = qs.beta * densities_.bsdf(qs, w) * densities_.bsdf(pt, -w) * pt.beta * g;
        if (isBlack(L)) return L;
        L *= scene_.transmittanceBetween(qs.sp, pt.sp);
        if (isBlack(L)) return L;
    }
    if (!weighted) return L;
    const float w = misWeight(s, t, sampledPtr);
    if (record) {
        record->misWeight = w;
        if (sampledPtr) record->sampled = *sampledPtr;
        // The density the light point was drawn with, not the by-power one the weights compare.
        if (s == 1) record->sampled.pdfFwd *= nextEventRatio(sampled, camera_[t - 1], camera_[t - 2]);
    }
    return L * w;
}

V3f BdptTracer::receivingNormal(const PathVertex& x1, const PathVertex& x2) const {
    return shadingNormal(scene_.material(x1.sp.material), x1.sp.ng, x2.p() - x1.p());
}

float BdptTracer::nextEventRatio(const PathVertex& x0, const PathVertex& x1, const PathVertex& x2) const {
    if (x1.kind != VertexKind::Surface) return 1.0f;  // no next-event estimation from the camera
    const V3f receiving = receivingNormal(x1, x2);
    // A pure function of the light, x1 and the side it receives on: the strategies of one
    // sample ask for few distinct ones (every s >= 3 for the same), so the last few are kept.
    const uint32_t light = x0.onSurface() ? x0.sp.triangle : x0.light;
    for (const TauEntry& e : tauCache_)
        if (e.light == light && e.onSurface == x0.onSurface() && e.p == x1.p() && e.receiving == receiving) return e.tau;
    const LightSampler& lights = scene_.lights();
    const float tau = x0.onSurface() ? lights.emitterSelectionRatio(light, x1.p(), receiving)
                                     : lights.selectionRatio(light, x1.p(), receiving);
    tauCache_[tauNext_] = {light, x0.onSurface(), x1.p(), receiving, tau};
    tauNext_ = (tauNext_ + 1) % tauCache_.size();
    return tau;
}

float BdptTracer::misWeight(int s, int t, const PathVertex* sampled) const {
    const auto lightAt = [&](int i) -> const PathVertex& { return s == 1 && i == 0 ? *sampled : light_[size_t(i)]; };
    const auto cameraAt = [&](int i) -> const PathVertex& { return t == 1 && i == 0 ? *sampled : camera_[size_t(i)]; };
    // Paths of one edge: s = 0, t = 2 alone (s = 1, t = 1 is skipped), or beside next-event
    // estimation at an irradiance sensor's point (sampleTraced).
    if (s + t == 2) return sensorDirectWeight(cameraAt(0), cameraAt(1));
    const PathVertex* qs = s > 0 ? &lightAt(s - 1) : nullptr;
    const PathVertex& pt = cameraAt(t - 1);
    const PathVertex* qsMinus = s > 1 ? &lightAt(s - 2) : nullptr;
    const PathVertex* ptMinus = t > 1 ? &cameraAt(t - 2) : nullptr;

    // The reverse densities of the (up to) four vertices beside the connection, as they are in
    // this strategy's path (pbrt-v3's scoped assignments, without mutating the subpaths).
    const float ptRev = qs ? densities_.pdf(*qs, qsMinus, pt) : densities_.pdfLightOrigin(pt, ptMinus);
    const float ptMinusRev = !ptMinus ? 0.0f : qs ? densities_.pdf(pt, qs, *ptMinus) : densities_.pdfLight(pt, *ptMinus);
    const float qsRev = qs ? densities_.pdf(pt, ptMinus, *qs) : 0.0f;
    const float qsMinusRev = qsMinus ? densities_.pdf(*qs, &pt, *qsMinus) : 0.0f;

    // The vertices store a light point's density by power, as light subpaths start; next-event
    // estimation (s = 1) chose it with tau = nextEventRatio times that density at x1 (the tree's
    // choice there): its path density is p_1 tau, every other strategy's is as stored.
    const auto pathAt = [&](int j) -> const PathVertex& { return j < s ? lightAt(j) : cameraAt(s + t - 1 - j); };
    const double tau = nextEventRatio(pathAt(0), pathAt(1), pathAt(2));  // s + t >= 3: x2 exists
    const double own = s == 1 ? tau : 1.0;
    if (!(own > 0.0)) return 0.0f;

    // sum over the other strategies i of (p_i / p_s)^2, each ratio built vertex by vertex
    // outward from the connection (eq. 10.9); a zero density is a delta one and cancels (remap).
    const auto remap = [](float f) { return f != 0.0f ? f : 1.0f; };
    double sumRatios = 0.0, ratio = 1.0;
    for (int i = t - 1; i > 0; --i) {  // strategy (s + t - i, i)
        const PathVertex& v = cameraAt(i);
        const float rev = i == t - 1 ? ptRev : i == t - 2 ? ptMinusRev : v.pdfRev;
        const double r = double(remap(rev)) / double(remap(v.pdfFwd));
        ratio *= r * r;
        const bool deltaHere = i == t - 1 ? false : v.delta;
        if (!deltaHere && !cameraAt(i - 1).delta) sumRatios += s + t - i == 1 ? ratio * tau * tau : ratio;
    }
    ratio = 1.0;
    for (int i = s - 1; i >= 0; --i) {  // strategy (i, s + t - i)
        const PathVertex& v = lightAt(i);
        const float rev = i == s - 1 ? qsRev : i == s - 2 ? qsMinusRev : v.pdfRev;
        const double r = double(remap(rev)) / double(remap(v.pdfFwd));
        ratio *= r * r;
        const bool deltaHere = i == s - 1 ? false : v.delta;
        const bool deltaBefore = i > 0 ? lightAt(i - 1).delta : lightAt(0).isDeltaLight();
        if (!deltaHere && !deltaBefore) sumRatios += i == 1 ? ratio * tau * tau : ratio;
    }
    sumRatios /= own * own;
    const double w = 1.0 / (1.0 + sumRatios);
    return std::isfinite(w) ? float(w) : 0.0f;
}

float BdptTracer::sensorDirectWeight(const PathVertex& sensor, const PathVertex& light) const {
    const int point = int(sensor.light);
    if (light.atInfinity()) return sensorRayWeight(scene_, point, -light.sp.ng, nullptr);
    return sensorRayWeight(scene_, point, (light.p() - sensor.p()).normalized(), &light.sp);
}

Rgb BdptTracer::sample(float x, float y, SampleGenerator& rng, std::vector<FilmSplat>& splats) {
    return sampleTraced(x, y, nullptr, Reuse::Nothing, rng, splats);
}

Rgb BdptTracer::sample(float x, float y, const std::optional<SurfacePoint>& primaryHit, bool reuseLightSubpath,
                       SampleGenerator& rng, std::vector<FilmSplat>& splats) {
    return sampleTraced(x, y, &primaryHit, reuseLightSubpath ? Reuse::LightSubpath : Reuse::Nothing, rng, splats);
}

void BdptTracer::traceCameraSubpathOnly(float x, float y, SampleGenerator& rng) {
    camera_.clear();
    rng.beginStream(SampleStream::Camera);
    if (settings_.strategies != BdptSettings::Strategies::LightTracing) traceCameraSubpath(x, y, nullptr, rng);
}

Rgb BdptTracer::sampleWithCameraSubpath(float x, float y, SampleGenerator& rng, std::vector<FilmSplat>& splats) {
    return sampleTraced(x, y, nullptr, Reuse::CameraSubpath, rng, splats);
}

Rgb BdptTracer::sampleTraced(float x, float y, const std::optional<SurfacePoint>* primaryHit, Reuse reuse,
                             SampleGenerator& rng, std::vector<FilmSplat>& splats) {
    const bool lightTracingOnly = settings_.strategies == BdptSettings::Strategies::LightTracing;
    if (record_) record_->strategies.clear();  // (light tracing alone records nothing)
    if (reuse != Reuse::CameraSubpath) {
        camera_.clear();
        rng.beginStream(SampleStream::Camera);
        if (!lightTracingOnly) traceCameraSubpath(x, y, primaryHit, rng);
    }
    if (reuse != Reuse::LightSubpath) {
        light_.clear();
        rng.beginStream(SampleStream::Light);
        traceLightSubpath(rng);
    }
    rng.beginStream(SampleStream::Connection);

    const Sensor& camera = scene_.camera();
    const auto splat = [&](const Rgb& value, float rx, float ry) {
        if (isBlack(value) || !isFinite(value)) return;
        const int px = std::clamp(int(rx), 0, camera.width() - 1), py = std::clamp(int(ry), 0, camera.height() - 1);
        splats.push_back(FilmSplat{px, py, value});
    };
    const int nLight = int(light_.size());
    if (lightTracingOnly) {
        // Every light vertex to the pinhole, weight 1; s = 1 too (emitters seen directly), but
        // not for delta lights, which no camera ray can see (SPEC.md).
        for (int s = 1; s <= std::min(nLight, settings_.maxDepth + 1); ++s) {
            float rx = 0, ry = 0;
            if (s == 1 && light_[0].kind != VertexKind::AreaLight) continue;
            const Rgb c = connect(s, 1, false, rng, rx, ry);  // before reading rx, ry
            splat(c, rx, ry);
        }
        return Rgb(0, 0, 0);
    }

    const int nCamera = int(camera_.size());
    if (nCamera >= 1) {
        // t = 1 first, as the connection numbers are laid out. Its contributions depend on the
        // light subpath and the numbers they read alone (the camera subpath is replaced by a
        // sensor point), so a reused light subpath brings its splats along: only the numbers
        // are read again, to keep every later one where it was.
        if (reuse == Reuse::LightSubpath) {
            // (Reuse is for Metropolis samplers, whose pairs are two single numbers.)
            for (int i = 0; i < lightTracingNumbers_; ++i) rng.next1D();
        } else {
            CountingGenerator counted(rng);
            lightTracingSplats_.clear();
            for (int s = 2; s <= std::min(nLight, settings_.maxDepth + 1); ++s) {
                StrategyRecord r;
                r.s = s;
                r.t = 1;
                r.weighted = connect(s, 1, true, counted, r.rasterX, r.rasterY, &r);
                if (!isBlack(r.weighted) && isFinite(r.weighted)) lightTracingSplats_.push_back(r);
            }
            lightTracingNumbers_ = counted.count;
        }
        for (const StrategyRecord& s : lightTracingSplats_) splat(s.weighted, s.rasterX, s.rasterY);
    }
    if (record_) record_->strategies = lightTracingSplats_;
    Rgb L(0, 0, 0);
    for (int t = 2; t <= nCamera; ++t)
        for (int s = 0; s <= std::max(nLight, 1); ++s) {
            if (s + t - 2 > settings_.maxDepth) continue;
            if (s >= 2 && s > nLight) continue;
            float rx = 0, ry = 0;
            StrategyRecord r;
            r.s = s;
            r.t = t;
            const Rgb c = connect(s, t, true, rng, rx, ry, record_ ? &r : nullptr);
            if (!isFinite(c)) continue;
            L += c;
            if (record_ && !isBlack(c)) {
                r.weighted = c;
                r.rasterX = x;
                r.rasterY = y;
                record_->strategies.push_back(r);
            }
        }
    // Last, so that every number before it stays where it was for the pinhole.
    if (const Rgb c = nCamera >= 1 ? sensorNextEvent(scene_, int(camera_[0].light), rng) : Rgb(0, 0, 0);
        isFinite(c) && !isBlack(c)) {
        L += c;
        if (record_) {
            StrategyRecord r;
            r.s = r.t = 1;
            r.sensorNextEvent = true;
            r.sampled = camera_[0];
            r.weighted = c;
            r.rasterX = x;
            r.rasterY = y;
            record_->strategies.push_back(r);
        }
    }
    if (record_) {
        record_->camera = camera_;
        record_->light = light_;
    }
    return L;
}

}  // namespace lucerna
