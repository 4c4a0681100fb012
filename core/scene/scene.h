#pragma once
// The scene of SPEC.md section 1 as plain values: what the file says, kept faithfully so that
// save(load(file)) loses nothing, plus the resolved world-space triangle meshes that backends use.

#include "core/photometry/calculation_grid.h"
#include "core/photometry/lighting_energy.h"
#include "core/math.h"
#include "core/photometry/photometric_units.h"
#include "core/photometry/standard_edition.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lucerna {

struct Camera {
    V3d position{0, 0, 0};
    V3d target{0, 0, -1};
    V3d up{0, 1, 0};
    double fovYDeg = 45;   // full vertical field of view, degrees
    int width = 512;       // pixels
    int height = 512;

    bool operator==(const Camera&) const = default;
};

// Glazing (SPEC.md section 5): a thin pane that light crosses straight, scaled by its
// transmittance; no ray ever scatters on it.
enum class MaterialType { Diffuse, Glossy, Mirror, Dielectric, Emitter, Glazing };

struct Material {
    std::string name;
    MaterialType type = MaterialType::Diffuse;
    Rgbd albedo{0, 0, 0};       // diffuse, glossy: Lambertian part, each channel in [0, 1]
    Rgbd specular{0, 0, 0};     // glossy: GGX lobe weight, in [0, 1]
    double roughness = 0.5;     // glossy: GGX alpha, in (0, 1]
    Rgbd reflectance{0, 0, 0};  // mirror
    double ior = 1.5;           // dielectric
    Rgbd radiance{0, 0, 0};     // emitter, W sr^-1 m^-2, front face only
    Rgbd transmittance{1, 1, 1};// glazing, each channel in [0, 1], at every angle

    bool operator==(const Material&) const = default;
};

// SPEC: scale (number or triple), then rotate (axis, degrees), then translate; or a row-major
// matrix for column vectors.
struct Transform {
    bool isMatrix = false;
    V3d scale{1, 1, 1};
    bool uniformScale = true;  // written back as a number rather than a triple
    V3d rotateAxis{0, 1, 0};
    double rotateDeg = 0;
    bool hasRotate = false;
    V3d translate{0, 0, 0};
    M44d matrix;  // row-major as in the file: matrix[i][j] is row i, column j; p' = M p

    // The 4x4 matrix (row-major, column vectors) this transform applies.
    M44d toMatrix() const;
    bool operator==(const Transform&) const = default;
};

struct TriangleMesh {
    std::vector<V3d> vertices;
    std::vector<V3i> triangles;
    bool operator==(const TriangleMesh&) const = default;
};

struct MeshSource {
    enum class Kind { Inline, Quad, File };
    Kind kind = Kind::Inline;
    TriangleMesh inlineMesh;   // Inline
    // Imath vectors are not zeroed by default construction, so spell the zeros out: equality
    // compares this array for every kind of mesh.
    std::array<V3d, 4> quad{V3d(0), V3d(0), V3d(0), V3d(0)}; // Quad
    std::string file;          // File, as written (relative to the scene's folder)

    bool operator==(const MeshSource&) const = default;
};

struct Object {
    std::string name;
    std::string material;  // key into Scene::materials
    MeshSource mesh;
    std::optional<Transform> transform;
    // An addition (README, "Rooms"): the room this object is a surface of (a key of
    // Scene::rooms); empty: none.
    std::string room;
    // An addition (README, "Daylight portals"): an opening, not a surface. Rays pass through it
    // untouched and daylight particles and the sky's next-event samples are sent through it,
    // like an unglazed door of a drawn room; its material is not used.
    bool portal = false;

    // World-space triangles after the transform, degenerate triangles dropped. Filled by the
    // loader (resolveMeshes); shared between scene copies, never mutated once set.
    std::shared_ptr<const TriangleMesh> worldMesh;

    // Equality compares what the file says, not the cache.
    bool operator==(const Object& o) const {
        return name == o.name && material == o.material && mesh == o.mesh && transform == o.transform &&
               room == o.room && portal == o.portal;
    }
};

// Sun: SPEC.md section 5, a disc of uniform radiance at infinity (a delta light when its
// angular diameter is 0), placed by `direction` or by the site's local `time`.
enum class LightType { Point, Spot, Directional, Luminaire, Sun };

struct GoniometricDistribution;

// A goniometric luminaire's keys (README, "Luminaires"): the photometric file and how its
// output is scaled and coloured. The light's `direction` is its nadir.
struct LuminaireSpec {
    std::string file;                    // IES or EULUMDAT, as written (relative to the scene's folder)
    std::optional<double> rotationDeg;   // about the nadir, degrees (absent: 0)
    std::optional<double> lumens;        // rescale the distribution to this total flux
    std::optional<Rgbd> colour;          // normalised to luminance 1; white by default
    std::optional<double> temperatureK;  // a blackbody's colour instead
    // An addition (README, "Glare"): the luminous area [width along C90-C270, length along
    // C0-C180] in metres, flat and facing the nadir; overrides the file's luminous opening.
    std::optional<V2d> luminousAreaM;

    // The file's distribution, read by the loader (resolveMeshes); shared between scene copies,
    // never mutated once set. Null until then (the light is then dark).
    std::shared_ptr<const GoniometricDistribution> distribution;

    // Equality compares what the scene file says, not the loaded distribution.
    bool operator==(const LuminaireSpec& o) const {
        return file == o.file && rotationDeg == o.rotationDeg && lumens == o.lumens && colour == o.colour &&
               temperatureK == o.temperatureK && luminousAreaM == o.luminousAreaM;
    }
};

// A maintenance factor (CIE 97:2005; an addition to the format, README "Maintained values"):
// one number, or the product of its four factors, LLMF x LSF x LMF x RSMF, those absent
// counting 1. Each in (0, 1].
struct MaintenanceFactor {
    std::optional<double> value;  // the one number
    std::optional<double> lampLumenMaintenance, lampSurvival, luminaireMaintenance, roomSurfaceMaintenance;

    double factor() const;
    bool operator==(const MaintenanceFactor&) const = default;
};

// A sun's keys (SPEC.md section 5). Its direction is Light::direction unless `time` is given.
struct SunSpec {
    double illuminanceLux = 0;        // direct normal illuminance
    double angularDiameterDeg = 0.53; // in [0, 5]; 0: a delta light
    bool angularDiameterGiven = false;// written back only if it was there
    std::optional<std::string> time;  // "YYYY-MM-DDTHH:MM", local time at the site's utc_offset
    std::optional<Rgbd> colour;       // normalised to luminance 1; white by default
    // False only beside a perez sky (SPEC.md section 6) or a sky whose levels follow the sun's
    // altitude (Sky::levels), whose model gives the illuminance.
    bool illuminanceGiven = true;

    bool operator==(const SunSpec&) const = default;
};

struct Light {
    std::string name;
    LightType type = LightType::Point;
    V3d position{0, 0, 0};   // point, spot
    V3d direction{0, -1, 0}; // spot: axis; directional: the direction light travels (as written)
    Rgbd intensity{0, 0, 0}; // point, spot: W/sr (on axis for a spot)
    Rgbd irradiance{0, 0, 0};// directional: W/m^2 on a surface facing it
    double coneAngleDeg = 45;         // spot: half-angle, degrees
    std::optional<double> falloffStartDeg;  // spot: half-angle, degrees; absent = hard edge
    // Point, spot: given in lumens or candela instead of `intensity` (README); `intensity` then
    // holds the converted value, and the file is written back as it was given while the two agree.
    std::optional<PhotometricSpec> photometric;
    // Luminaire only (type Luminaire; position, and direction = the nadir, as for a spot).
    std::optional<LuminaireSpec> luminaire;
    // Sun only (type Sun); `direction` is the direction its light travels when sun->time is absent.
    std::optional<SunSpec> sun;
    // Additions to the format (README, "Light groups"): the group the light belongs to (empty:
    // none), and whether it is switched on. A light switched off is kept in the scene and the
    // file but renders as if it were not there (withoutLightsSwitchedOff).
    std::string group;
    bool on = true;
    // Point, spot, luminaire (README, "Maintained values"): this light's maintenance factor,
    // which replaces the scene's for it. Absent: the scene's, or none.
    std::optional<MaintenanceFactor> maintenance;
    // Point, spot, luminaire (README, "Energy"): the light's circuit power, W, for the lighting
    // energy; a luminaire without it takes the power its file states. Absent: not given.
    std::optional<double> circuitWatts;

    bool operator==(const Light&) const = default;
};

// Where the scene stands on Earth (SPEC.md section 5): what places the sun by local time.
struct Site {
    double latitudeDeg = 0;   // north positive
    double longitudeDeg = 0;  // east positive
    double utcOffsetHours = 0;
    V3d north{0, 0, -1};      // horizontal direction of geographic north; east = north x up
    bool northGiven = false;  // written back only if it was there
    // An addition to SPEC.md (README, "Daylight"): the site's median external diffuse
    // illuminance, lx, from which EN 17037's daylight-factor targets follow. Absent: not given.
    std::optional<double> medianDiffuseIlluminance;

    bool operator==(const Site&) const = default;
};

enum class SkyModelType { Uniform, CieOvercast, CieGeneral, Perez };

// How bright a uniform, cie_overcast or cie_general sky and its sun are (an addition to SPEC.md;
// README, "Daylight levels"). Fixed: the numbers the file gives (the sky's zenith_luminance or
// horizontal_illuminance, the sun's illuminance), whatever the time. FollowAltitude (the sky's
// "daylight_levels": "altitude"): the file gives neither; resolveDaylight computes both from the
// sun's altitude (core/daylight/daylight_availability.h).
enum class DaylightLevels { Fixed, FollowAltitude };

// The sky of SPEC.md section 5: an emitter at infinity, the ground below the horizon.
struct Sky {
    SkyModelType model = SkyModelType::CieOvercast;
    int cieType = 0;                                 // CieGeneral: 1..15
    std::optional<double> zenithLuminance;           // cd/m^2; exactly one of the two is set
    std::optional<double> horizontalIlluminance;     // lx, of the sky alone on an open plane
    // FollowAltitude: neither quantity is set (nor the sun's illuminance); never for perez.
    DaylightLevels levels = DaylightLevels::Fixed;
    // Perez (SPEC.md section 6): one hour of a weather file, instead of the two quantities above.
    double directNormalIrradiance = 0;               // Ib, W/m^2
    double diffuseHorizontalIrradiance = 0;          // Ed, W/m^2
    std::optional<double> dewPointC;                 // Td; 11 when absent
    double groundReflectance = 0.2;                  // in [0, 1]
    bool groundReflectanceGiven = false;             // written back only if it was there

    bool operator==(const Sky&) const = default;
};

// Who the design is for (README, "Reports"; an addition): the report's cover. All optional.
struct ProjectInfo {
    std::string name, client, designer, notes;
    bool operator==(const ProjectInfo&) const = default;
};

// A glare observer (README, "Glare"): the eye and the direction it looks in (scene units).
struct GlareObserver {
    V3d position{0, 0, 0};
    V3d view{0, 0, -1};  // non-zero, as written
    bool operator==(const GlareObserver&) const = default;
};

// A task area (EN 12464-1:2021, 5.3; README, "Task areas"; an addition): a rectangle on the work
// plane, as a calculation grid, with the activity whose requirements it is checked against (a
// reference number of the bundled table, resources/standards/en12464-1.json; empty: none) and
// the observers whose UGR is checked (none given: four, README). Optionally the widths of
// EN 12464-1's surrounding zone (a band around the area, at least 0.5 m) and of its background
// area (a band around that zone, at least 3 m; only with a surrounding zone), in metres
// (core/photometry/surrounding_zones.h).
struct TaskArea {
    CalculationGrid grid;   // grid.name is the area's name
    std::string activity;
    std::vector<GlareObserver> observers;
    std::optional<double> surroundingMeters;  // "surrounding_m"; absent: no surrounding zone
    std::optional<double> backgroundMeters;   // "background_m"; absent: no background area
    // "posture": "standing" puts the cylindrical illuminance at 1.6 m above the floor instead of
    // seated's 1.2 m (EN 12464-1:2021, 5.2.6); written back only when standing.
    bool standing = false;
    bool operator==(const TaskArea& o) const {
        return grid.name == o.grid.name && grid.corner == o.grid.corner && grid.edgeU == o.grid.edgeU &&
               grid.edgeV == o.grid.edgeV && grid.spacingMeters == o.grid.spacingMeters && activity == o.activity &&
               observers == o.observers && surroundingMeters == o.surroundingMeters &&
               backgroundMeters == o.backgroundMeters && standing == o.standing;
    }
};

// An opening in a room's wall (README, "Rooms"; an addition): a window holds a glazing pane, a
// door reaches down to the floor, a plain opening is a hole. Lengths in scene units.
enum class OpeningType { Window, Door, Opening };

struct RoomOpening {
    OpeningType type = OpeningType::Window;
    int wall = 1;         // 1-based: wall k runs from outline corner k-1 to corner k (the last back to the first)
    double offset = 0;    // along the wall from its first corner to the opening's near edge
    double sill = 0;      // above the floor level (a door's is 0)
    double width = 1, height = 1;
    std::string glazing;  // a window's pane: a glazing material's name

    bool operator==(const RoomOpening&) const = default;
};

// A room (README, "Rooms"; an addition): a parametric room has an outline in plan, a floor level
// and a height, the materials of floor, walls and ceiling, and openings in its walls; its
// generated surfaces are ordinary objects tagged with its name (Object::room). A room without an
// outline was marked on existing objects (a closed shell): its surfaces are never regenerated.
struct Room {
    std::string name;
    std::vector<V2d> outline;  // corners (x, z), scene units, either orientation; empty: marked
    double floorLevel = 0;     // y of the floor, scene units
    double height = 3;         // floor to ceiling, scene units
    std::string floorMaterial, wallMaterial, ceilingMaterial;
    std::vector<RoomOpening> openings;

    bool parametric() const { return !outline.empty(); }
    bool operator==(const Room&) const = default;
};

struct Scene {
    int version = 1;
    double metersPerUnit = 1.0;
    bool metersPerUnitGiven = false;  // written back only if it was there
    Camera camera;
    std::vector<Material> materials;  // in file order; names unique
    std::vector<Object> objects;
    std::vector<Light> lights;
    std::optional<Site> site;  // SPEC.md section 5
    std::optional<Sky> sky;
    // Additions (README, "Maintained values", "Task areas", "Reports").
    std::optional<MaintenanceFactor> maintenance;  // every electric light's without its own
    // "lighting_standard": the EN 12464-1 edition task areas are checked against; absent:
    // kDefaultStandardEdition (and nothing written back).
    std::optional<StandardEdition> lightingStandard;
    std::vector<TaskArea> taskAreas;
    std::optional<ProjectInfo> project;
    std::optional<EnergySettings> energy;  // README, "Energy (LENI)"; absent: LENI not computed
    std::vector<Room> rooms;  // README, "Rooms"; an addition
    std::string baseDir;  // folder that relative mesh paths resolve against (absolute)

    const Material* findMaterial(const std::string& name) const;
    int materialIndex(const std::string& name) const;  // -1 if absent

    bool operator==(const Scene& s) const {
        return version == s.version && metersPerUnit == s.metersPerUnit && camera == s.camera &&
               materials == s.materials && objects == s.objects && lights == s.lights && site == s.site &&
               sky == s.sky && maintenance == s.maintenance && lightingStandard == s.lightingStandard && taskAreas == s.taskAreas && project == s.project &&
               energy == s.energy && rooms == s.rooms;
    }
};

// Immutable snapshots are what backends receive (DESIGN.md, "The flow of data").
using SceneSnapshot = std::shared_ptr<const Scene>;

// The scene as the renderers see it: the lights switched off ("on": false) left out, the others
// in their order. The same snapshot when every light is on (no copy). Every place that builds
// what renders from a scene (the tracing backends, the preview, the grids) goes through it.
SceneSnapshot withoutLightsSwitchedOff(SceneSnapshot scene);

// The edition the scene's task areas are checked against: its own, else kDefaultStandardEdition.
inline StandardEdition lightingStandardOf(const Scene& scene) {
    return scene.lightingStandard.value_or(kDefaultStandardEdition);
}
// A light's maintenance factor (its own, else the scene's, else 1); daylight (sun, directional)
// has none: 1. Emitter materials take the scene's.
double maintenanceFactor(const Scene& scene, const Light& light);
// The range of maintenance factors over the lights switched on and, when the scene has emitter
// objects, the scene's own: {1, 1} when nothing is scaled (the new installation).
struct MaintenanceRange {
    double lowest = 1, highest = 1;
    bool electric = false;  // whether the scene has any electric light switched on
    bool maintained() const { return lowest != 1 || highest != 1; }
};
MaintenanceRange maintenanceRange(const Scene& scene);
// Which values a figure is: "maintained values (maintenance factor 0.80)", "... (maintenance
// factors 0.72 to 0.80)", "values of the new installation (no maintenance factor)" or, with no
// electric light, "daylight only (no electric light to maintain)".
std::string describeMaintenance(const MaintenanceRange& range);

// The scene as the renderers see it (every backend, the preview, the grids and the illuminance
// layer): withoutLightsSwitchedOff, then each electric light's emission (point, spot,
// luminaire, and every emitter material) scaled by its maintenance factor, so that what they
// compute is the maintained value. The same snapshot when nothing changes.
SceneSnapshot sceneAsRendered(SceneSnapshot scene);
// The scene with every maintenance factor removed: the new installation (what UGR is
// computed for, CIE 117).
Scene withoutMaintenance(Scene scene);

// What a scene calls for, so that backends model only what it needs (and `lucerna info` says so).
// Lights switched off are not counted.
struct SceneFeatures {
    bool hasDiffuse = false, hasGlossy = false, hasMirror = false, hasDielectric = false, hasGlazing = false;
    int emitterTriangles = 0;
    int pointLights = 0, spotLights = 0, directionalLights = 0, luminaires = 0;
    bool hasSun = false, hasSky = false;  // SPEC.md section 5
    size_t triangles = 0;
    bool hasSpecular() const { return hasMirror || hasDielectric; }
    bool hasDeltaLights() const { return pointLights + spotLights + directionalLights + luminaires > 0; }
    bool hasDaylight() const { return hasSun || hasSky; }
};
SceneFeatures analyseFeatures(const Scene& scene);

}  // namespace lucerna
