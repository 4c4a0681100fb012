#pragma once
// The edition of EN 12464-1 a scene's task areas are checked against (scene key
// "lighting_standard", README "Task areas"; an addition).

#include <optional>
#include <string>

namespace lucerna {

enum class StandardEdition { En12464_2011, En12464_2021 };
// The edition a scene is checked against when it names none.
inline constexpr StandardEdition kDefaultStandardEdition = StandardEdition::En12464_2021;
// "EN 12464-1:2011", "EN 12464-1:2021": the scene key's values.
const char* standardEditionName(StandardEdition edition);
std::optional<StandardEdition> standardEditionFromName(const std::string& name);

}  // namespace lucerna
