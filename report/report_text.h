#pragma once
// The report's figures as text: the grid's as `lucerna grid` prints them (app/grid_command.cpp),
// so that a reader (or a test) finds the same numbers in both, and the few phrases the pages
// share.

#include "report/report_data.h"

#include <QString>

namespace lucerna {

inline QString qs(const std::string& s) { return QString::fromStdString(s); }

// "Eavg 512.3 lx, Emin 301.0 lx, Emax 702.4 lx, U0 0.588", as `lucerna grid` prints it; what it
// prints when every point is inside geometry.
QString gridFiguresLine(const GridStatistics& s);
// "error bar (95%) at most 1.93% of each point's value after 12 passes, 192 samples per point,
// 3.2 s", as `lucerna grid` prints it (or its line for an unknown error bar).
QString gridErrorLine(const GridResult& r, int counted);
// "%.1f", the grid's lux.
QString lux(double value);
// "4 min 05 s" or "12.3 s".
QString seconds(double s);
// The activity in words: "5.26.2 Offices: Writing, typing, reading, data processing".
QString activityText(const ActivityRequirement& a);
// What a grid method does, in a sentence.
QString methodDescription(GridMethod method);
// "met", "not met", "not stated", "not computed".
QString outcomeText(const RequirementCheck& check);

}  // namespace lucerna
