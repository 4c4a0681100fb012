// The Annual dock (issue 39) in the window, as a designer uses it: on the bundled daylit office
// with the bundled weather file, the task area chosen, Compute shows SPEC.md section 6's figures,
// the chosen metric per point on the dock's map and on the plan (its legend in the metric's
// unit), a click on the map shows that point's year as a heat map; Cancel stops a year and
// leaves nothing half shown; a bad weather file is one line in the dock.

#include "ui/calculation/annual_charts.h"
#include "ui/calculation/annual_panel.h"
#include "ui/plan/plan_view.h"
#include "ui/window/main_window.h"
#include "window_test_helpers.h"

#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTemporaryDir>
#include <QtTest>

#include <fstream>

using namespace lucerna;
using namespace lucerna::test;

namespace {
constexpr int kTimeout = 120000;  // ms; generous for a loaded machine, never a timing assertion
const QString kOffice = LUCERNA_RESOURCE_DIR "/scenes/daylit_office.json";
}  // namespace

class TestAnnualPanel : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { useTestSettings("test_annual_panel"); }

    void yearOfTheOffice() {
        MainWindow w(kOffice);
        w.resize(1600, 1000);
        w.show();
        AnnualPanel* panel = w.annualPanel();
        w.findChild<QDockWidget*>("annualDock")->raise();
        auto* area = child<QComboBox>(*panel, "annualArea");
        QCOMPARE(area->itemText(1), QString("Reference plane"));
        area->setCurrentIndex(1);
        child<QDoubleSpinBox>(*panel, "annualSpacing")->setValue(0.6);
        QVERIFY(child<QLineEdit>(*panel, "annualWeather")->text().endsWith("paris_synthetic.epw"));
        QTest::mouseClick(child<QPushButton>(*panel, "annualCompute"), Qt::LeftButton);
        QVERIFY(panel->isComputing());
        QTRY_VERIFY_WITH_TIMEOUT(!panel->isComputing(), kTimeout);
        QVERIFY(panel->result() && panel->metrics());
        const QString figures = child<QLabel>(*panel, "annualFigures")->text();
        for (const char* line : {"weather: Paris (synthetic)", "hours: 4348 with daylight", "3650 occupied", "sDA300/50%: ",
                                 "ASE1000,250h: ", "UDI: fell short ", "EN 17037 illuminance method", "stated 95% error"})
            QVERIFY2(figures.contains(line), qPrintable(figures));

        // DA300 on the plan, in %; then ASE in hours.
        QVERIFY(w.planView()->gridLegend().has_value());
        QCOMPARE(w.planView()->gridLegend()->unit, QString("%"));
        auto* metric = child<QComboBox>(*panel, "annualMetric");
        metric->setCurrentIndex(4);
        QCOMPARE(w.planView()->gridLegend()->unit, QString("h"));
        QCOMPARE(panel->planValues()->lux.size(), panel->layout().points.size());
        QCOMPARE(panel->planValues()->lux[0], double(panel->metrics()->points[0].aseHours));

        // A click on the map's first cell: that point's year.
        auto* map = child<AnnualGridMap>(*panel, "annualMap");
        QTest::qWait(50);
        click(map, QPointF(12, 12));
        QCOMPARE(map->selected(), 0);
        QTest::qWait(100);
        panel->grab().save("annual_panel.png");
        w.grab().save("annual_window.png");

        // A bad weather file: one line, and the shown year stays.
        QTemporaryDir dir;
        const QString bad = dir.filePath("bad.epw");
        std::ofstream(bad.toStdString()) << "LOCATION,x\n";
        panel->setWeatherFile(bad);
        QTest::mouseClick(child<QPushButton>(*panel, "annualCompute"), Qt::LeftButton);
        QVERIFY(!panel->isComputing());
        QVERIFY(panel->result());
        QVERIFY(w.findChild<QLabel*>("annualStatus")->text().contains("bad.epw:1:"));
    }

    void cancelStops() {
        MainWindow w(kOffice);
        w.show();
        AnnualPanel* panel = w.annualPanel();
        child<QDoubleSpinBox>(*panel, "annualSpacing")->setValue(0.2);
        panel->compute();
        QVERIFY(panel->isComputing());
        panel->cancel();
        QVERIFY(!panel->isComputing());
        QVERIFY(!panel->result());
        QCOMPARE(w.findChild<QLabel*>("annualStatus")->text(), QString("Cancelled."));
    }
};

QTEST_MAIN(TestAnnualPanel)
#include "test_annual_panel.moc"
