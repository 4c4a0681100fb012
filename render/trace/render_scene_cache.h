#pragma once
// Render scenes shared by several backends of one render (auto's candidates): one per way of
// choosing lights and of sending daylight through the portals, the two settings a backend's
// render scene depends on besides the snapshot, resolution and sensor, which one render shares.

#include "render/trace/render_scene.h"

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <utility>

namespace lucerna {

class RenderSceneCache {
public:
    // The scene made for (selection, portals), built by `build` the first time it is asked for.
    std::shared_ptr<const RenderScene> get(LightSelection selection, bool daylightPortals,
                                           const std::function<std::shared_ptr<const RenderScene>()>& build) {
        const std::lock_guard lock(mutex_);
        auto& scene = scenes_[{selection, daylightPortals}];
        if (!scene) scene = build();
        return scene;
    }

private:
    std::mutex mutex_;
    std::map<std::pair<LightSelection, bool>, std::shared_ptr<const RenderScene>> scenes_;
};

}  // namespace lucerna
