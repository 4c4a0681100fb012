// `lucerna annual` (SPEC.md section 6) as a user runs it: on the bundled daylit office with the
// bundled weather file it prints the section's lines and writes both CSVs; --export-hour writes
// the hour's scene; bad input is a one-line error with exit 2 and no file.

#include "process_run.h"
#include "csv_table.h"

#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <fstream>
#include <optional>
#include <sstream>

using namespace lucerna::test;

namespace {

const QString kOffice = LUCERNA_RESOURCE_DIR "/scenes/daylit_office.json";
const QString kWeather = LUCERNA_RESOURCE_DIR "/weather/paris_synthetic.epw";

}  // namespace

class TestAnnualCommand : public QObject {
    Q_OBJECT
private slots:
    void bundledOffice();
    void exportHour();
    void badInput();
    void reportSection();
};

void TestAnnualCommand::bundledOffice() {
    QTemporaryDir dir;
    const QString csv = dir.filePath("points.csv"), hourly = dir.filePath("hourly.csv");
    const Run r = runLucerna({"annual", kOffice, "--weather", kWeather, "--task-area", "Reference plane", "--spacing", "0.7",
                              "--paths", "1024", "--sun-paths", "64", "--csv", csv, "--hourly", hourly});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    for (const char* line : {"weather: Paris (synthetic)", "hours: 4348 with daylight", "3650 occupied", "sDA300/50%: ",
                             "blinds are not modelled", "ASE1000,250h: ", "UDI: fell short (< 100 lx) ",
                             "EN 17037 illuminance method, over 4380 daylight hours: minimum ", "stated 95% error"})
        QVERIFY2(r.out.contains(line), qPrintable(QString(line) + "\n" + r.out));
    const CsvTable points = CsvTable::read(csv);
    QCOMPARE(points.header, (QStringList{"x", "y", "z", "da300", "udi_fell_short", "udi_useful", "udi_exceeded",
                                         "ase_hours", "mean_lux"}));
    QVERIFY(points.rows.size() >= 20);
    for (size_t i = 0; i < points.rows.size(); ++i) {
        const auto da = points.number(i, "da300"), a = points.number(i, "udi_fell_short"),
                   b = points.number(i, "udi_useful"), c = points.number(i, "udi_exceeded");
        QVERIFY(da && a && b && c);
        QVERIFY(*da >= 0 && *da <= 1);
        QVERIFY(std::abs(*a + *b + *c - 1) < 1e-4);  // the three UDI bands cover the occupied hours
    }
    const CsvTable hours = CsvTable::read(hourly);
    QCOMPARE(hours.rows.size(), size_t(8760));
    QCOMPARE(size_t(hours.header.size()), 3 + points.rows.size());
    QCOMPARE(hours.header[3], QString("p1"));
    QCOMPARE(hours.rows[0].mid(0, 3).join('-'), QString("1-1-1"));
    QCOMPARE(hours.number(0, "p1"), std::optional<double>(0.0));  // 00:30 on 1 January: night
}

void TestAnnualCommand::exportHour() {
    QTemporaryDir dir;
    const QString out = dir.filePath("hour.json");
    const Run r = runLucerna({"annual", kOffice, "--weather", kWeather, "--export-hour", "06-21-13", out});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QFile f(out);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(f.readAll());
    QVERIFY(text.contains("\"perez\""));
    QVERIFY(text.contains("\"2021-06-21T12:30\""));  // the hour ending 13:00 stands for 12:30
    QVERIFY(!text.contains("\"illuminance\""));       // the model gives the sun's
    const Run info = runLucerna({"info", out});
    QCOMPARE(info.exitCode, 0);
    QVERIFY2(info.out.contains("sky: perez"), qPrintable(info.out));
}

void TestAnnualCommand::badInput() {
    QTemporaryDir dir;
    // A weather file with a negative irradiance on its 20th line.
    std::ifstream in(kWeather.toStdString());
    std::ostringstream text;
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        if (n == 20) {
            std::vector<std::string> fields;
            std::stringstream ss(line);
            for (std::string f; std::getline(ss, f, ',');) fields.push_back(f);
            fields[15] = "-5";
            line.clear();
            for (size_t i = 0; i < fields.size(); ++i) line += (i ? "," : "") + fields[i];
        }
        text << line << "\n";
    }
    const QString bad = dir.filePath("bad.epw"), csv = dir.filePath("out.csv");
    std::ofstream(bad.toStdString()) << text.str();
    Run r = runLucerna({"annual", kOffice, "--weather", bad, "--work-plane", "0.85", "--csv", csv});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("bad.epw:20:") && r.err.trimmed().count('\n') == 0, qPrintable(r.err));
    QVERIFY(!QFile::exists(csv));
    r = runLucerna({"annual", kOffice, "--work-plane", "0.85"});
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.err.contains("--weather"));
    r = runLucerna({"annual", kOffice, "--weather", kWeather, "--export-hour", "02-30-01", dir.filePath("x.json")});
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.err.contains("no row"));
    r = runLucerna({"annual", kOffice, "--weather", kWeather, "--task-area", "Nowhere"});
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.err.contains("Reference plane"));
}

void TestAnnualCommand::reportSection() {
    // `lucerna report --weather`: the area's year in the PDF, with the section's figures.
    if (QStandardPaths::findExecutable("pdftotext").isEmpty())
        QFAIL("pdftotext (poppler-utils) is missing: packaging/install-deps.sh installs it");
    QTemporaryDir dir;
    const QString pdf = dir.filePath("office.pdf");
    const Run r = runLucerna({"report", kOffice, "-o", pdf, "--weather", kWeather, "--spp", "2", "--error", "0.2"});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QProcess p;
    p.start("pdftotext", {pdf, "-"});
    QVERIFY(p.waitForFinished(30000) && p.exitCode() == 0);
    const QString text = QString::fromUtf8(p.readAllStandardOutput());
    for (const char* words : {"Annual daylight: Reference plane", "Paris (synthetic)", "sDA300/50%", "ASE1000,250h",
                              "UDI useful", "EN 17037 level", "Stated 95% error", "DA300 [%]"})
        QVERIFY2(text.contains(words), words);
    // A bad weather file: one line, exit 2, no PDF.
    const Run bad = runLucerna({"report", kOffice, "-o", dir.filePath("x.pdf"), "--weather", kOffice});
    QCOMPARE(bad.exitCode, 2);
    QVERIFY(!QFile::exists(dir.filePath("x.pdf")));
}

QTEST_GUILESS_MAIN(TestAnnualCommand)
#include "test_annual_command.moc"
