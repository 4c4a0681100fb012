#pragma once
// A vertex of a bidirectional subpath and the densities that the multiple importance sampling
// weights need (Veach 1997, section 10.2; pbrt-v3 section 16.3).
//
// Every density here is per unit AREA at the vertex it generates (per unit solid angle times
// |cos| / d^2), except at vertices that are not on a surface (the pinhole, point and spot
// lights), where the cosine is left out. A path's density for strategy (s, t) is the product of
// the light subpath's pdfFwd over its first s vertices and the camera subpath's pdfFwd over its
// first t; the MIS weights only ever need ratios pdfRev / pdfFwd of one vertex (eq. 10.9).

#include "render/trace/render_scene.h"

namespace lucerna {

enum class VertexKind : uint8_t {
    Camera,            // the pinhole (delta position)
    Surface,           // a scattering point, or an emitter hit by a camera subpath (s = 0)
    AreaLight,         // a point on an emissive triangle where a light subpath starts
    PointLight,        // delta position
    SpotLight,         // delta position
    Luminaire,         // delta position, a goniometric distribution
    DirectionalLight,  // delta direction; `sp.p` is a point on the disk the particles start from
    // Daylight at infinity (pbrt-v3's infinite lights): `sp.ng` is the direction the light
    // travels, `sp.p` a point far up the beam (a camera subpath that left the scene, a
    // next-event sample) or on the disk particles start from. Densities toward it stay per
    // unit solid angle; its origin density is the direction's.
    EnvironmentLight,
};

struct PathVertex {
    VertexKind kind = VertexKind::Surface;
    SurfacePoint sp;       // position, its error bound and the front normal (lights: the emitter's)
    V3f wo{0, 0, 0};       // Surface: unit direction toward the previous vertex of its own subpath
    Rgb beta{0, 0, 0};     // subpath throughput up to this vertex (Veach's alpha_i, eq. 10.3/10.4)
    float pdfFwd = 0;      // area density of this vertex generated from its predecessor
    float pdfRev = 0;      // area density of this vertex generated from its successor (other direction)
    bool delta = false;    // scattered here by a delta BSDF (mirror, glass): cannot be connected
    uint32_t light = 0;    // lights: LightSample::light numbering; the camera: its sensor point

    const V3f& p() const { return sp.p; }
    bool onSurface() const { return kind == VertexKind::Surface || kind == VertexKind::AreaLight; }
    bool atInfinity() const { return kind == VertexKind::EnvironmentLight; }
    bool isDeltaLight() const {
        return kind == VertexKind::PointLight || kind == VertexKind::SpotLight || kind == VertexKind::Luminaire ||
               kind == VertexKind::DirectionalLight;
    }
};

// The densities of one scene: the camera's importance sampling, the lights' emission sampling and
// the BSDFs, each as the area density of the next vertex.
class VertexDensities {
public:
    explicit VertexDensities(const RenderScene& scene);

    // pbrt's ConvertDensity: a solid-angle density at `from` toward `to` made an area density at `to`.
    static float toArea(float pdfSolidAngle, const PathVertex& from, const PathVertex& to);

    // Density with which `v` generates `next` when it was reached from `prev` (nullptr at the
    // camera and at lights): the camera's directional pdf, the BSDF's, or the light's emission.
    float pdf(const PathVertex& v, const PathVertex* prev, const PathVertex& next) const;
    // Emission density of light vertex `v` (a light, or an emitter hit by a camera subpath)
    // toward `next`, per unit area at `next`. Without the light selection (it cancels).
    float pdfLight(const PathVertex& v, const PathVertex& next) const;
    // Density of choosing light vertex `v` as the start of a light subpath (selection times
    // position, per unit area); the same for next-event estimation. 0 for delta lights (it is
    // never compared: their strategy s = 0 does not exist). For the environment, the density of
    // its direction as next-event estimation at `next` (its neighbour on the path) draws it, the
    // windows' portals included; every strategy uses that one, so the weights still sum to one.
    float pdfLightOrigin(const PathVertex& v, const PathVertex* next = nullptr) const;

    // Solid-angle density of the camera rays of sensor point `point` (pbrt's Pdf_We; the
    // pinhole's is 1 / (A cos^3 theta) for all the image together, A the image plane's area at
    // distance 1; an irradiance sensor's is cos theta / pi; sensor.h). 0 where no ray goes.
    float cameraPdfDirection(int point, const V3f& dir) const { return scene_.camera().pdfDirection(point, dir); }
    // The importance times cos theta, We cos, equal to that density: a light-tracing
    // contribution arriving along -dir weighs this much per unit of radiance and solid angle,
    // for an image whose pixels each receive one light subpath per pass (with several sensor
    // points, the one it joins is chosen uniformly, and the choice's 1 / n cancels against the
    // n blocks of the image).
    float cameraImportance(int point, const V3f& dir) const { return cameraPdfDirection(point, dir); }

    // f(wo, wi) of a Surface vertex toward unit direction `wi` (two-sided frame flipped toward
    // the vertex's own wo, glass keeping its front side as the path tracer does).
    Rgb bsdf(const PathVertex& v, const V3f& wi) const;
    // Emitted radiance (area) or intensity in scene units (delta lights, meters_per_unit folded
    // in as in EmissionSample) of light vertex `v` toward unit direction w.
    Rgb emitted(const PathVertex& v, const V3f& w) const;

    const RenderScene& scene() const { return scene_; }

private:
    float bsdfPdf(const PathVertex& v, const V3f& wFrom, const V3f& wTo) const;

    const RenderScene& scene_;
};

}  // namespace lucerna
