#include "ui/commands/light_group_commands.h"

namespace lucerna {

std::vector<int> groupMembers(const Scene& scene, const std::string& group) {
    std::vector<int> members;
    if (group.empty()) return members;
    for (size_t i = 0; i < scene.lights.size(); ++i)
        if (scene.lights[i].group == group) members.push_back(int(i));
    return members;
}

}  // namespace lucerna
