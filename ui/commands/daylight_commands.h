#pragma once
// Undo commands on the scene's daylight (SPEC.md section 5): the site and the sky. The sun is a
// light and is edited with the light commands; the suns made here are what those commands take.
// Consecutive edits with the same merge key fold into one step (a run of arrow steps in a field).

#include "ui/commands/change_value.h"

#include <string>

namespace lucerna {

// EditSiteCommand(doc, after, mergeKey, text), EditSkyCommand(doc, after, mergeKey, text);
// mergeKey 0: never merges.
using EditSiteCommand = ChangeValue<ValueKind::Site, &Document::site, &Document::setSite>;
using EditSkyCommand = ChangeValue<ValueKind::Sky, &Document::sky, &Document::setSky>;

// The index of the scene's sun (SPEC.md: at most one), or -1.
int sunIndex(const Scene& scene);

// A new sun of 75,000 lx direct normal illuminance (a clear day's order of magnitude) and the
// default 0.53 degree disc: placed by `time` ("YYYY-MM-DDTHH:MM") when the scene has a site,
// else by direction, 45 degrees above the southern horizon.
Light newSun(const Scene& scene, const std::string& name, const std::string& time);
// The sun placed by that local time (its direction then comes from the site).
Light sunAtTime(const Light& sun, const std::string& time);
// The sun placed by the direction it has now in `scene` (for a sun about to lose its site).
Light sunByDirection(const Scene& scene, const Light& sun);

// The north angle of the daylight panel: degrees from -z toward +x, in [0, 360), and back to the
// site's `north` vector [sin a, 0, -cos a] (components within 1e-12 of 0 written as 0).
double northAngleDeg(const V3d& north);
V3d northFromAngle(double degrees);

}  // namespace lucerna
