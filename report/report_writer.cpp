#include "report/report_writer.h"

#include "core/atomic_file.h"
#include "report/page_flow.h"
#include "report/report_pages.h"
#include "report/report_text.h"

#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>

#include <stdexcept>

namespace lucerna {

namespace {

constexpr int kDotsPerInch = 300;

}  // namespace

int writeReportPdf(const ReportData& data, const std::string& path) {
    int pages = 0;
    writeAtomically(path, [&](const std::string& temp) {
        QPdfWriter writer(QString::fromStdString(temp));
        writer.setPageSize(QPageSize(QPageSize::A4));
        writer.setPageOrientation(QPageLayout::Portrait);
        writer.setPageMargins(QMarginsF(0, 0, 0, 0));
        writer.setResolution(kDotsPerInch);
        writer.setTitle(qs(data.projectName) + QStringLiteral(": lighting design report"));
        writer.setCreator(qs(data.software));

        PageFlow flow(writer);
        addCoverPage(flow, data);
        addRoomSummaryPage(flow, data);
        addSchedulePage(flow, data);
        addEnergySection(flow, data);
        addDataSheetPages(flow, data);
        for (const AreaReport& area : data.areas) addAreaPages(flow, data, area);
        addRendersPage(flow, data);
        addMethodPage(flow, data);

        QPainter painter;
        if (!painter.begin(&writer)) throw std::runtime_error(path + ": cannot write");
        painter.setRenderHint(QPainter::Antialiasing);
        const QString footer = QStringLiteral("%1, %2, %3").arg(qs(data.sceneFile), qs(data.date), qs(data.software));
        bool pageFailed = false;
        flow.paint(painter, qs(data.projectName), QStringLiteral("Lighting design report"), footer,
                   [&] { pageFailed = pageFailed || !writer.newPage(); });
        if (!painter.end() || pageFailed) throw std::runtime_error(path + ": cannot write");
        pages = flow.pageCount();
    });
    return pages;
}

}  // namespace lucerna
