// Small things of the window a designer tripped over (issue 40): the wheel over a dock scrolls it
// and never edits a field without the focus (ui/window/wheel_guard.h); Ctrl+Y redoes; the Help
// menu (ui/window/help_actions.h); the report's save dialog offers a file name, not a folder's.

#include "ui/io/file_dialogs.h"
#include "ui/properties/light_properties.h"
#include "ui/properties/luminaire_polar_plot.h"
#include "ui/scene_panels/outliner.h"
#include "ui/window/help_actions.h"
#include "ui/window/main_window.h"
#include "window_test_helpers.h"

#include <QDialog>
#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QScrollArea>
#include <QScrollBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QWheelEvent>
#include <QtTest>

using namespace lucerna;
using namespace lucerna::test;

namespace {
QString luminairePath() { return QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/luminaire.json"); }

// One notch of the wheel over the middle of `w`: down the page (a field's value down), or up.
void wheel(QWidget* w, bool down) {
    const QPointF at(w->width() / 2.0, w->height() / 2.0);
    QWheelEvent e(at, w->mapToGlobal(at), QPoint(), QPoint(0, down ? -120 : 120), Qt::NoButton, Qt::NoModifier,
                  Qt::NoScrollPhase, false);
    QApplication::sendEvent(w, &e);
}

int firstLuminaire(const Scene& scene) {
    for (size_t i = 0; i < scene.lights.size(); ++i)
        if (scene.lights[i].type == LightType::Luminaire) return int(i);
    return -1;
}
}  // namespace

class TestWindowConveniences : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void wheelScrollsTheDockNotTheField();
    void propertiesFitTheDefaultDock();
    void ctrlYRedoes();
    void helpMenu();
    void reportDialogOffersAFileName();
};

void TestWindowConveniences::initTestCase() { useTestSettings("test_window_conveniences"); }

void TestWindowConveniences::wheelScrollsTheDockNotTheField() {
    MainWindow w(luminairePath());
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    w.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    const int light = firstLuminaire(w.document()->scene());
    QVERIFY(light >= 0);
    w.outliner()->select(Outliner::Kind::Light, light);
    LightProperties* props = w.lightProperties();
    QDoubleSpinBox* tilt = props->tiltField();
    QVERIFY(tilt->isVisible());
    // The wheel does not focus the field (it would edit from the second notch on).
    QCOMPARE(tilt->focusPolicy(), Qt::StrongFocus);

    auto* scroll = qobject_cast<QScrollArea*>(w.findChild<QDockWidget*>("propertiesDock")->widget());
    QVERIFY(scroll);
    QScrollBar* bar = scroll->verticalScrollBar();
    // The luminaire's properties are taller than the dock: it scrolls (once the layouts settle).
    QTRY_VERIFY(bar->maximum() > 0);
    bar->setValue(0);
    QUndoStack* undo = w.document()->undoStack();
    const int steps = undo->count();
    const double tiltBefore = tilt->value();
    const V3d direction = w.document()->scene().lights[size_t(light)].direction;

    // Without the focus: the dock scrolls, the field and the light stay.
    QVERIFY(!tilt->hasFocus());
    wheel(tilt, true);
    QCOMPARE(tilt->value(), tiltBefore);
    QCOMPARE(undo->count(), steps);
    QCOMPARE(w.document()->scene().lights[size_t(light)].direction, direction);
    QCOMPARE_GT(bar->value(), 0);
    QVERIFY(!tilt->hasFocus());

    // Focused (clicked or tabbed into), the field takes the wheel: one step up, one undo step.
    tilt->setFocus();
    QTRY_VERIFY(tilt->hasFocus());
    const int scrolled = bar->value();
    wheel(tilt, false);
    QCOMPARE(tilt->value(), tiltBefore + tilt->singleStep());
    QCOMPARE(undo->count(), steps + 1);
    QVERIFY(!(w.document()->scene().lights[size_t(light)].direction == direction));
    QCOMPARE(bar->value(), scrolled);
    w.document()->markSaved();
}

// A luminaire of the office floor selected at the default layout of the window on a 1600 x 1000
// screen (1500 x 900, MainWindow's default size): every
// field of the Properties dock, the position's z and the polar plot among them, is in view
// without scrolling sideways.
void TestWindowConveniences::propertiesFitTheDefaultDock() {
    MainWindow w(QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/office_floor.json"));
    w.resize(1500, 900);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    trigger(w, "actionResetLayout");
    w.outliner()->select(Outliner::Kind::Light, firstLuminaire(w.document()->scene()));
    QTest::qWait(50);  // the layouts settle
    auto* scroll = qobject_cast<QScrollArea*>(w.findChild<QDockWidget*>("propertiesDock")->widget());
    QVERIFY(scroll);
    QCOMPARE_LT(scroll->width(), 300);  // a narrow dock, as the default layout makes it
    QVERIFY(scroll->viewport()->width() > 0);
    scroll->grab().save("window_conveniences_properties.png");
    // Whatever is too wide, named, for the failure's message.
    QStringList wide;
    const QRect view = scroll->viewport()->rect();
    const auto across = [&](QWidget* c) { return c->mapTo(scroll->viewport(), QPoint(0, 0)).x(); };
    for (QWidget* c : w.lightProperties()->findChildren<QWidget*>())
        if (c->isVisible() && (across(c) < 0 || across(c) + c->width() > view.width()))
            wide << QStringLiteral("%1 %2 at x %3 width %4")
                        .arg(c->metaObject()->className(), c->objectName())
                        .arg(c->mapTo(scroll->viewport(), QPoint(0, 0)).x())
                        .arg(c->width());
    QVERIFY2(wide.isEmpty(), qPrintable(QStringLiteral("viewport %1 px: ").arg(view.width()) + wide.join("; ")));
    QCOMPARE(scroll->horizontalScrollBar()->maximum(), 0);
    QVERIFY(w.lightProperties()->positionFields()[2]->isVisible());
    QVERIFY(w.lightProperties()->polarPlot()->isVisible());
    QCOMPARE_GE(w.lightProperties()->polarPlot()->canvas()->width(), 150);
}

void TestWindowConveniences::ctrlYRedoes() {
    MainWindow w(luminairePath());
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    w.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    auto* redo = w.findChild<QAction*>("actionRedo");
    QVERIFY(redo);
    QVERIFY(redo->shortcuts().contains(QKeySequence(Qt::CTRL | Qt::Key_Y)));
    for (const QKeySequence& k : QKeySequence::keyBindings(QKeySequence::Redo)) QVERIFY(redo->shortcuts().contains(k));

    const size_t lights = w.document()->scene().lights.size();
    trigger(w, "actionAddPointLight");
    QCOMPARE(w.document()->scene().lights.size(), lights + 1);
    QWidget* focus = w.outliner();
    focus->setFocus();
    QTRY_COMPARE(QApplication::focusWidget(), focus);
    QTest::keyClick(focus, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(w.document()->scene().lights.size(), lights);
    QTest::keyClick(focus, Qt::Key_Y, Qt::ControlModifier);
    QCOMPARE(w.document()->scene().lights.size(), lights + 1);
    // The platform's key too.
    QTest::keyClick(focus, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(w.document()->scene().lights.size(), lights);
    QTest::keyClick(focus, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(w.document()->scene().lights.size(), lights + 1);
    w.document()->markSaved();
}

void TestWindowConveniences::helpMenu() {
    MainWindow w(luminairePath());
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QMenu* help = nullptr;
    for (QAction* a : w.menuBar()->actions())
        if (a->menu() && a->text() == "&Help") help = a->menu();
    QVERIFY(help);

    // Keyboard Shortcuts: read from the actions, so a shortcut given to an action shows.
    auto* helpActions = w.findChild<HelpActions*>();
    QVERIFY(helpActions);
    const auto find = [&](const QString& command) -> std::optional<ShortcutRow> {
        for (const ShortcutRow& r : helpActions->shortcutRows())
            if (r.command == command) return r;
        return std::nullopt;
    };
    const auto redo = find("Redo");
    QVERIFY(redo);
    QCOMPARE(redo->place, QString("Edit"));
    QVERIFY2(redo->keys.contains("Ctrl+Y") && redo->keys.contains("Ctrl+Shift+Z"), qPrintable(redo->keys));
    QVERIFY(find("Save As...") && find("Save As...")->keys == "Ctrl+Shift+S");
    QVERIFY(!find("Project Settings..."));  // no shortcut, no row
    w.findChild<QAction*>("actionProjectSettings")->setShortcut(QKeySequence("Ctrl+Alt+J"));
    QVERIFY(find("Project Settings...") && find("Project Settings...")->keys == "Ctrl+Alt+J");
    trigger(w, "actionKeyboardShortcuts");
    auto* shortcuts = w.findChild<QDialog*>("shortcutsDialog");
    QVERIFY(shortcuts && shortcuts->isVisible());
    auto* table = shortcuts->findChild<QTableWidget*>("shortcutsTable");
    QCOMPARE(table->rowCount(), int(helpActions->shortcutRows().size()));
    QVERIFY(!table->findItems("Project Settings...", Qt::MatchExactly).isEmpty());
    shortcuts->close();

    // User Guide: the README, as formatted text.
    QVERIFY(!HelpActions::userGuidePath().isEmpty());
    trigger(w, "actionUserGuide");
    auto* guide = w.findChild<QDialog*>("userGuideDialog");
    QVERIFY(guide && guide->isVisible());
    const QString text = guide->findChild<QTextBrowser*>("userGuideText")->toPlainText();
    QVERIFY2(text.startsWith("Lucerna"), qPrintable(text.left(80)));  // "# Lucerna" as a heading
    QVERIFY(text.contains("Command line"));
    guide->close();

    // About: the version and the libraries.
    trigger(w, "actionAbout");
    auto* about = w.findChild<QDialog*>("aboutDialog");
    QVERIFY(about && about->isVisible());
    const QString aboutText = about->findChild<QLabel*>("aboutText")->text();
    QVERIFY2(QRegularExpression("Lucerna \\d+\\.\\d+\\.\\d+").match(aboutText).hasMatch(), qPrintable(aboutText));
    QVERIFY2(aboutText.contains(QStringLiteral("Qt %1").arg(qVersion())), qPrintable(aboutText));
    QVERIFY2(QRegularExpression("Embree \\d").match(aboutText).hasMatch(), qPrintable(aboutText));
    about->close();
}

void TestWindowConveniences::reportDialogOffersAFileName() {
    QTemporaryDir dir;
    const QString scene = dir.filePath("my office.json");
    QVERIFY(QFile::copy(luminairePath(), scene));
    // The scene's luminaire and mesh files, beside it as in the bundled folder.
    for (const char* folder : {"luminaires", "meshes"})
        QVERIFY(QFile::link(QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/") + folder, dir.filePath(folder)));
    MainWindow w(scene);
    QString start;
    int asked = 0;
    w.fileDialogs()->replace([&](FileDialogs::Mode, const QString&, const QString& at, const QString&) {
        start = at;
        ++asked;
        return QString();  // cancelled
    });
    trigger(w, "actionExportReport");
    QCOMPARE(asked, 1);
    QCOMPARE(QFileInfo(start).fileName(), QString("my office.pdf"));
    QCOMPARE(QFileInfo(start).absoluteDir(), QDir(dir.path()));
    // An untitled scene: report.pdf in a folder that exists (never a folder's name as the file's).
    w.newScene();
    trigger(w, "actionExportReport");
    QCOMPARE(asked, 2);
    QCOMPARE(QFileInfo(start).fileName(), QString("report.pdf"));
    QVERIFY2(QFileInfo(QFileInfo(start).absolutePath()).isDir(), qPrintable(start));
    QCOMPARE(suggestedFileName("/a/b/office_floor.json", "png", "render"), QString("office_floor.png"));
    QCOMPARE(suggestedFileName("", "pdf", "report"), QString("report.pdf"));
}

QTEST_MAIN(TestWindowConveniences)
#include "test_window_conveniences.moc"
