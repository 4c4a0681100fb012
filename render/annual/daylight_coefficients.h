#pragma once
// Daylight coefficients (Tregenza and Waters 1983; Radiance's rcontrib): each point's response to
// each patch of the sky, traced once, so that any hour's sky is a dot product. The response to
// the sun is split as Radiance's 5-phase method splits it, because sunlit areas and ASE depend on
// the sun's disc, not on a patch:
//   - the sky and the ground seen straight from the point: by quadrature, one ray through each
//     of 4 x 4 cells of each patch (and the same cells mirrored below the horizon for the
//     ground), its solid angle times the cosine times what the panes let through: no noise, and
//     an open plane gets the patches' horizontal illuminance;
//   - the sky and the ground after reflections: paths traced backward from the point
//     (cosine-weighted, through glazing, every BSDF, Russian roulette), each one's throughput
//     binned by the patch of the direction it leaves the scene in (one bin for the ground) when
//     it left after at least one reflection;
//   - the sun after one or more reflections: at every non-specular vertex of `sunPaths` paths of
//     their own, next-event estimation toward each node of a grid of the sun's possible positions
//     (SunPathGrid), later interpolated at each hour's sun;
//   - the sun straight onto the point is not here: the annual calculation traces it per hour
//     (annual_calculation.h).
// All values are luminance (photometric Y) responses: E in lx per cd/m^2 of a patch's luminance
// (the sky is white), and E in lx per lx of the sun's direct normal illuminance.
//
// The error: the paths are dealt into `batches` independent groups (path index modulo batches),
// each with its own coarse (Tregenza, 145 + 1 bins) sky coefficients and sun-node coefficients,
// so that any hour's value has a batch-means standard error.

#include "core/daylight/sky_patches.h"
#include "core/daylight/sun_path_grid.h"
#include "render/trace/render_scene.h"
#include "render/trace/rng.h"

#include <cstdint>
#include <vector>

namespace lucerna {

struct DaylightCoefficientSettings {
    int skySubdivision = 4;   // Reinhart's MF: 2,305 patches
    int paths = 32768;        // per point, for the sky and ground after reflections
    int sunPaths = 512;       // per point, of their own, for the sun's reflections
    int batches = 8;          // for the error bars
    uint64_t seed = 1;
};

// One point's coefficients; a point inside geometry keeps them all 0.
struct PointCoefficients {
    std::vector<float> sky;                // SkyPatches(m).count() patches, then the ground
    std::vector<float> coarseSky;          // batches x (145 + 1): each batch's own, in Tregenza's patches
    std::vector<float> sunIndirect;        // per SunPathGrid node
    std::vector<float> sunIndirectBatches; // batches x nodes
};

// For points chosen to measure the discretisation: what the paths met, unbinned, so that an
// hour's sky can also be summed direction by direction and the sun traced at its own position.
struct PathRecords {
    struct Escape {
        V3f direction;
        float weight;  // lx per cd/m^2 arriving along it
    };
    struct SunVertex {
        SurfacePoint point;
        uint32_t material;
        Frame frame;
        V3f woLocal;
        Rgb throughput;  // pi / sunPaths times the path's throughput up to the vertex
    };
    std::vector<Escape> escapes;      // after reflections
    std::vector<SunVertex> sunVertices;
    std::vector<float> direct;        // the quadrature's coefficients alone, per bin
    std::vector<Escape> directCells;  // a quadrature twice as fine per side, cell by cell
};

class DaylightCoefficientTracer {
public:
    DaylightCoefficientTracer(const RenderScene& scene, const SkyPatches& patches, const SkyPatches& coarse,
                              const SunPathGrid& sun, const DaylightCoefficientSettings& settings);

    // The coefficients of the point at `position` facing `normal` (unit; the sensor already lifted
    // off any surface it lies on); `records`, if given, receives what the paths met.
    PointCoefficients trace(const V3f& position, const V3f& normal, uint64_t pointIndex, PathRecords* records = nullptr) const;

    // lx per lx of direct normal illuminance that the sun toward `towardSun` gives at the
    // recorded vertices (the sun's indirect light at its exact position, for the discretisation).
    float sunIndirectAt(const PathRecords& records, const V3f& towardSun) const;

private:
    // The straight view of the sky and ground through cells `side` x `side` per patch:
    // onCell(bin, direction, solid angle x cosine x transmittance's luminance).
    template <class OnCell>
    void directView(const V3f& position, const V3f& normal, int side, const OnCell& onCell) const;
    // One path from ray: onEscape(direction, luminance of the throughput, depth) where it leaves
    // the scene, onVertex(vertex with the throughput up to it) at each non-specular vertex.
    template <class OnEscape, class OnVertex>
    void tracePath(Ray ray, Rng& rng, const OnEscape& onEscape, const OnVertex& onVertex) const;
    // Next-event estimate toward the sun along `towardSun` at one vertex: luminance response.
    float sunResponse(const PathRecords::SunVertex& v, const V3f& towardSun) const;

    const RenderScene& scene_;
    const SkyPatches& patches_;
    const SkyPatches& coarse_;
    const SunPathGrid& sun_;
    DaylightCoefficientSettings settings_;
    std::vector<int> upperNodes_;  // the sun nodes above the horizon
};

}  // namespace lucerna
