// libFuzzer: parseScene on any bytes either returns a scene or throws SceneError (one line);
// nothing else escapes, nothing crashes, and what parses survives a save and a reload.

#include "core/scene/scene_io.h"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    try {
        const lucerna::Scene scene = lucerna::parseScene(bytes, "fuzz.json");
        const lucerna::Scene again = lucerna::parseScene(lucerna::saveSceneToString(scene), "fuzz.json");
        if (again.objects.size() != scene.objects.size() || again.lights.size() != scene.lights.size()) std::abort();
    } catch (const lucerna::SceneError& e) {
        if (std::string(e.what()).find('\n') != std::string::npos) std::abort();
    }
    return 0;
}
