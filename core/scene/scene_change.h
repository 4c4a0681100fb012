#pragma once
// What differs between two versions of a scene, computed in one place for every part that keeps
// state derived from a scene: the interactive preview (what to redraw), the editor's surface
// picker (when to rebuild), the per-light layers (whether an edit is a re-mix), and the plan and
// the grid dock (whether a grid's result is out of date).

#include "core/scene/scene.h"

#include <vector>

namespace lucerna {

struct SceneChange {
    bool geometry = false;    // objects added or removed, or an object's world mesh replaced
    bool materials = false;   // a material, an object's material or the scene's unit
    bool camera = false;      // the camera's pose or field of view
    bool resolution = false;  // the camera's width or height
    bool lightSet = false;    // lights added or removed (then `lights` is empty)
    std::vector<size_t> lights;  // the indices of the lights that differ (same count)
    // The site or the sky differ (SPEC.md section 5). A sun placed by time moves with its site,
    // so a site change also lists such a sun in `lights`.
    bool daylight = false;
    // The scenes differ at most in the emission of their lights (intensity, irradiance,
    // photometric values, a luminaire's lumens and colour, switched on or off), in their lights'
    // groups, and in their emitters' radiance; true when they are equal. Never with `daylight`.
    bool emissionOnly = false;

    // Whether light on the scene's surfaces may differ: its geometry, materials, lights or
    // daylight changed; not so the camera's pose or resolution (what a grid's or a plan's
    // illuminance is out of date by).
    bool changesIlluminance() const { return geometry || materials || lightSet || !lights.empty() || daylight; }

    bool none() const {
        return !geometry && !materials && !camera && !resolution && !lightSet && lights.empty() && !daylight &&
               emissionOnly;
    }
};

// True when the scenes have the same world meshes (the same shared mesh data, in the same
// objects): what `geometry` of their diff denies, without the rest of the diff.
bool sameWorldMeshes(const Scene& a, const Scene& b);

// What changed from `before` to `after`. Meshes compare by their shared data (a mesh reloaded
// from the same file is a change), everything else by value.
SceneChange diff(const Scene& before, const Scene& after);

}  // namespace lucerna
