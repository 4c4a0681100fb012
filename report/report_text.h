#pragma once
// The few phrases the report's pages share. A grid's results read as everywhere else
// (render/photometry/grid_text.h), so that a reader (or a test) finds the numbers `lucerna grid`
// prints.

#include "report/report_data.h"

#include <QString>

namespace lucerna {

inline QString qs(const std::string& s) { return QString::fromStdString(s); }

// "%.1f", a figure in lux.
QString lux(double value);
// The activity in words: "5.26.2 Offices: Writing, typing, reading, data processing".
QString activityText(const ActivityRequirement& a);
// What a grid method does, in a sentence.
QString methodDescription(GridMethod method);
// "met", "not met", "not stated", "not computed".
QString outcomeText(const RequirementCheck& check);

}  // namespace lucerna
