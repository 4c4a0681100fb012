#pragma once
// The kinds of page a report has, each laid out on the flow from the report's data: the cover
// (project, summary), the luminaire schedule, a task area's results (plan, figures, checks, UGR,
// table of values), the renders, and the calculation's method and error bars.

#include "report/page_flow.h"
#include "report/plan_figure.h"
#include "report/report_data.h"

namespace lucerna {

void addCoverPage(PageFlow& flow, const ReportData& data);
void addSchedulePage(PageFlow& flow, const ReportData& data);
// The room's dimensions, main surfaces, maintenance and load (room_summary_page.cpp); for a scene
// with rooms (data.rooms), room by room; none without either.
void addRoomSummaryPage(PageFlow& flow, const ReportData& data);
// A page (or two) per luminaire type: its figures, polar diagram and UGR tables (data_sheet_pages.cpp).
void addDataSheetPages(PageFlow& flow, const ReportData& data);
// EN 15193-1's LENI with its factors (energy_page.cpp), flowing on after the schedule.
void addEnergySection(PageFlow& flow, const ReportData& data);
void addAreaPages(PageFlow& flow, const ReportData& data, const AreaReport& area);
// Parts of an area's pages: its plan with `values` (at most maxHeight tall with the legend), and
// the daylight factor.
void addPlan(PageFlow& flow, const ReportData& data, const AreaReport& area, PlanValues values, double maxHeight);
void addDaylightFactor(PageFlow& flow, const ReportData& data, const AreaReport& area);
// The area's year of daylight from the weather file (SPEC.md section 6).
void addAnnualDaylight(PageFlow& flow, const ReportData& data, const AreaReport& area);
// Ez, the walls and ceiling of its room and its zones, with the modelling ratio
// (area_extras_section.cpp); nothing where none was computed.
void addAreaExtras(PageFlow& flow, const ReportData& data, const AreaReport& area);
void addRendersPage(PageFlow& flow, const ReportData& data);
void addMethodPage(PageFlow& flow, const ReportData& data);

// A picture across the content width at its aspect ratio, at most `maxHeight` tall, centred.
void addPicture(PageFlow& flow, const QImage& picture, double maxHeight);

}  // namespace lucerna
