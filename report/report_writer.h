#pragma once
// The report as a PDF (README, "Reports"): A4 portrait, a header with the project's name and a
// footer with the scene, the date and "Page n of N" on every page; the cover, the luminaire
// schedule, a page (or more) per task area, the renders and the method (report_pages.h).

#include "report/report_data.h"

#include <string>

namespace lucerna {

// Writes `data` as a PDF at `path`, whole or not at all (core/atomic_file.h). Throws
// std::runtime_error with one line when it cannot be written. Returns the number of pages.
int writeReportPdf(const ReportData& data, const std::string& path);

}  // namespace lucerna
