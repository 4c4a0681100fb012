#pragma once
// The parser of one SPEC.md scene file (section 1), for parseScene (scene_io.h): every rule of
// the contract is checked, and every violation becomes one SceneError line
// "<file>: <JSON path>: <problem>". Its parts are read in scene_reader.cpp (the top level, camera,
// materials, objects), light_keys.cpp, daylight_keys.cpp and project_keys.cpp; the typed values
// they all read in scene_parser.cpp. Internal to core/scene.

#include "core/scene/json_reader.h"
#include "core/scene/scene.h"

#include <initializer_list>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace lucerna {

class SceneParser {
public:
    explicit SceneParser(const std::string& file) : file_(file) {}

    // The scene of the JSON document `root`, its meshes and luminaire files not yet read.
    Scene parse(const json::Value& root);

private:
    using Type = json::Type;
    using Value = json::Value;
    static constexpr const char* kTopLevel = "top level";

    // The JSON path of `key` in `parent`: camera.fov_y, objects[2].mesh.vertices[5][1],
    // materials["my glass"].ior.
    static std::string member(const std::string& parent, const std::string& key);

    // Typed values, each checked and named by its place (scene_parser.cpp).
    [[noreturn]] void fail(const std::string& place, const std::string& problem) const;
    void expectType(const Value& v, Type type, const std::string& place) const;
    // `v` is an object whose keys are all among `allowed` (listed in the message otherwise).
    void checkKeys(const Value& v, const std::string& place, std::initializer_list<std::string_view> allowed,
                   const std::string& what = {}) const;
    const Value& required(const Value& object, const std::string& place, const std::string& key) const;
    double number(const Value& v, const std::string& place) const;
    // SPEC.md: "indices and resolutions are integers". As in JSON Schema, a number with no
    // fractional part (2, 2.0, 2e0) is an integer.
    double integer(const Value& v, const std::string& place) const;
    double numberIn(const Value& v, const std::string& place, double lo, bool loOpen, double hi, bool hiOpen,
                    const std::string& unit = {}) const;
    std::string text(const Value& v, const std::string& place) const;
    const Value& array(const Value& v, const std::string& place, size_t size, const char* what) const;
    V3d vec3(const Value& v, const std::string& place) const;
    V3d direction(const Value& v, const std::string& place) const;
    // Albedo-like colours are fractions in [0, 1]; radiometric ones are at least 0.
    Rgbd colour(const Value& v, const std::string& place, bool fraction) const;
    // A light's or object's name, unique among them all.
    std::string parseName(const Value& v, const std::string& place);

    // The camera, materials and objects (scene_reader.cpp).
    Camera parseCamera(const Value& v, const std::string& place) const;
    void parseMaterials(const Value& v, const std::string& place, Scene& scene) const;
    Object parseObject(const Value& v, const std::string& place, const Scene& scene);
    MeshSource parseMesh(const Value& v, const std::string& place) const;
    Transform parseTransform(const Value& v, const std::string& place) const;

    // Lights (light_keys.cpp).
    Light parseLight(const Value& v, const std::string& place);
    // The additions every light type takes (README, "Light groups"): "group", a non-empty name
    // (groups are their own namespace: a group may share a light's name), and "on", a boolean.
    void parseGroupAndSwitch(const Value& v, const std::string& place, Light& l) const;
    // A luminaire's keys (README): its file, rotation about the nadir, and optional lumens and
    // colour (color or temperature, not both). The file itself is read by resolve().
    LuminaireSpec parseLuminaire(const Value& v, const std::string& place) const;
    // The photometric keys of a point or spot light (README): exactly one of intensity, lumens
    // and candela; with lumens or candela, at most one of color and temperature.
    std::optional<PhotometricSpec> parsePhotometric(const Value& v, const std::string& place) const;
    // "color" (of a positive luminance) or "temperature" (kelvin), not both: a light's colour,
    // left unset where neither is given.
    void parseLightColour(const Value& v, const std::string& place, std::optional<Rgbd>& rgb,
                          std::optional<double>& kelvin) const;

    // Daylight: the sun, the site and the sky (daylight_keys.cpp).
    // SPEC.md section 5: the illuminance, the disc's size, and its place: a direction or a local time.
    SunSpec parseSun(const Value& v, const std::string& place, Light& l) const;
    Site parseSite(const Value& v, const std::string& place) const;
    Sky parseSky(const Value& v, const std::string& place) const;
    Sky parsePerezSky(const Value& v, const std::string& place) const;
    // The rules that span keys: one sun at most, a local time needs a site, a CIE general sky a sun.
    void checkDaylight(const Scene& scene) const;

    // Maintenance factors, task areas, the project's details (project_keys.cpp).
    // A maintenance factor (README, "Maintained values"): a number, or CIE 97's factors, each in
    // (0, 1], at least one of them.
    MaintenanceFactor parseMaintenance(const Value& v, const std::string& place) const;
    // A task area (README, "Task areas"): a named rectangle as a calculation grid's, its activity
    // and its glare observers.
    TaskArea parseTaskArea(const Value& v, const std::string& place, const std::vector<TaskArea>& earlier) const;
    ProjectInfo parseProject(const Value& v, const std::string& place) const;
    // "lighting_standard" (README, "Task areas"): "EN 12464-1:2021" or "EN 12464-1:2011".
    StandardEdition parseLightingStandard(const Value& v, const std::string& place) const;
    // Rooms (room_keys.cpp; README, "Rooms"): a room's name, outline, levels, materials and
    // openings (core/scene/room_geometry.h's roomProblem), its name unique among rooms; after
    // the objects, that every room without an outline has objects tagged with it.
    Room parseRoom(const Value& v, const std::string& place, const Scene& scene) const;
    void checkRooms(const Scene& scene) const;
    // The lighting energy's settings (README, "Energy (LENI)"): the building type and the
    // factors over its defaults, each in its range, the hours of a year at most 8760 together.
    EnergySettings parseEnergy(const Value& v, const std::string& place) const;
    // A point, spot or luminaire's "circuit_watts", W, at least 0.
    void parseCircuitWatts(const Value& v, const std::string& place, Light& l) const;

    std::string file_;
    std::unordered_map<std::string, std::string> names_;  // name -> where it was first used
};

}  // namespace lucerna
