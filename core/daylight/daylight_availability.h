#pragma once
// How bright the sun and the sky are at a given solar altitude, without a weather file: the IES
// daylight availability model (IES Lighting Handbook; IES RP-21, "Recommended Practice for the
// Calculation of Daylight Availability", J. IES 13(4) 381-392, 1984, after Krochmann and Seidl
// and Kittler), the mean levels of a clear, a partly cloudy and an overcast day. What a sky with
// "daylight_levels": "altitude" gets (scene.h, DaylightLevels; resolveDaylight in daylight.h).
//
// - Sky, diffuse horizontal illuminance: E_kh = A + B sin^C(h) klx, h the solar altitude, with
//   (A, B, C) = (0.8, 15.5, 0.5) clear, (0.3, 45.0, 1.0) partly cloudy, (0.3, 21.0, 1.0)
//   overcast. The model stops at the horizon, where it still gives A; below it, through civil
//   twilight, the sky fades linearly in altitude to 0 at -6 degrees: E_kh = A (h + 6) / 6
//   (continuous at 0 and at -6, increasing); 0 lower still.
// - Sun, direct normal illuminance: E_dn = E_xt exp(-c m) with the extraterrestrial illuminance
//   E_xt = 127.5 klx (1 + 0.034 cos(2 pi (J - 2) / 365)) on day J (127.5 klx without a date), the
//   extinction coefficient c = 0.21 clear, 0.80 partly cloudy, and m the relative optical air mass
//   of Kasten and Young 1989. An overcast sky hides the sun (RP-21 gives it no direct light); at
//   and below the horizon the sun gives nothing (E_dn sin h, its horizontal part, goes to 0 there).

#include "core/scene/scene.h"

#include <optional>

namespace lucerna {

// The IES model's three sky conditions.
enum class SkyCondition { Clear, PartlyCloudy, Overcast };

// The condition a sky model stands for. ISO 15469's general skies fall in three groups of five
// (CIE S 011/E:2003's descriptions: 1 to 5 overcast, with type 5 the sky of uniform luminance; 6
// to 10 partly cloudy; 11 to 15 clear, 12 the CIE standard clear sky); `cie_overcast` is overcast
// and `uniform` is type 5, so overcast too. Perez has levels of its own: Overcast is returned and
// never used.
SkyCondition skyCondition(const Sky& sky);

// Kasten and Young 1989 (Applied Optics 28, 4735): m = 1 / (sin h + 0.50572 (h + 6.07995)^-1.6364),
// h the apparent altitude in degrees; 38 at the horizon. For h <= 0 it returns the horizon's value.
double relativeOpticalAirMass(double altitudeDeg);

// E_xt, lx, on day of year `dayOfYear` (1..366), or the mean 127,500 lx without one.
double extraterrestrialIlluminance(std::optional<int> dayOfYear);

// E_kh, lx: the sky alone on an unobstructed horizontal plane (with the twilight fade above).
double skyHorizontalIlluminance(SkyCondition condition, double altitudeDeg);

// E_dn, lx: the sun's direct normal illuminance; 0 for an overcast sky and at or below the horizon.
double sunDirectNormalIlluminance(SkyCondition condition, double altitudeDeg, std::optional<int> dayOfYear);

}  // namespace lucerna
