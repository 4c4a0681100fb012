#include "render/trace/lights/light_sampler.h"

#include <algorithm>
#include <cmath>

#include "core/photometry/luminaire.h"
#include "render/trace/warp.h"

namespace lucerna {

DeltaLight compileDeltaLight(const Light& l, GoniometricSamplers* samplers) {
    DeltaLight d;
    if (l.type == LightType::Sun) {  // daylight, placed by the site: RenderScene adds it (black here)
        d.type = LightType::Directional;
        d.intensity = Rgb(0, 0, 0);
        return d;
    }
    d.type = l.type;
    d.position = toFloat(l.position);
    d.direction = toFloat(l.direction.normalized());
    d.intensity = toFloat(l.type == LightType::Directional ? l.irradiance : l.intensity);
    if (l.type == LightType::Spot) {
        d.cosCone = float(std::cos(radians(l.coneAngleDeg)));
        d.cosFalloffStart = float(std::cos(radians(l.falloffStartDeg.value_or(l.coneAngleDeg))));
    }
    if (l.type == LightType::Luminaire) {
        d.intensity = toFloat(luminaireRadiantScale(l));  // black until the file is loaded
        const LuminaireFrame f = luminaireFrame(l.direction, l.luminaire ? l.luminaire->rotationDeg.value_or(0.0) : 0.0);
        d.direction = toFloat(f.nadir);
        d.c0 = toFloat(f.c0);
        d.c90 = toFloat(f.c90);
        if (l.luminaire && l.luminaire->distribution) {
            const auto& distribution = l.luminaire->distribution;
            if (!samplers) d.goniometric = std::make_shared<const GoniometricSampler>(distribution);
            else {
                auto& shared = (*samplers)[distribution.get()];
                if (!shared) shared = std::make_shared<const GoniometricSampler>(distribution);
                d.goniometric = shared;
            }
        } else
            d.intensity = Rgb(0, 0, 0);
    }
    return d;
}

float DeltaLight::factor(const V3f& w) const {
    switch (type) {
    case LightType::Spot: return spotFactor(w.dot(direction));
    case LightType::Luminaire: return goniometric ? goniometric->intensity(toLuminaire(w)) : 0.0f;
    default: return 1.0f;
    }
}

float DeltaLight::pdfDirection(const V3f& w) const {
    switch (type) {
    case LightType::Point: return uniformSpherePdf();
    case LightType::Spot: return w.dot(direction) < cosCone ? 0.0f : uniformConePdf(cosCone);
    case LightType::Luminaire: return goniometric ? goniometric->pdf(toLuminaire(w)) : 0.0f;
    case LightType::Directional:
    case LightType::Sun: return 0.0f;
    }
    return 0.0f;
}

float DeltaLight::spotFactor(float cosTheta) const {
    if (cosFalloffStart <= cosCone)  // equal angles: a hard edge
        return cosTheta >= cosCone ? 1.0f : 0.0f;
    const float t = std::clamp((cosTheta - cosCone) / (cosFalloffStart - cosCone), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

namespace {
// Power of each light, in one common unit (irradiance times scene units squared), so that the
// selection probabilities are comparable across light types. Luminance weights the channels.
double emitterPower(const EmitterTriangle& e) { return kPi * double(e.area) * luminance(e.radiance); }

double deltaPower(const DeltaLight& l, float metersPerUnit, float sceneRadius) {
    const double y = luminance(l.intensity);
    const double toScene = 1.0 / (double(metersPerUnit) * metersPerUnit);  // E = I / (d mpu)^2
    switch (l.type) {
    case LightType::Point: return 4.0 * kPi * y * toScene;
    case LightType::Spot: {
        // Solid angle of the cone, with the smooth edge counted at half weight.
        const double c = 0.5 * (double(l.cosCone) + double(std::max(l.cosCone, l.cosFalloffStart)));
        return 2.0 * kPi * (1.0 - c) * y * toScene;
    }
    case LightType::Luminaire: return l.goniometric ? l.goniometric->flux() * y * toScene : 0.0;
    case LightType::Directional: return kPi * double(sceneRadius) * sceneRadius * y;
    case LightType::Sun: return 0.0;  // never a delta light of its own (compileDeltaLight)
    }
    return 0.0;
}
}  // namespace

LightSampler::LightSampler(std::vector<EmitterTriangle> emitters, std::vector<DeltaLight> deltas, float metersPerUnit,
                           const V3f& sceneCenter, float sceneRadius, size_t triangleCount,
                           LightSelection selection, std::optional<EnvironmentLight> environment,
                           std::vector<Portal> portals)
    : emitters_(std::move(emitters)), deltas_(std::move(deltas)), environment_(std::move(environment)),
      metersPerUnit_(metersPerUnit), sceneCenter_(sceneCenter), sceneRadius_(sceneRadius) {
    // Portals serve the sky: aimed at a pane, a sample finds the sun's tiny disc almost never.
    if (environment_ && environment_->hasSky() && !portals.empty() && portals.size() <= kMaxPortalTriangles) {
        std::vector<double> areas;
        for (const Portal& p : portals) areas.push_back(p.area), portalArea_ += p.area;
        if (portalArea_ > 0) portals_ = std::move(portals), portalSelect_ = DiscreteDistribution(areas);
    }
    std::vector<double> weights;
    weights.reserve(emitters_.size() + deltas_.size() + 1);
    for (const auto& e : emitters_) weights.push_back(emitterPower(e));
    for (const auto& l : deltas_) weights.push_back(deltaPower(l, metersPerUnit, sceneRadius));
    // The power of the particles the environment sends: pi R^2 times its integrated radiance.
    if (environment_) weights.push_back(kPi * double(sceneRadius) * sceneRadius * environment_->integratedLuminance());
    select_ = DiscreteDistribution(weights);
    areaPdf_.assign(emitters_.empty() ? 0 : triangleCount, 0.0f);
    if (!select_.empty())
        for (size_t i = 0; i < emitters_.size(); ++i)
            areaPdf_[emitters_[i].triangle] = float(select_.pdf(i) / double(emitters_[i].area));
    if (selection == LightSelection::Tree && select_.size() > 1) buildTree(triangleCount);
}

namespace {

// Emissive triangles share a tree leaf while they are neighbours in the mesh's order with one
// radiance, face within about 25 degrees of the first one and stay within a box four times the
// first one's: a quad lamp is one leaf, a tessellated panel a leaf per patch of up to 16
// triangles. Within a leaf a triangle is chosen by power (its area): they are close enough
// that the tree could not tell them apart, and the descent is shorter.
constexpr size_t kClusterSize = 16;

bool joins(const EmitterTriangle& first, const LightBounds& cluster, const EmitterTriangle& e, float firstDiagonal) {
    if (e.radiance != first.radiance || e.normal.dot(first.normal) < 0.9f) return false;
    LightBounds grown = cluster;
    for (const V3f& p : {e.p0, e.p1, e.p2})
        for (int k = 0; k < 3; ++k) {
            grown.lo[k] = std::min(grown.lo[k], p[k]);
            grown.hi[k] = std::max(grown.hi[k], p[k]);
        }
    return (grown.hi - grown.lo).length() <= 4 * firstDiagonal;
}

}  // namespace

void LightSampler::buildTree(size_t triangleCount) {
    std::vector<LightBounds> bounds;
    leafOfTriangle_.assign(triangleCount, -1);
    shareInLeaf_.assign(emitters_.size(), 0.0f);
    for (size_t i = 0; i < emitters_.size();) {
        const EmitterTriangle& first = emitters_[i];
        const float radianceY = luminance(first.radiance);
        LightBounds cluster = LightBounds::triangle(first.p0, first.p1, first.p2, first.normal, radianceY);
        const float firstDiagonal = (cluster.hi - cluster.lo).length();
        size_t end = i + 1;
        while (end < emitters_.size() && end - i < kClusterSize && joins(first, cluster, emitters_[end], firstDiagonal)) {
            const EmitterTriangle& e = emitters_[end];
            cluster = unite(cluster, LightBounds::triangle(e.p0, e.p1, e.p2, e.normal, radianceY));
            ++end;
        }
        double area = 0;
        for (size_t k = i; k < end; ++k) area += emitters_[k].area;
        for (size_t k = i; k < end; ++k) {
            shareInLeaf_[k] = float(emitters_[k].area / area);
            leafOfTriangle_[emitters_[k].triangle] = int32_t(bounds.size());
        }
        leaves_.push_back({uint32_t(i), uint32_t(end), float(area)});
        bounds.push_back(cluster);
        i = end;
    }
    for (size_t i = 0; i < deltas_.size(); ++i) {
        const DeltaLight& l = deltas_[i];
        const uint32_t index = uint32_t(emitters_.size() + i);
        const float intensity = luminance(l.intensity) / (metersPerUnit_ * metersPerUnit_);
        switch (l.type) {
        case LightType::Directional: directional_.push_back(index); continue;
        case LightType::Spot:
            bounds.push_back(LightBounds::spot(l.position, l.direction, std::acos(std::clamp(l.cosCone, -1.0f, 1.0f)),
                                               intensity));
            break;
        case LightType::Luminaire:
            // A spot about the nadir as wide as the table's last lit gamma (an uplight's upper
            // hemisphere included), as strong as the table's peak.
            if (!l.goniometric) continue;
            bounds.push_back(LightBounds::spot(l.position, l.direction, l.goniometric->emissionConeRad(),
                                               intensity * l.goniometric->peakIntensity()));
            break;
        default: bounds.push_back(LightBounds::point(l.position, intensity)); break;
        }
        leaves_.push_back({index, index + 1, 0.0f});
    }
    if (environment_) directional_.push_back(environmentIndex());
    if (leaves_.size() == 1 && directional_.empty()) {
        // One cluster (a quad lamp) or one light: the tree would choose it with probability 1
        // and its triangles by area, as power selection does, only slower.
        leaves_.clear();
        shareInLeaf_.clear();
        leafOfTriangle_.clear();
        return;
    }
    tree_ = LightTree(bounds);
}

bool LightSampler::selectByTree(const V3f& p, const V3f& n, float u, size_t& index, float& pdf) const {
    // The tree and the directional lights share the choice evenly, as in pbrt-v4.
    const size_t choices = directional_.size() + (tree_.empty() ? 0 : 1);
    if (choices == 0) return false;
    const size_t k = std::min(size_t(u * float(choices)), choices - 1);
    const float share = 1.0f / float(choices);
    if (k < directional_.size()) {
        index = directional_[k];
        pdf = share;
        return true;
    }
    const auto choice = tree_.sample(p, n, std::min(u * float(choices) - float(k), 0x1.fffffep-1f));
    if (!choice) return false;
    const TreeLeaf& leaf = leaves_[choice->light];
    index = leaf.begin;
    // Within a cluster by area, with what is left of u after the descent.
    for (float rest = choice->u; index + 1 < leaf.end && rest >= shareInLeaf_[index]; ++index) rest -= shareInLeaf_[index];
    pdf = share * choice->pmf * (index < emitters_.size() ? shareInLeaf_[index] : 1.0f);
    return pdf > 0;
}

bool LightSampler::sample(const SurfacePoint& ref, const V2f& u, float uSelect, LightSample& out,
                          const V3f& receiving) const {
    if (select_.empty()) return false;
    size_t index = 0;
    float selectPdf = 1.0f;
    if (!leaves_.empty() || !directional_.empty()) {
        if (!selectByTree(ref.p, receiving, uSelect, index, selectPdf)) return false;
    } else if (select_.size() > 1) {
        index = select_.sample(uSelect);
        selectPdf = float(select_.pdf(index));
    }
    out.light = uint32_t(index);
    if (index < emitters_.size()) return sampleEmitter(emitters_[index], selectPdf, ref, u, out);
    if (isEnvironment(uint32_t(index))) return sampleEnvironment(selectPdf, ref, u, out);
    return sampleDelta(deltas_[index - emitters_.size()], selectPdf, ref, out);
}

float LightSampler::environmentSelectPdf() const {
    if (!environment_) return 0.0f;
    if (!leaves_.empty() || !directional_.empty()) return 1.0f / float(directional_.size() + (tree_.empty() ? 0 : 1));
    return select_.size() > 1 ? float(select_.pdf(environmentIndex())) : 1.0f;
}

float LightSampler::portalPdf(const V3f& w, const V3f& p) const {
    // Every pane triangle the ray from p along w crosses adds t^2 / (A |cos|): the uniform
    // density 1 / A over the panes' total area A, turned into solid angle at p.
    float pdf = 0.0f;
    for (const Portal& portal : portals_) {
        const float cosine = portal.normal.dot(w);
        if (cosine == 0.0f) continue;
        const V3f e1 = portal.p1 - portal.p0, e2 = portal.p2 - portal.p0;
        const V3f s = w.cross(e2);
        const float det = e1.dot(s);
        if (det == 0.0f) continue;
        const V3f o = p - portal.p0;
        const float b1 = o.dot(s) / det;
        const V3f q = o.cross(e1);
        const float b2 = w.dot(q) / det, t = e2.dot(q) / det;
        if (b1 < 0 || b2 < 0 || b1 + b2 > 1 || !(t > 0)) continue;
        pdf += t * t / (portalArea_ * std::abs(cosine));
    }
    return pdf;
}

float LightSampler::environmentDirectionPdf(const V3f& w, const V3f& p) const {
    const float q = portalShare();
    return (1.0f - q) * environment_->pdf(w) + (q > 0 ? q * portalPdf(w, p) : 0.0f);
}

float LightSampler::pdfEnvironment(const V3f& w, const V3f& p) const {
    return environment_ ? environmentSelectPdf() * environmentDirectionPdf(w, p) : 0.0f;
}

float LightSampler::pdfEnvironmentByPower(const V3f& w, const V3f& p) const {
    if (!environment_) return 0.0f;
    return (select_.size() > 1 ? float(select_.pdf(environmentIndex())) : 1.0f) * environmentDirectionPdf(w, p);
}

bool LightSampler::sampleEnvironment(float selectPdf, const SurfacePoint& ref, const V2f& u, LightSample& out) const {
    const float q = portalShare();
    if (u.x < q) {
        // Aim at a uniform point of the panes.
        float uRest = 0.0f;
        const Portal& portal = portals_[portalSelect_.sample(std::min(u.x / q, 0x1.fffffep-1f), &uRest)];
        const V2f b = squareToUniformTriangle(V2f(uRest, u.y));
        const V3f target = portal.p0 * (1.0f - b.x - b.y) + portal.p1 * b.x + portal.p2 * b.y;
        const V3f d = target - ref.p;
        const float length = d.length();
        if (!(length > 0.0f)) return false;
        out.wi = d / length;
        out.value = environment_->radiance(out.wi);
        if (isBlack(out.value)) return false;
    } else {
        float ignored = 0.0f;
        const V2f rest(std::min((u.x - q) / (1.0f - q), 0x1.fffffep-1f), u.y);
        if (!environment_->sample(rest, out.wi, ignored, out.value)) return false;
    }
    out.pdf = selectPdf * environmentDirectionPdf(out.wi, ref.p);
    out.isDelta = false;
    out.position = farAlong(ref.p, out.wi);  // bidirectional connections need a place
    out.shadowRay = Ray{ref.spawnOrigin(out.wi), out.wi};
    return out.pdf > 0.0f && std::isfinite(out.pdf);
}

bool LightSampler::sampleDeltaLight(size_t index, const SurfacePoint& ref, LightSample& out) const {
    if (index >= deltas_.size()) return false;
    out.light = uint32_t(emitters_.size() + index);
    return sampleDelta(deltas_[index], 1.0f, ref, out);
}

bool LightSampler::sampleEmitter(const EmitterTriangle& e, float selectPdf, const SurfacePoint& ref, const V2f& u,
                                 LightSample& out) const {
    const V2f b = squareToUniformTriangle(u);
    const float b0 = 1.0f - b.x - b.y;
    SurfacePoint q;
    q.p = e.p0 * b0 + e.p1 * b.x + e.p2 * b.y;
    q.pError = interpolationError(e.p0, e.p1, e.p2, b0, b.x, b.y);
    q.ng = e.normal;
    q.triangle = e.triangle;
    out.position = q.p;
    const V3f toLight = q.p - ref.p;
    const float dist2 = toLight.length2();
    if (!(dist2 > 0.0f)) return false;
    out.wi = toLight / std::sqrt(dist2);
    const float cosLight = -out.wi.dot(e.normal);
    if (cosLight <= 0.0f) return false;  // the back of a one-sided emitter
    out.value = e.radiance;
    out.pdf = selectPdf * dist2 / (e.area * cosLight);
    out.isDelta = false;
    const V3f from = ref.spawnOrigin(out.wi);
    const V3f to = q.spawnOrigin(-out.wi);
    out.shadowRay = Ray{from, to - from, 0.0f, kShadowRayEnd};
    return out.pdf > 0.0f && std::isfinite(out.pdf);
}

bool LightSampler::sampleDelta(const DeltaLight& l, float selectPdf, const SurfacePoint& ref, LightSample& out) const {
    out.isDelta = true;
    out.pdf = selectPdf;
    if (l.type == LightType::Directional) {
        out.wi = -l.direction;
        out.value = l.intensity;
        out.shadowRay = Ray{ref.spawnOrigin(out.wi), out.wi};
        return true;
    }
    out.position = l.position;
    const V3f toLight = l.position - ref.p;
    const float dist2 = toLight.length2();
    if (!(dist2 > 0.0f)) return false;
    out.wi = toLight / std::sqrt(dist2);
    float factor = 1.0f;
    if (l.type != LightType::Point) {
        factor = l.factor(-out.wi);
        if (factor <= 0.0f) return false;
    }
    // SPEC.md: E = I cos / (d * meters_per_unit)^2.
    out.value = l.intensity * (factor / (dist2 * metersPerUnit_ * metersPerUnit_));
    const V3f from = ref.spawnOrigin(out.wi);
    out.shadowRay = Ray{from, l.position - from, 0.0f, kShadowRayEnd};
    return true;
}

SurfacePoint EmissionSample::surface() const {
    SurfacePoint sp;
    sp.p = position;
    sp.pError = pError;
    sp.ng = normal;
    sp.triangle = triangle;
    return sp;
}

bool LightSampler::sampleEmission(const V2f& uPosition, const V2f& uDirection, float uSelect,
                                  EmissionSample& out) const {
    if (select_.empty()) return false;
    size_t index = 0;
    float selectPdf = 1.0f;
    if (select_.size() > 1) {  // particles leave in proportion to power, tree or not
        index = select_.sample(uSelect);
        selectPdf = float(select_.pdf(index));
    }
    out = EmissionSample();
    out.light = uint32_t(index);
    if (isEnvironment(uint32_t(index))) return emitFromEnvironment(selectPdf, uPosition, uDirection, out);
    if (index < emitters_.size()) {
        const EmitterTriangle& e = emitters_[index];
        const V2f b = squareToUniformTriangle(uPosition);
        const float b0 = 1.0f - b.x - b.y;
        out.position = e.p0 * b0 + e.p1 * b.x + e.p2 * b.y;
        out.pError = interpolationError(e.p0, e.p1, e.p2, b0, b.x, b.y);
        out.normal = e.normal;
        out.triangle = e.triangle;
        const V3f local = squareToCosineHemisphere(uDirection);
        if (local.z <= 0.0f) return false;
        out.direction = Frame(e.normal).toWorld(local);
        out.pdfPosition = selectPdf / e.area;
        out.pdfDirection = cosineHemispherePdf(local);
        // Le cos / (pdfPosition pdfDirection) = Le pi area / selectPdf.
        out.power = e.radiance * (local.z / (out.pdfPosition * out.pdfDirection));
        return true;
    }
    const DeltaLight& l = deltas_[index - emitters_.size()];
    const float toScene = 1.0f / (metersPerUnit_ * metersPerUnit_);
    switch (l.type) {
    case LightType::Point:
        out.position = l.position;
        out.direction = squareToUniformSphere(uDirection);
        out.pdfDirection = uniformSpherePdf();
        out.power = l.intensity * (toScene / (selectPdf * out.pdfDirection));
        break;
    case LightType::Spot: {
        out.position = l.position;
        const V3f local = squareToUniformCone(uDirection, l.cosCone);
        out.direction = Frame(l.direction).toWorld(local);
        out.pdfDirection = uniformConePdf(l.cosCone);
        const float factor = l.spotFactor(local.z);
        if (factor <= 0.0f) return false;
        out.power = l.intensity * (factor * toScene / (selectPdf * out.pdfDirection));
        break;
    }
    case LightType::Luminaire: {
        out.position = l.position;
        V3f local(0, 0, 1);
        float pdf = 0.0f;
        if (!l.goniometric || !l.goniometric->sample(uDirection, local, pdf)) return false;
        out.direction = (l.c0 * local.x + l.c90 * local.y + l.direction * local.z).normalized();
        out.pdfDirection = pdf;
        const float candela = l.goniometric->intensity(local);
        if (candela <= 0.0f) return false;
        out.power = l.intensity * (candela * toScene / (selectPdf * pdf));
        break;
    }
    case LightType::Directional: {
        // A disk of the scene's radius, facing the light, just outside the scene.
        const V2f d = squareToUniformDisk(uPosition) * sceneRadius_;
        const Frame frame(l.direction);
        out.position = sceneCenter_ - l.direction * sceneRadius_ + frame.s * d.x + frame.t * d.y;
        out.direction = l.direction;
        out.deltaDirection = true;
        const float area = kPi * sceneRadius_ * sceneRadius_;
        out.pdfPosition = selectPdf / area;
        out.pdfDirection = 0.0f;
        out.power = l.intensity * (area / selectPdf);
        out.normal = l.direction;
        return true;
    }
    case LightType::Sun: return false;  // never a delta light of its own (compileDeltaLight)
    }
    out.normal = out.direction;
    out.deltaPosition = true;
    out.pdfPosition = selectPdf;
    return true;
}

bool LightSampler::emitFromEnvironment(float selectPdf, const V2f& uPosition, const V2f& uDirection,
                                       EmissionSample& out) const {
    // A direction toward the sky, then a point on the disc of the scene's radius facing it,
    // just outside the scene; the particle travels back along the direction.
    V3f toward;
    float pdfDirection = 0.0f;
    Rgb L;
    if (!environment_->sample(uDirection, toward, pdfDirection, L)) return false;
    const V2f d = squareToUniformDisk(uPosition) * sceneRadius_;
    const Frame frame(toward);
    out.position = sceneCenter_ + toward * sceneRadius_ + frame.s * d.x + frame.t * d.y;
    out.direction = -toward;
    out.normal = -toward;
    const float area = kPi * sceneRadius_ * sceneRadius_;
    out.pdfPosition = selectPdf / area;
    out.pdfDirection = pdfDirection;
    out.power = L / (out.pdfPosition * pdfDirection);
    out.environment = true;
    return isFinite(out.power);
}

float LightSampler::pdfEmitter(uint32_t triangle, const V3f& p, const V3f& q, const V3f& nq,
                               const V3f& receiving) const {
    float areaPdf = triangle < areaPdf_.size() ? areaPdf_[triangle] : 0.0f;
    if (areaPdf <= 0.0f) return 0.0f;
    if (!leaves_.empty()) {
        const int32_t leaf = leafOfTriangle_[triangle];
        if (leaf < 0) return 0.0f;
        // The triangle's share of its leaf over its area: 1 / the leaf's area.
        const float share = 1.0f / float(directional_.size() + 1);
        areaPdf = share * tree_.pmf(p, receiving, uint32_t(leaf)) / leaves_[size_t(leaf)].area;
        if (areaPdf <= 0.0f) return 0.0f;
    }
    const V3f d = q - p;
    const float dist2 = d.length2();
    const float cosLight = std::abs(nq.dot(d)) / std::sqrt(dist2);
    if (!(cosLight > 0.0f)) return 0.0f;
    return areaPdf * dist2 / cosLight;
}

}  // namespace lucerna
