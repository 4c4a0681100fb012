#include "render/preview/preview.h"

#include "core/scene/scene_change.h"

#include "render/preview/daylight_samples.h"
#include "render/preview/gpu_state.h"
#include "render/preview/mir_vpl_source.h"
#include "render/preview/per_light_vpls.h"
#include "render/preview/shadow_proxy.h"
#include "render/trace/render_scene.h"
#include "render/trace/rng.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <numeric>
#include <optional>
#include <stdexcept>

namespace lucerna {

using namespace preview_detail;

std::string Preview::defaultShaderDirectory() { return std::string(LUCERNA_RESOURCE_DIR) + "/shaders/preview"; }

Preview::Preview(std::string shaderDir) : context_(std::make_unique<EglContext>()), state_(std::make_unique<State>()) {
    EglContext::ScopedCurrent current(*context_);
    State& st = *state_;
    st.shaderDir = std::move(shaderDir);
    const std::string& d = st.shaderDir;
    st.gbufferProgram = gl::loadProgram(d, "gbuffer.vert", "gbuffer.frag");
    st.splitProgram = gl::loadProgram(d, "fullscreen.vert", "split.frag");
    st.blurProgram = gl::loadProgram(d, "fullscreen.vert", "blur.frag");
    st.blockBoundsProgram = gl::loadProgram(d, "fullscreen.vert", "light_block_bounds.frag");
    st.shadowProgram = gl::loadProgram(d, "shadow.vert", "shadow.frag", "shadow.geom");
    st.dirShadowProgram = gl::loadProgram(d, "shadow_dir.vert", "shadow_dir.frag");
    st.glazingProgram = gl::loadProgram(d, "gbuffer.vert", "glazing.frag");
    st.glazingShadowProgram = gl::loadProgram(d, "shadow_dir.vert", "glazing.frag");
    st.skyShadows.filtered = false;
    st.rawDepth = gl::makeSampler();
    glSamplerParameteri(st.rawDepth.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(st.rawDepth.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(st.rawDepth.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
    st.emptyVao = gl::makeVertexArray();
    gl::checkErrors("Preview()");
}

Preview::~Preview() {
    // GL names must go while the context is current; the context itself goes last.
    EglContext::ScopedCurrent current(*context_);
    state_.reset();
}

const PreviewTimings& Preview::timings() const { return state_->timings; }
const std::string& Preview::degradation() const { return state_->degradation; }
int Preview::vplSetGenerations() const { return state_->generations; }

void Preview::setSettings(const PreviewSettings& s) {
    const bool regenerateVpls =
        s.vplCount != settings_.vplCount || s.seed != settings_.seed || s.maxBounces != settings_.maxBounces ||
        s.vplSource != settings_.vplSource || s.indirect != settings_.indirect ||
        s.metropolisUnderDaylight != settings_.metropolisUnderDaylight ||
        // Whether one set serves all lights depends on the sub-buffer count.
        s.patternX * s.patternY != settings_.patternX * settings_.patternY ||
        // MIR's chain targets the clamped contribution, so its VPLs depend on the clamp.
        (s.clampDistance != settings_.clampDistance &&
         (s.vplSource == VplSource::Metropolis ||
          (s.metropolisUnderDaylight && (state_->daylight.sun || state_->daylight.sky))));
    // The area-light samples are dealt to the sub-buffers like VPLs: a new pattern redeals them.
    const bool relight = s.areaLightSamples != settings_.areaLightSamples || s.shadowSize != settings_.shadowSize ||
                         s.patternX != settings_.patternX || s.patternY != settings_.patternY ||
                         s.lightsShadedInFull != settings_.lightsShadedInFull;
    const bool repartition = s.patternX != settings_.patternX || s.patternY != settings_.patternY ||
                             s.vplShadowSize != settings_.vplShadowSize || s.visibility != settings_.visibility ||
                             s.maxUnrolledVpls != settings_.maxUnrolledVpls;
    if (s.patternX < 1 || s.patternY < 1 || s.vplCount < 0 || s.splitBlock < 1)
        throw std::invalid_argument("preview: pattern, block and VPL count must be positive");
    const bool newProxy = s.shadowProxyTriangles != settings_.shadowProxyTriangles;
    settings_ = s;
    State& st = *state_;
    if (newProxy && current_) {
        setScene(current_, st.width, st.height);
        return;
    }
    st.seed = st.dealSeed = s.seed;
    if (regenerateVpls && st.scene && !st.customVpls) regenerate(s.seed);
    if (relight) st.lightsDirty = true;
    if (repartition) st.vplsDirty = true;
}

void Preview::update(SceneSnapshot scene, int width, int height) {
    // Lights switched off are left out (so switching one changes the set of lights), the
    // others at their maintained output.
    scene = sceneAsRendered(std::move(scene));
    const State& st = *state_;
    if (current_ && st.scene) {
        const SceneChange change = diff(*current_, *scene);
        const int w = width > 0 ? width : scene->camera.width, h = height > 0 ? height : scene->camera.height;
        // A new site or sky (SPEC.md section 5) is no one light's edit: the scene is set again.
        if (!change.geometry && !change.materials && !change.lightSet && !change.daylight && !change.resolution &&
            w == st.width && h == st.height) {
            if (change.camera) setCamera(scene->camera);
            for (size_t i : change.lights) editLight(i, scene->lights[i], change.emissionOnly);
            current_ = std::move(scene);
            return;
        }
    }
    setScene(std::move(scene), width, height);
}

namespace {

// The preview's form of a scene light: its delta light, or for a sun (drawn as daylight,
// render/preview/daylight_samples.h) a dark placeholder that keeps the lights' indices.
DeltaLight previewDeltaLight(const Light& l, GoniometricSamplers* samplers = nullptr) {
    if (l.type != LightType::Sun) return compileDeltaLight(l, samplers);
    DeltaLight d;
    d.type = LightType::Sun;
    d.position = d.direction = V3f(0, 0, 0);
    d.intensity = Rgb(0, 0, 0);
    return d;
}

// The proxy the VPLs' and area samples' shadow maps draw (shadow_proxy.h): the scene's own
// vertex array when it is small enough.
void uploadShadowProxy(Preview::State& st, const std::vector<float>& positions, int maxTriangles) {
    ShadowProxy proxy = clusterTriangles(positions, size_t(std::max(maxTriangles, 0)));
    if (proxy.cellSize == 0) {
        st.proxyVao = gl::VertexArray();
        st.proxyVertices = gl::Buffer();
        st.proxyCaster = st.sceneCaster;
        return;
    }
    upload(st.proxyVertices, proxy.positions);
    st.proxyVao = gl::makeVertexArray();
    glVertexArrayVertexBuffer(st.proxyVao.id(), 0, st.proxyVertices.id(), 0, 3 * sizeof(float));
    glEnableVertexArrayAttrib(st.proxyVao.id(), 0);
    glVertexArrayAttribFormat(st.proxyVao.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(st.proxyVao.id(), 0, 0);
    // A proxy surface lies within a cell of the true one, mostly much closer (the cell's mean).
    st.proxyCaster = {st.proxyVao.id(), GLsizei(proxy.positions.size() / 3), proxy.cellSize};
}

}  // namespace

void Preview::setScene(SceneSnapshot snapshot, int width, int height) {
    snapshot = sceneAsRendered(std::move(snapshot));
    State& st = *state_;
    current_ = snapshot;
    st.snapshot = snapshot;
    st.scene = std::make_unique<RenderScene>(snapshot, width, height);
    // New geometry: every shadow map must be drawn again, wherever its light or VPL is.
    st.lightShadows.forget();
    st.vplShadows.forget();
    st.dirShadows.forget();
    st.skyShadows.forget();
    st.daylight = resolveDaylight(*snapshot);
    st.camera = snapshot->camera;
    st.width = st.scene->camera().width();
    st.height = st.scene->camera().height();
    st.deltas.clear();
    GoniometricSamplers samplers;
    for (const Light& l : snapshot->lights) st.deltas.push_back(previewDeltaLight(l, &samplers));
    st.customVpls = false;

    // Geometry: non-indexed world-space triangles, per-triangle normal and material; the opaque
    // ones first, then the panes (drawn apart: seen through, casting no shadow).
    const RenderScene& rs = *st.scene;
    std::vector<float> positions;
    std::vector<std::array<float, 4>> tris;
    positions.reserve(rs.triangleCount() * 9);
    for (const bool panes : {false, true}) {
        if (panes) st.opaqueVertexCount = GLsizei(positions.size() / 3);
        for (uint32_t i = 0; i < rs.triangleCount(); ++i) {
            if ((rs.materialOfTriangle(i).type == MaterialType::Glazing) != panes) continue;
            for (const V3f& v : rs.verticesOfTriangle(i)) positions.insert(positions.end(), {v.x, v.y, v.z});
            const V3f n = rs.normalOfTriangle(i);
            // The material id rides in a float: exact for any realistic number of materials.
            const auto mat = uint32_t(&rs.materialOfTriangle(i) - &rs.material(0));
            tris.push_back({n.x, n.y, n.z, float(mat)});
        }
    }
    st.glazing = GLsizei(positions.size() / 3) > st.opaqueVertexCount;
    std::vector<GpuPane> panes;
    for (uint32_t i = 0; i < rs.triangleCount(); ++i) {
        if (rs.materialOfTriangle(i).type != MaterialType::Glazing) continue;
        const std::array<V3f, 3> v = rs.verticesOfTriangle(i);
        GpuPane p{};
        put(p.p0, v[0], 0);
        put(p.e1, v[1] - v[0], 0);
        put(p.e2, v[2] - v[0], 0);
        put(p.transmittance, rs.materialOfTriangle(i).transmittance, 0);
        panes.push_back(p);
    }
    st.vplPaneCount = int(panes.size()) <= kMaxVplPanes ? int(panes.size()) : 0;
    st.paneNote = st.vplPaneCount < int(panes.size())
                      ? "VPL light unattenuated by the " + std::to_string(panes.size()) + " pane triangles (more than " +
                            std::to_string(kMaxVplPanes) + ")"
                      : "";
    std::vector<GpuMaterial> mats;
    st.glossyScene = false;
    for (uint32_t m = 0; m < rs.materialCount(); ++m) {
        const ShadingMaterial& sm = rs.material(m);
        st.glossyScene = st.glossyScene || (sm.type == MaterialType::Glossy && !isBlack(sm.specular));
        GpuMaterial g{};
        // A pane's transmittance where the others keep their albedo (glazing.frag reads it).
        put(g.albedoKind, sm.type == MaterialType::Glazing ? sm.transmittance : sm.albedo,
            materialKind(sm.type));
        put(g.specularAlpha, sm.type == MaterialType::Glossy ? sm.specular : Rgb(0, 0, 0), sm.alpha);
        put(g.radiance, sm.radiance, 0);
        mats.push_back(g);
    }
    {
        EglContext::ScopedCurrent current(*context_);
        upload(st.vertices, positions);
        upload(st.paneTriangles, panes);
        upload(st.triangles, tris);
        upload(st.materials, mats);
        st.vertexCount = GLsizei(positions.size() / 3);
        st.sceneVao = gl::makeVertexArray();
        glVertexArrayVertexBuffer(st.sceneVao.id(), 0, st.vertices.id(), 0, 3 * sizeof(float));
        glEnableVertexArrayAttrib(st.sceneVao.id(), 0);
        glVertexArrayAttribFormat(st.sceneVao.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(st.sceneVao.id(), 0, 0);
        st.sceneCaster = {st.sceneVao.id(), st.opaqueVertexCount, 0.0f, 0};
        st.paneCaster = {st.sceneVao.id(), st.vertexCount - st.opaqueVertexCount, 0.0f, st.opaqueVertexCount};
        positions.resize(size_t(st.opaqueVertexCount) * 3);  // the proxy of what casts shadows
        uploadShadowProxy(st, positions, settings_.shadowProxyTriangles);
    }
    regenerate(settings_.seed);
}

void Preview::setCamera(const Camera& camera) {
    // The resolution stays what setScene chose; which lights each block shades in full is chosen
    // every frame (chooseLightsPerBlock), so nothing else changes.
    state_->camera = camera;
}

namespace {

// now / before per channel, for a light whose emission alone changed (a channel dark in both: 1);
// nothing when a dark channel lights up (its VPLs carry none of that channel to scale).
std::optional<Rgb> emissionRatio(const Rgb& before, const Rgb& now) {
    Rgb ratio(1, 1, 1);
    for (int c = 0; c < 3; ++c) {
        if (before[c] > 0) ratio[c] = now[c] / before[c];
        else if (now[c] != 0) return std::nullopt;
    }
    return ratio;
}

// Each light's share of the VPL budget, in proportion to its power (at least one per
// sub-buffer, so that no sub-buffer misses a light entirely).
int vplShare(double power, double totalPower, int budget, int subsets) {
    if (power <= 0 || totalPower <= 0) return 0;
    return std::max(subsets, int(std::lround(budget * power / totalPower)));
}

// A light sampler over these emitters and delta lights, with the daylight's particles when
// `daylight`: the sky and the sun's disc as the environment light (render/trace/lights/environment_light.h;
// particles leave a disc over the scene facing each direction), a sun without a disc as a
// directional light, as the ray-traced backends have them.
LightSampler previewLightSampler(const Preview::State& st, std::vector<EmitterTriangle> emitters,
                                 std::vector<DeltaLight> deltas, bool daylight) {
    std::optional<EnvironmentLight> environment;
    if (daylight) {
        environment = EnvironmentLight::fromDaylight(st.daylight);
        const auto& sun = st.daylight.sun;
        if (sun && sun->aboveHorizon && !(sun->halfAngleRad > 0)) {
            DeltaLight d;
            d.type = LightType::Directional;
            d.position = V3f(0, 0, 0);
            d.direction = toFloat(-sun->towardSun);
            d.intensity = toFloat(sun->irradiance());
            if (!isBlack(d.intensity)) deltas.push_back(d);
        }
    }
    return LightSampler(std::move(emitters), std::move(deltas), st.scene->metersPerUnit(), st.scene->boundsCenter(),
                        st.scene->boundsRadius(), st.scene->triangleCount(), kDefaultLightSelection,
                        std::move(environment));
}

// Daylight's particles alone.
LightSampler daylightSampler(const Preview::State& st) { return previewLightSampler(st, {}, {}, true); }

// Every light of the scene, daylight's too, chosen by power.
LightSampler allLightsSampler(const Preview::State& st) {
    std::vector<DeltaLight> deltas;
    for (const DeltaLight& d : st.deltas)
        if (d.type != LightType::Sun) deltas.push_back(d);
    return previewLightSampler(st, st.scene->lights().emitters(), std::move(deltas), true);
}

}  // namespace

void Preview::redeal(uint64_t seed) {
    State& st = *state_;
    st.dealSeed = seed;
    st.vplsDirty = st.lightsDirty = true;
}

void Preview::regenerate(uint64_t seed) {
    State& st = *state_;
    st.seed = st.dealSeed = seed;
    if (!st.scene) return;
    if (st.customVpls) {
        st.lightsDirty = true;
        return;
    }
    if (usesMetropolis()) {
        regenerateMir();
        return;
    }
    const int subsets = settings_.patternX * settings_.patternY;
    const int budget = settings_.indirect ? settings_.vplCount : 0;
    size_t sources = (st.scene->lights().emitters().empty() ? 0 : 1) + (st.daylight.sun || st.daylight.sky ? 1 : 0);
    for (const DeltaLight& d : st.deltas) sources += d.type != LightType::Sun;
    st.sets.clear();
    // The VPL budget is the scene's, not the light count's: when every light cannot have a set
    // of at least one VPL per sub-buffer within it, one set serves all lights, its paths
    // starting at lights chosen by power (an edit then regenerates the whole set).
    if (sources * size_t(subsets) > size_t(budget)) {
        LightVpls set;
        set.lightIndex = kAllLights;
        set.count = budget;
        set.vpls = traceVpls(*st.scene, allLightsSampler(st), budget, hashSeed(seed, 0xa11ULL), settings_.maxBounces);
        ++st.generations;
        st.sets.push_back(std::move(set));
        st.vplsDirty = st.lightsDirty = true;
        return;
    }
    std::vector<LightSampler> samplers;
    std::vector<int> indices;
    if (!st.scene->lights().emitters().empty()) {
        samplers.push_back(singleLightSampler(*st.scene, nullptr));
        indices.push_back(-1);
    }
    for (size_t i = 0; i < st.deltas.size(); ++i) {
        if (st.deltas[i].type == LightType::Sun) continue;  // with daylight
        samplers.push_back(singleLightSampler(*st.scene, &st.deltas[i]));
        indices.push_back(int(i));
    }
    if (st.daylight.sun || st.daylight.sky) {
        samplers.push_back(daylightSampler(st));
        indices.push_back(kDaylightSet);
    }
    double total = 0;
    for (const LightSampler& s : samplers) total += s.totalPower();
    for (size_t i = 0; i < samplers.size(); ++i) {
        LightVpls set;
        set.lightIndex = indices[i];
        set.count = vplShare(samplers[i].totalPower(), total, budget, subsets);
        set.vpls = traceVpls(*st.scene, samplers[i], set.count, hashSeed(seed, uint64_t(set.lightIndex + 2)),
                             settings_.maxBounces);
        ++st.generations;
        st.sets.push_back(std::move(set));
    }
    st.vplsDirty = st.lightsDirty = true;
}

void Preview::setLight(size_t index, const Light& light) {
    if (index >= state_->deltas.size()) throw std::out_of_range("preview: no light " + std::to_string(index));
    auto edited = std::make_shared<Scene>(*current_);
    edited->lights[index] = light;
    const bool emissionOnly = diff(*current_, *edited).emissionOnly;
    current_ = std::move(edited);
    editLight(index, light, emissionOnly);
}

void Preview::editLight(size_t index, const Light& light, bool emissionOnly) {
    State& st = *state_;
    const DeltaLight previous = st.deltas[index];
    st.deltas[index] = previewDeltaLight(light);
    st.lightsDirty = true;
    if (previous.type == LightType::Sun || light.type == LightType::Sun) {
        // The sun shapes the sky too (cie_general, the ground's luminance): daylight resolved
        // again with the edited sun (a scene holds at most one), and every set drawn anew.
        Scene sky;
        sky.site = st.snapshot->site;
        sky.sky = st.snapshot->sky;
        if (light.type == LightType::Sun) sky.lights.push_back(light);
        st.daylight = resolveDaylight(sky);
        regenerate(st.seed);
        return;
    }
    if (st.customVpls) return;
    if (usesMetropolis()) {
        regenerateMir();  // MIR's VPLs serve every light at once
        return;
    }
    if (st.sets.size() == 1 && st.sets[0].lightIndex == kAllLights) {
        regenerate(st.seed);  // one set serves every light
        return;
    }
    // Only its emission changed (dimmed, recoloured): its VPLs' power is linear in the light's,
    // channel by channel, so they are scaled (still an unbiased set), keep their places and
    // need no shadow map drawn again.
    const std::optional<Rgb> ratio =
        emissionOnly ? emissionRatio(previous.intensity, st.deltas[index].intensity) : std::nullopt;
    if (ratio) {
        for (LightVpls& set : st.sets)
            if (set.lightIndex == int(index))
                for (Vpl& v : set.vpls) v.power *= *ratio;
        st.vplsDirty = true;
        return;
    }
    const LightSampler sampler = singleLightSampler(*st.scene, &st.deltas[index]);
    double total = 0;
    for (const LightVpls& s : st.sets)
        total += s.lightIndex == -1            ? singleLightSampler(*st.scene, nullptr).totalPower()
                 : s.lightIndex == kDaylightSet ? daylightSampler(st).totalPower()
                                                : singleLightSampler(*st.scene, &st.deltas[size_t(s.lightIndex)]).totalPower();
    for (LightVpls& set : st.sets) {
        if (set.lightIndex != int(index)) continue;
        set.count = vplShare(sampler.totalPower(), total, settings_.indirect ? settings_.vplCount : 0,
                             settings_.patternX * settings_.patternY);
        set.vpls = traceVpls(*st.scene, sampler, set.count, hashSeed(st.seed, uint64_t(index + 2)), settings_.maxBounces);
        ++st.generations;
    }
    st.vplsDirty = true;
}

bool Preview::usesMetropolis() const {
    const State& st = *state_;
    return settings_.vplSource == VplSource::Metropolis ||
           (settings_.metropolisUnderDaylight && (st.daylight.sun || st.daylight.sky));
}

void Preview::regenerateMir() {
    State& st = *state_;
    const LightSampler all = allLightsSampler(st);
    MirVplSettings mir;
    mir.pathVpls = settings_.indirect ? settings_.vplCount : 0;
    mir.clampFraction = settings_.clampDistance;
    mir.chain.vpl.maxBounces = settings_.maxBounces;
    LightVpls set;
    set.lightIndex = -3;
    set.vpls = generateMirVpls(*st.scene, all, st.camera, st.width, st.height, mir, hashSeed(st.seed, 0x4d4952ULL));
    set.count = int(set.vpls.size());
    ++st.generations;
    st.sets.clear();
    st.sets.push_back(std::move(set));
    st.vplsDirty = st.lightsDirty = true;
}

void Preview::setVpls(VplSet vpls) {
    State& st = *state_;
    st.customVpls = true;
    st.sets.clear();
    LightVpls set;
    set.lightIndex = -2;
    set.count = int(vpls.size());
    set.vpls = std::move(vpls);
    st.sets.push_back(std::move(set));
    st.vplsDirty = true;
}

double Preview::freshSetShadowTriangles() const {
    const State& st = *state_;
    const double cubes = double(st.uploadedVplCount) + double(st.areaLightCount);
    // The sky's maps and the sun's (whose direction moves within the disc) draw the scene.
    const double maps = double(st.skyLightCount) + (st.daylight.sun ? 1.0 : 0.0);
    return 6.0 * cubes * double(st.proxyCaster.vertexCount / 3) + maps * double(st.sceneCaster.vertexCount / 3);
}

Rgb Preview::sunDiscIrradiance(const V3f& point, const V3f& normal) const {
    const State& st = *state_;
    if (!st.scene || !st.daylight.sun || !(st.daylight.sun->halfAngleRad > 0)) return Rgb(0, 0, 0);
    // The same direction as the sun's shadow map of this set (direct_lights.cpp).
    const auto sun = sunSample(*st.daylight.sun, hashSeed(st.seed, 0x5a11ULL));
    if (!sun) return Rgb(0, 0, 0);
    const float cosine = normal.dot(sun->toward);
    if (cosine <= 0.0f) return Rgb(0, 0, 0);
    const Ray ray{point + normal * (st.scene->boundsRadius() * 1e-5f), sun->toward};
    return sun->irradiance * st.scene->transmittance(ray) * cosine;
}

VplSet Preview::vpls() const {
    VplSet all;
    for (const LightVpls& s : state_->sets) all.insert(all.end(), s.vpls.begin(), s.vpls.end());
    return all;
}

}  // namespace lucerna
