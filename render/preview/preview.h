#pragma once
// The interactive preview (seed 002, slides 80 to 95; DESIGN.md "Interleaved sampling with
// deferred shading"): OpenGL 4.5 core through its own EGL context, a G-buffer drawn once per
// frame, split into n x m sub-buffers (in one pass or two), each sub-buffer shaded with its own
// subset of the VPLs (and of the area-light samples) in one pass (a draw per sub-buffer, none
// per VPL), gathered, blurred over continuous regions, and blended with direct light from
// shadow-mapped lights. VPLs come from instant radiosity (per light) or Metropolis instant
// radiosity (PreviewSettings::vplSource).
// One object serves the GUI and the command line.
//
// Threading: the object may be used from any one thread at a time; each call makes the context
// current and releases it, so task threads can take turns.

#include "core/image/image.h"
#include "core/scene/scene.h"
#include "render/preview/egl_context.h"
#include "render/vpl/vpl.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace lucerna {

// Where the indirect VPLs come from: instant radiosity light paths (per light, so that a light
// edit regenerates only its set), or Metropolis instant radiosity (mir_vpl_source.h: VPLs
// where they light what the camera sees; one set for all lights).
enum class VplSource { InstantRadiosity, Metropolis };

// How the G-buffer reaches the interleaved sub-buffers: by a split pass in two passes (blocks,
// then translation: the thesis, for a GPU's texture cache), in one pass, or fused into the VPL
// shading pass (each fragment reads its texel of the image-layout G-buffer; no split pass).
enum class SplitMode { TwoPass, OnePass, Fused };

struct PreviewSettings {
    int vplCount = 256;            // indirect VPLs over all lights (MIR: chain steps, at most this many)
    VplSource vplSource = VplSource::InstantRadiosity;
    // Under daylight the VPLs come from MIR whatever vplSource says: the sky's and the sun's
    // particles land mostly on the building's outside, which leaves a room lit through its
    // windows a few dozen of its 256 instant-radiosity VPLs, whose spots (squares, interleaved)
    // still showed along the daylit office's ceiling and corners after 64 frames; MIR puts them
    // where the camera looks (relmse 0.041 against 0.048 at 64 frames, the same cost).
    bool metropolisUnderDaylight = true;
    int patternX = 4, patternY = 4;  // interleaving n x m (1 x 1: no interleaving)
    // The VPL geometric term is clamped as geometricClampBound (render/vpl/vpl_contribution.h):
    // at 1 / (this fraction of the scene's bounding radius)^2; 0: no clamping. It removes the
    // bright spots near VPLs and loses some energy.
    float clampDistance = 0.05f;
    // VPL visibility by low-resolution cube shadow maps per VPL; off is the thesis' fast mode. On
    // by default: on llvmpipe it measured 4% of a 256-VPL 4x4 frame (plus the maps, redrawn only
    // when lights or VPLs change) for a third of the error (docs/benchmarks-history.md, issue 5,
    // "VPL visibility: cost").
    bool visibility = true;
    int vplShadowSize = 32;        // per cube face
    bool blur = true;              // the n x m box blur over continuous regions
    // Fused by default: on llvmpipe one pass measured twice as fast as two, and fused faster
    // than one (BENCHMARKS.md, "Interactive preview (issue 5)"); the two passes win on GPUs (the
    // thesis).
    SplitMode split = SplitMode::Fused;
    int splitBlock = 8;            // B of the two-pass split
    // The VPL shading pass unrolls its loop over a sub-buffer's VPLs, read at constant indices
    // from a uniform block, when no sub-buffer has more than this many (shade_vpl.frag); 0: never.
    // 16 by measurement on llvmpipe (docs/benchmarks-history.md, issue 5, "Session 5"): unrolled,
    // 16 VPLs a sub-buffer (256 at 4x4) shaded 4 to 27% faster; 22 and 64 (1024 at 8x6 and 4x4)
    // 10% slower.
    int maxUnrolledVpls = 16;
    bool direct = true, indirect = true;
    // Point samples (shadow-mapped) standing for the emissive triangles' direct light. With
    // interleaving they are rounded up to a multiple of n m and dealt to the sub-buffers like
    // VPLs ("area lights as VPLs of their own"): each pixel evaluates n m times fewer, and the
    // box blur over continuous regions averages them back.
    int areaLightSamples = 16;
    int shadowSize = 256;          // direct lights' cube shadow maps, per face (smaller for many lights)
    // Point, spot and luminaire lights shaded at every pixel; with more, these are the ones
    // nearest the camera for their power, and the rest are dealt to the interleaved sub-buffers
    // like the area samples, so that a pixel evaluates n m times fewer of them and the blur
    // restores the rest (BENCHMARKS.md, "The preview on real scenes (issue 20)").
    int lightsShadedInFull = 8;
    // The VPLs' and area samples' shadow maps, drawn again for every fresh set, draw a clustered
    // proxy of the scene of at most this many triangles (shadow_proxy.h); 0: the scene itself.
    // 2048 made the closed sphere's sets 4 times cheaper but lost the desks and partitions of a
    // 7,500-triangle hall (+6% of light leaked through them; BENCHMARKS.md,
    // "The preview on real scenes (issue 20)").
    int shadowProxyTriangles = 8192;
    // Daylight (SPEC.md section 5): the sky and the ground as this many directional lights, drawn
    // in proportion to their luminance anew for every fresh set (render/preview/daylight_samples.h),
    // each with an orthographic shadow map of skyShadowSize^2 texels over the scene; with
    // interleaving they are rounded up to a multiple of n m and dealt to the sub-buffers like the
    // area samples. The sun is one directional light with a map of (4 shadowSize)^2.
    // 256: llvmpipe's shading pass fetched from 64 maps of 512^2 at twice the cost (memory-bound,
    // 100 against 56 ms for the daylit office at 400x267) and drew them at twice the cost; the
    // sky's light is soft, and each map's edges are looked up by the receiver's plane.
    int skySamples = 64;
    int skyShadowSize = 256;
    // Surface interactions a VPL particle may have. Russian roulette ends particles long before
    // (as in the ir backend); a low cap would cut the long paths that closed bright rooms live
    // on (at albedo 0.8, 8 bounces lose 13% of the light).
    int maxBounces = 1024;
    uint64_t seed = 1;
};

// Milliseconds of the last render(), per pass (glFinish between passes, so they add up).
struct PreviewTimings {
    // gather: the gather with the horizontal half of the blur; direct: the vertical half, the
    // direct light and the blend; lightBlocks: each block's choice of the lights it shades in
    // full (with many delta lights only).
    double shadows = 0, gbuffer = 0, lightBlocks = 0, split = 0, shading = 0, gather = 0, direct = 0, readback = 0;
    double total = 0;  // the whole render() call
    int shadowCubes = 0;  // cube shadow maps drawn (only those of lights and VPLs that moved)
    int directionalMaps = 0;  // orthographic maps drawn (directional lights, the sun, the sky's directions)
};

class Preview {
public:
    // The folder holding resources/shaders/preview. Throws std::runtime_error when EGL cannot
    // give an OpenGL 4.5 core context or a shader does not compile.
    explicit Preview(std::string shaderDir = defaultShaderDirectory());
    ~Preview();
    Preview(const Preview&) = delete;
    Preview& operator=(const Preview&) = delete;

    static std::string defaultShaderDirectory();
    const EglContext& context() const { return *context_; }

    // Regenerates VPLs only when what they depend on changes (count, seed, bounces).
    void setSettings(const PreviewSettings& settings);
    const PreviewSettings& settings() const { return settings_; }

    // Takes a new scene: geometry, materials, lights; generates every light's VPLs.
    // width/height override the camera's resolution (0: keep).
    void setScene(SceneSnapshot scene, int width = 0, int height = 0);
    // Takes the newest version of the scene and redraws only what changed since the one before
    // (core/scene/scene_change.h): the camera, the lights that differ (as setLight; when the
    // scenes differ in emission alone, those lights keep their VPLs, scaled), or everything
    // (setScene) when geometry, materials, the number of lights, the site or sky, or the size
    // changed. width/height as for setScene.
    void update(SceneSnapshot scene, int width = 0, int height = 0);
    // A camera move: no VPL is regenerated (MIR's camera-dependent VPLs follow at regenerate()).
    void setCamera(const Camera& camera);
    // Light `index` of the scene changed (same type of edit as the GUI's): only its VPLs and its
    // shadow map are regenerated; when its emission alone changed (core/scene/scene_change.h),
    // its VPLs are kept, scaled. Throws std::out_of_range for no such light.
    void setLight(size_t index, const Light& light);
    // New VPL sets and area-light samples for every light from this seed (progressive passes).
    void regenerate(uint64_t seed);
    // The same VPLs and area samples dealt anew to the sub-buffers (and a new random subset of
    // the far lights): a frame with a fresh interleaving pattern that draws no shadow map.
    // Averaged, such frames converge to the non-interleaved image of the current VPL set.
    void redeal(uint64_t seed);
    // Replaces the generated VPLs with exactly these (tests, and MIR's VPLs): one set, split
    // among the sub-buffers as the generated ones are.
    void setVpls(VplSet vpls);
    // Triangles a fresh set's shadow maps draw (cube faces of the VPLs and area samples times
    // the triangles of what they draw): what makes regenerate() cost more than redeal(), known
    // from the scene and settings alone, so that callers can choose between them the same way
    // on any machine.
    double freshSetShadowTriangles() const;
    // Every VPL in use, all lights' sets together, with the power each set gave it.
    VplSet vpls() const;
    // How many per-light VPL sets have been generated so far (tests check what a change redoes).
    int vplSetGenerations() const;

    // Renders a frame with the pixel sample at (x + jitterX, y + jitterY): linear RGB radiance,
    // SPEC.md conventions (converges to the box filter when passes jitter uniformly). With the
    // albedo layer on, also the albedo of the surface under each pixel as channels albedo.R/G/B
    // (0 where it is not diffuse or glossy), read back from the G-buffer.
    Image render(float jitterX = 0.5f, float jitterY = 0.5f);
    // Off by default: on llvmpipe the two extra read-backs cost ~35 ms at 640x480, a third of
    // a frame, so only the lux view asks for them.
    void setAlbedoLayer(bool on) { albedoLayer_ = on; }
    // With white receivers on, render() gives what white Lambertian surfaces (albedo 1) in place
    // of every diffuse and glossy one would reflect under the same direct light and VPLs: E / pi,
    // the irradiance over pi (0 on emitters, mirrors, glass and the background). The VPLs keep
    // the scene's own materials. For the illuminance layer (preview_illuminance.h).
    void setWhiteReceivers(bool on) { whiteReceivers_ = on; }
    // Whether pixels that see no surface show the sun's disc (on by default). Hemicubes of small
    // faces (hemicube_irradiance.h) would catch a disc a fraction of a pixel wide only now and
    // then, all their points alike: they take its light from sunDiscIrradiance instead.
    void setSunDiscShown(bool shown) { sunDiscShown_ = shown; }
    // The irradiance (W/m^2 per channel) of a sun with a disc at `point` on a surface of unit
    // `normal`: from the direction the current fresh set draws within the disc, through panes
    // times their transmittance, 0 behind anything opaque (a ray traced). 0 without such a sun,
    // or for a sun of diameter 0 (a directional light of the render scene's, as calculation
    // grids already sum).
    Rgb sunDiscIrradiance(const V3f& point, const V3f& normal) const;
    const PreviewTimings& timings() const;
    // What the preview gave up on this scene to stay within the GPU's limits (fewer shadowed
    // VPLs, smaller or shared shadow maps, pooled VPLs), in one line for a status bar or stderr;
    // empty when nothing was given up. Known after render().
    const std::string& degradation() const;

    // Tests: uploads `in` as a G-buffer attachment, splits it with the current settings (the
    // fused split as one pass: the same addressing) and gathers it back. `split` is the split
    // layout, `gathered` should equal `in`.
    struct SplitCheck {
        Image split, gathered;
        int subWidth = 0, subHeight = 0;  // a tile's size in the split layout
    };
    SplitCheck splitAndGather(const Image& in);

    // The GL objects and CPU-side scene data; opaque (defined in gpu_state.h) and public
    // only so that the passes' free functions can take it.
    struct State;

    // Whether the VPLs come from MIR: asked for, or under daylight (metropolisUnderDaylight).
    bool usesMetropolis() const;

private:
    void regenerateMir();
    // setLight's work, with what the scene diff says of the edit.
    void editLight(size_t index, const Light& light, bool emissionOnly);

    std::unique_ptr<EglContext> context_;
    std::unique_ptr<State> state_;
    SceneSnapshot current_;  // the scene as of the last setScene(), update() or setLight()
    PreviewSettings settings_;
    bool albedoLayer_ = false;
    bool whiteReceivers_ = false;
    bool sunDiscShown_ = true;
};

}  // namespace lucerna
