// The figures EN 12464-1:2021 adds to a task area, in the Calculation grid dock (issue 36): in a
// closed box room with a maintenance factor, a task area of activity 5.26.2 (the 2021 entry asks
// Ez, walls and ceiling) gets its Ez, walls and ceiling computed after its Em grid, shown and
// checked; with the boxes unticked they are not; an area without an activity gets what is ticked,
// unchecked; Cancel during them leaves the Em figures and says they are not computed; an edit
// while they run marks the result out of date.

#include "grid_check_scenes.h"
#include "ui/calculation/grid_panel.h"
#include "ui/commands/light_commands.h"
#include "ui/window/main_window.h"
#include "window_test_helpers.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <string>

#include <fstream>

using namespace lucerna;
using namespace lucerna::test;

namespace {
constexpr int kTimeout = 60000;  // ms; generous for a loaded machine, never a timing assertion

// The box room of grid_check_scenes.h (6 x 3 x 6 m, a lamp 2.5 m up) with a maintenance factor, a
// desk of activity 5.26.2 beside the cabinet and a shelf without an activity.
std::string officeJson() {
    std::string json = boxRoomSceneJson(true, false);
    json.insert(json.rfind('}'), R"(, "maintenance_factor": 0.8, "task_areas": [
      {"name": "desk", "corner": [-2.5, 0.8, 2.5], "u": [1.5, 0, 0], "v": [0, 0, -1.5], "spacing": 0.5, "activity": "5.26.2"},
      {"name": "shelf", "corner": [1.5, 0.8, 2.5], "u": [1, 0, 0], "v": [0, 0, -1], "spacing": 0.5}])");
    return json;
}

void choose(GridPanel& panel, int item) {
    auto* areas = child<QComboBox>(panel, "gridTaskArea");
    areas->setCurrentIndex(item);
    emit areas->activated(item);
}

// A click on the box's indicator (a wide box's middle may lie beyond its text, outside what it takes).
void clickBox(QCheckBox* box) { QTest::mouseClick(box, Qt::LeftButton, {}, QPoint(6, box->height() / 2)); }

QString figuresOf(GridPanel& panel) { return child<QLabel>(panel, "gridFigures")->text(); }

// The number a regular expression's first group captures in `text`; stops the test where there
// is none or it is not a number.
double captured(const QString& text, const QString& pattern) {
    const QRegularExpressionMatch m = QRegularExpression(pattern).match(text);
    if (!m.hasMatch()) qFatal("no match for %s in:\n%s", qPrintable(pattern), qPrintable(text));
    try {
        return std::stod(m.captured(1).toStdString());
    } catch (const std::exception&) {
        qFatal("not a number for %s in:\n%s", qPrintable(pattern), qPrintable(text));
    }
}
}  // namespace

class TestGridPanelExtras : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        useTestSettings("test_grid_panel_extras");
        QVERIFY(dir_.isValid());
    }

    void computedCheckedLeftOutAndCancelled() {
        const QString path = dir_.filePath("office.json");
        std::ofstream(path.toStdString()) << officeJson();
        MainWindow w(path);
        w.resize(1400, 900);
        w.show();
        GridPanel* panel = w.gridPanel();
        w.findChild<QDockWidget*>("gridDock")->raise();
        auto* cylindrical = child<QCheckBox>(*panel, "gridCylindrical");
        auto* surfaces = child<QCheckBox>(*panel, "gridRoomSurfaces");
        auto* compute = child<QPushButton>(*panel, "gridCompute");
        auto* status = child<QLabel>(*panel, "gridStatus");
        QVERIFY(!cylindrical->isEnabled() && !cylindrical->isChecked());  // the whole room: task areas only
        QVERIFY(!surfaces->isEnabled() && !surfaces->isChecked());
        auto* method = child<QComboBox>(*panel, "gridMethod");
        method->setCurrentIndex(method->findText("path"));
        child<QDoubleSpinBox>(*panel, "gridTarget")->setValue(10);

        // The desk: the 2021 entry asks both, so both are ticked; computed after the Em grid.
        choose(*panel, 1);
        QVERIFY(cylindrical->isEnabled() && cylindrical->isChecked());
        QVERIFY(surfaces->isEnabled() && surfaces->isChecked());
        QTest::mouseClick(compute, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(panel->isComputingExtras(), kTimeout);
        QVERIFY(figuresOf(*panel).contains("Ez, walls and ceiling: computing..."));
        QVERIFY2(status->text().contains("Computing Ez (9 points at 1.20 m above the floor), then the room's walls and ceiling"),
                 qPrintable(status->text()));
        QTRY_VERIFY_WITH_TIMEOUT(!panel->isComputing(), kTimeout);
        QString figures = figuresOf(*panel);
        const QString lux = R"(([0-9]+(?:\.[0-9])?) lx \+- [0-9.]+ lx)";
        const double ez = captured(figures, R"(\nEz at 1.20 m above the floor \(seated, floor of the scene's bounds\): Eavg )" + lux +
                                                R"(, Emin [0-9.]+ lx, U0 [0-9.]+ \+- [0-9.]+ \(9 points\))");
        const double walls = captured(figures, R"(\nwalls of the scene's bounds: Eavg )" + lux);
        const double ceiling = captured(figures, R"(\nceiling of the scene's bounds: Eavg )" + lux);
        const double eh = captured(figures, R"(^Eavg ([0-9.]+) lx)");
        // The lamp lights all of them directly; the checks carry the same figures, rounded.
        QVERIFY(ez > 0 && walls > 0 && ceiling > 0);
        const QString verdict = R"(: (met|borderline|not met) \(margin)";
        QVERIFY(std::abs(captured(figures, R"(\n  Ez ([0-9]+) lx \+- [0-9.]+ lx >= 150 lx)" + verdict) - ez) <= 0.5);
        QVERIFY(std::abs(captured(figures, R"(\n  Ewall ([0-9]+) lx \+- [0-9.]+ lx >= 150 lx)" + verdict) - walls) <= 0.5);
        QVERIFY(std::abs(captured(figures, R"(\n  Eceiling ([0-9]+) lx \+- [0-9.]+ lx >= 100 lx)" + verdict) - ceiling) <= 0.5);
        for (const char* u0 : {"U0,z", "U0,wall", "U0,ceiling"})
            captured(figures, QString(R"(\n  %1 ([0-9.]+) \+- [0-9.]+ >= 0.10)").arg(u0) + verdict);
        QVERIFY(std::abs(captured(figures, R"(\nmodelling Ez/Eh ([0-9.]+) \(guidance 0.30 to 0.60: )") - ez / eh) <= 0.006);
        QVERIFY2(status->text().contains("Ez, walls and ceiling in "), qPrintable(status->text()));
        QTest::qWait(100);
        w.findChild<QDockWidget*>("gridDock")->grab().save("grid_panel_extras_dock.png");
        panel->grab().save("grid_panel_extras_panel.png");  // all of it, as the dock scrolls it

        // Unticked: only the Em grid, and the requirement's Ez, walls and ceiling not computed.
        clickBox(cylindrical);
        clickBox(surfaces);
        QVERIFY(!cylindrical->isChecked() && !surfaces->isChecked());
        QTest::mouseClick(compute, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!panel->isComputing(), kTimeout);
        figures = figuresOf(*panel);
        for (const char* gone : {"Ez at", "walls of", "ceiling of", "modelling", "Ez, walls and ceiling"})
            QVERIFY2(!figures.contains(gone), qPrintable(figures));
        for (const char* check : {"  Ez not computed (>= 150 lx required)", "  U0,z not computed (>= 0.10 required)",
                                  "  Ewall not computed (>= 150 lx required)", "  Eceiling not computed (>= 100 lx required)"})
            QVERIFY2(figures.contains(check), qPrintable(figures));
        QVERIFY(!status->text().contains("Ez"));

        // The shelf has no activity: nothing ticked, but Ez may be added; shown, not checked.
        choose(*panel, 2);
        QVERIFY(cylindrical->isEnabled() && !cylindrical->isChecked() && !surfaces->isChecked());
        clickBox(cylindrical);
        QTest::mouseClick(compute, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!panel->isComputing(), kTimeout);
        figures = figuresOf(*panel);
        QVERIFY2(figures.contains(QRegularExpression(R"(\nEz at 1.20 m above the floor \(seated, floor of the scene's bounds\): Eavg [0-9.]+ lx .*\(4 points\))")),
                 qPrintable(figures));
        QVERIFY2(figures.contains("modelling Ez/Eh") && !figures.contains("walls of") && !figures.contains("  Ez "),
                 qPrintable(figures));
        // Back to the desk: its requirement's defaults again.
        choose(*panel, 0);
        QVERIFY(!cylindrical->isEnabled() && !cylindrical->isChecked());
        choose(*panel, 1);
        QVERIFY(cylindrical->isChecked() && surfaces->isChecked());

        // Cancelled while they compute: the Em figures stay, theirs are not computed.
        child<QDoubleSpinBox>(*panel, "gridTarget")->setValue(1);  // the walls take a while at 1%
        QTest::mouseClick(compute, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(panel->isComputingExtras(), kTimeout);
        QTest::mouseClick(child<QPushButton>(*panel, "gridCancel"), Qt::LeftButton);
        QVERIFY(!panel->isComputing());
        QVERIFY(compute->isEnabled() && !child<QPushButton>(*panel, "gridCancel")->isEnabled());
        QVERIFY(panel->result() && panel->result()->converged);
        figures = figuresOf(*panel);
        QVERIFY2(figures.contains("\nEz, walls and ceiling: cancelled, not computed") && !figures.contains("Ez at") &&
                     figures.contains("  Ez not computed (>= 150 lx required)") && figures.contains(QRegularExpression(R"(\n  Em [0-9]+ lx)")),
                 qPrintable(figures));
        QVERIFY2(status->text().contains("Cancelled: the EN 12464-1:2021 figures are not computed."), qPrintable(status->text()));

        // An edit of the light while they compute: done, the result is marked out of date.
        child<QDoubleSpinBox>(*panel, "gridTarget")->setValue(10);
        QTest::mouseClick(compute, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(panel->isComputingExtras(), kTimeout);
        Light brighter = w.document()->scene().lights[0];
        brighter.intensity = brighter.intensity * 2.0;
        w.document()->undoStack()->push(new EditLightCommand(w.document(), 0, brighter, 0, "brighter"));
        QTRY_VERIFY_WITH_TIMEOUT(!panel->isComputing(), kTimeout);
        QVERIFY(panel->resultOutOfDate());
        QVERIFY2(figuresOf(*panel).contains("\nEz at") && status->text().contains("The scene changed since this result"),
                 qPrintable(status->text()));
        w.setSaveQuestion([] { return QMessageBox::Discard; });
    }

private:
    QTemporaryDir dir_;
};

QTEST_MAIN(TestGridPanelExtras)
#include "test_grid_panel_extras.moc"
