#pragma once
// What the report's tests share (test_report, test_report_parts): the bundled scenes, small
// settings, and the PDF read back with poppler-utils (pdftotext; packaging/install-deps.sh
// installs them).

#include "process_run.h"
#include "report/report_builder.h"

#include <QStandardPaths>
#include <QString>
#include <QStringList>
#include <QtTest>

namespace lucerna::test {

inline const QString kScenes = QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/");
// Small settings: a coarse error target and few samples, so that a report takes a second or two.
inline const QStringList kSmall = {"--error", "0.15", "--seed", "7", "--samples", "8"};

// The same small settings for buildReport().
inline ReportSettings smallSettings() {
    ReportSettings s;
    s.grid.targetRelativeError = 0.15;
    s.grid.seed = 7;
    s.grid.samplesPerPass = 8;
    s.renderSpp = 2;
    return s;
}

// poppler-utils are the test's eyes: without them it cannot read the PDF, and says how to get them.
inline bool havePoppler() {
    return !QStandardPaths::findExecutable("pdftotext").isEmpty() && !QStandardPaths::findExecutable("pdftoppm").isEmpty();
}
#define REQUIRE_POPPLER()                                                                                         \
    if (!havePoppler())                                                                                           \
        QFAIL("pdftotext and pdftoppm (poppler-utils) are missing: packaging/install-deps.sh installs them")

inline QString pdfText(const QString& pdf) {
    const Run r = runProgram("pdftotext", {pdf, "-"});
    return r.out;
}

// The office floor's two luminaire types as their files state them: for each, the file, the
// count, the flux as installed.
struct OfficeType {
    QString file;
    int count;
    double lumens;
};
inline const OfficeType kOfficeTypes[] = {{"luminaires/office_panel.ies", 84, 3600}, {"luminaires/office_linear.ldt", 24, 4000}};

}  // namespace lucerna::test
