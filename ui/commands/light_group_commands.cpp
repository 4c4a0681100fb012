#include "ui/commands/light_group_commands.h"

#include <unordered_set>

namespace lucerna {

std::vector<int> groupMembers(const Scene& scene, const std::string& group) {
    std::vector<int> members;
    if (group.empty()) return members;
    for (size_t i = 0; i < scene.lights.size(); ++i)
        if (scene.lights[i].group == group) members.push_back(int(i));
    return members;
}

std::vector<std::string> groupNames(const Scene& scene) {
    std::vector<std::string> names;
    std::unordered_set<std::string> seen;
    for (const Light& l : scene.lights)
        if (!l.group.empty() && seen.insert(l.group).second) names.push_back(l.group);
    return names;
}

}  // namespace lucerna
