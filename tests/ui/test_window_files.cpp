// The window's file handling and steadiness, driven as a user would: File > New, Import Model
// into a new scene or the open one, file dialogs that open in the scene's folder, Export PNG at
// full resolution, recovery offered only after an unclean run, a saved layout that cannot squeeze
// the viewport (and View > Reset Layout), shortcuts from any dock, fly keys only with the
// viewport's focus, a light drag that updates the preview before the release, no build path in
// the status bar. Screenshots window_files_*.png in the build's tests/ folder.

#include "core/scene/scene_io.h"
#include "ui/document/autosave.h"
#include "ui/compare/compare_view.h"
#include "ui/rendering/converging_render.h"
#include "ui/io/file_dialogs.h"
#include "ui/rendering/live_preview.h"
#include "ui/window/main_window.h"
#include "ui/rendering/render_panel.h"
#include "ui/viewport/viewport.h"
#include "window_test_helpers.h"

#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>

using namespace lucerna;
using namespace lucerna::test;

namespace {
constexpr int kTimeout = 30000;  // ms; generous for a loaded machine, never a timing assertion

// A table of two quads (its top, 0.75 m up, and a leg board) as OBJ with its MTL, in metres.
void writeModel(const QString& folder) {
    QFile obj(QDir(folder).filePath("table.obj")), mtl(QDir(folder).filePath("table.mtl"));
    QVERIFY(obj.open(QIODevice::WriteOnly) && mtl.open(QIODevice::WriteOnly));
    obj.write("mtllib table.mtl\n"
              "v -0.6 0.75 -0.4\nv 0.6 0.75 -0.4\nv 0.6 0.75 0.4\nv -0.6 0.75 0.4\n"
              "v -0.1 0 0\nv 0.1 0 0\nv 0.1 0.75 0\nv -0.1 0.75 0\n"
              "usemtl wood\nf 1 4 3 2\nf 5 6 7 8\n");
    mtl.write("newmtl wood\nKd 0.5 0.3 0.1\n");
}

std::shared_ptr<const LiveFrame> previewOf(MainWindow& w, const SceneSnapshot& want) {
    const auto ok = [&] { return w.livePreview()->frame() && w.livePreview()->frame()->scene == want; };
    if (!QTest::qWaitFor(ok, kTimeout)) return nullptr;
    return w.livePreview()->frame();
}

// "window 1500, viewport 700, outlinerDock 300 (min 280), ...": what a failed layout check shows.
QString widths(MainWindow& w) {
    QString text = QString("window %1, viewport %2").arg(w.width()).arg(w.viewport()->width());
    for (QDockWidget* d : w.findChildren<QDockWidget*>())
        if (d->isVisible())
            text += QString(", %1 %2 (min %3)").arg(d->objectName()).arg(d->width()).arg(d->minimumSizeHint().width());
    return text;
}

bool viewportHasHalf(MainWindow& w) { return w.viewport()->width() >= w.width() / 2; }

// The window as window_files_NAME.png.
void windowShot(QWidget& w, const QString& name) { screenshot(w, QString("window_files_%1.png").arg(name)); }

// The last file dialog the window asked, answered with `answer`.
struct DialogLog {
    FileDialogs::Mode mode{};
    QString caption, folder;
    int asked = 0;
    QString answer;
    void attach(MainWindow& w) {
        w.fileDialogs()->replace([this](FileDialogs::Mode m, const QString& c, const QString& f, const QString&) {
            mode = m, caption = c, folder = f;
            ++asked;
            return answer;
        });
    }
};

QString copyCornell(const QString& folder, const QString& name) {
    const QString path = QDir(folder).filePath(name);
    QFile::remove(path);
    QFile::copy(cornellPath(), path);
    QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);
    return path;
}
}  // namespace

class TestWindowFiles : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void newSceneAndImportIntoEither();
    void exportPngAtFullResolution();
    void recoveryOnlyAfterAnUncleanRun();
    void savedLayoutKeepsHalfForTheViewport();
    void shortcutsFromAnyDock();
    void lightDragUpdatesThePreviewBeforeRelease();

private:
    QTemporaryDir dir_;
};

void TestWindowFiles::initTestCase() {
    useTestSettings("test_window_files");
    QVERIFY(dir_.isValid());
}

void TestWindowFiles::newSceneAndImportIntoEither() {
    const QString folder = dir_.filePath("scenes");
    QVERIFY(QDir().mkpath(folder));
    writeModel(folder);
    const QString scenePath = copyCornell(folder, "room.json");
    MainWindow w(scenePath);
    DialogLog dialogs;
    dialogs.attach(w);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    // No build path in the status bar: the scene's file name.
    QCOMPARE(w.statusBar()->currentMessage(), QString("Opened room.json"));
    MainWindow bundled(cornellPath());
    QVERIFY2(!bundled.statusBar()->currentMessage().contains('/'), qPrintable(bundled.statusBar()->currentMessage()));
    // Dialogs for a bundled scene open in the user's documents (home without a documents folder,
    // whose name a save dialog would otherwise offer as the file's), not in the installation.
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    QCOMPARE(bundled.fileDialogs()->folder(), QFileInfo(documents).isDir() ? documents : QDir::homePath());

    // Every dialog opens in the scene's folder (Save As here, cancelled).
    trigger(w, "actionSaveAs");
    QCOMPARE(dialogs.asked, 1);
    QCOMPARE(dialogs.mode, FileDialogs::Mode::Save);
    QCOMPARE(QDir(dialogs.folder), QDir(folder));

    // Import Model asks where: into this scene (one undo step) ...
    int asked = 0;
    MainWindow::ImportTarget target = MainWindow::ImportTarget::OpenScene;
    w.setImportQuestion([&] {
        ++asked;
        return target;
    });
    dialogs.answer = QDir(folder).filePath("table.obj");
    const size_t objects = w.document()->scene().objects.size();
    const int undoSteps = w.document()->undoStack()->count();
    trigger(w, "actionImportModel");
    QCOMPARE(asked, 1);
    QCOMPARE(QDir(dialogs.folder), QDir(folder));
    QCOMPARE(w.document()->scene().objects.size(), objects + 1);
    QCOMPARE(w.document()->undoStack()->count(), undoSteps + 1);
    QCOMPARE(QString::fromStdString(w.document()->path()), QFileInfo(scenePath).absoluteFilePath());
    // ... or into a new, untitled scene: the model on a floor, framed by the camera.
    target = MainWindow::ImportTarget::NewScene;
    w.setSaveQuestion([] { return QMessageBox::Discard; });
    trigger(w, "actionImportModel");
    QCOMPARE(asked, 2);
    const Scene& fresh = w.document()->scene();
    QCOMPARE(fresh.objects.size(), size_t(2));
    QCOMPARE(fresh.objects[0].name, std::string("floor"));
    QVERIFY(w.document()->path().empty());
    QVERIFY(w.document()->isModified());
    QCOMPARE(fresh.objects[0].worldMesh->vertices[0].y, 0.0);  // the floor under the table's leg
    QCOMPARE_LT((fresh.camera.target - V3d(0, 0.375, 0)).length(), 1e-9);
    QCOMPARE(fresh.lights.size(), size_t(1));  // the model has none: the new scene's stays
    QCOMPARE_GT(fresh.lights[0].position.y, 0.75);
    QVERIFY(previewOf(w, w.document()->snapshot()));
    windowShot(w, "import_new_scene");
    // Cancel changes nothing.
    target = MainWindow::ImportTarget::Cancel;
    const SceneSnapshot before = w.document()->snapshot();
    trigger(w, "actionImportModel");
    QCOMPARE(w.document()->snapshot(), before);

    // File > New: an untitled scene with a floor and a light.
    trigger(w, "actionNew");  // unsaved changes: the save question (Discard) comes first
    QCOMPARE(w.document()->scene().objects.size(), size_t(1));
    QCOMPARE(w.document()->scene().lights.size(), size_t(1));
    QVERIFY(w.document()->path().empty());
    QVERIFY(!w.document()->isModified());
    QVERIFY(previewOf(w, w.document()->snapshot()));
    windowShot(w, "new_scene");
    // A click that places nothing says why: the sky above the floor has no surface.
    QVERIFY(w.viewport()->setTool(Viewport::Tool::PlacePoint));
    const QRectF image = w.viewport()->imageRect();
    click(w.viewport(), image.topLeft() + QPointF(image.width() / 2, 4));
    QCOMPARE(w.document()->scene().lights.size(), size_t(1));
    QVERIFY2(w.statusBar()->currentMessage().contains("No surface there"), qPrintable(w.statusBar()->currentMessage()));
    w.viewport()->setTool(Viewport::Tool::Navigate);
    // Untitled: the next dialog opens where the last one ended (cancelled).
    dialogs.answer.clear();
    trigger(w, "actionOpen");
    QCOMPARE(QDir(dialogs.folder), QDir(folder));
}

void TestWindowFiles::exportPngAtFullResolution() {
    MainWindow w;
    w.newScene();  // 640 x 480: the preview draws 400 x 300
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    const Camera& c = w.document()->scene().camera;
    const auto preview = previewOf(w, w.document()->snapshot());
    QVERIFY(preview);
    QCOMPARE_LT(preview->image.width, c.width);
    QTRY_VERIFY_WITH_TIMEOUT(w.convergingRender()->frame() != nullptr, kTimeout);
    const QString path = dir_.filePath("full.png");
    QVERIFY2(w.exportPng(path), qPrintable(w.lastError()));
    const QImage png(path);
    // The converged image's size (the camera's), not the preview's.
    QCOMPARE(png.size(), QSize(c.width, c.height));
    // The lit floor below, the black beyond it above.
    // The lamp is a plausible 3,000 lm (about 40 lx on the floor below it): grey 12 of 255 at
    // exposure 0, not bright, but never the 0 of an unlit pixel.
    QCOMPARE_GT(qGray(png.pixel(c.width / 2, c.height * 3 / 4)), 5);
    QCOMPARE(qGray(png.pixel(c.width / 2, 2)), 0);
}

void TestWindowFiles::recoveryOnlyAfterAnUncleanRun() {
    const QString recovery = dir_.filePath("recovery");
    const QString a = copyCornell(dir_.path(), "a.json"), b = copyCornell(dir_.path(), "b.json");
    const QString autosaved = QDir(recovery).filePath("autosave.json");
    const auto askedAtStart = [&](const QString& scene) {
        MainWindow w(scene);
        int asked = 0;
        w.setRecoveryQuestion([&] {
            ++asked;
            return QMessageBox::No;
        });
        w.startAutosave(recovery, 3600 * 1000);
        w.setSaveQuestion([] { return QMessageBox::Discard; });
        w.close();  // a clean close: nothing is offered at the next start
        return asked;
    };
    const auto editAndAutosave = [&](MainWindow& w) {
        w.startAutosave(recovery, 3600 * 1000);
        trigger(w, "actionAddPointLight");
        QVERIFY(w.autosave()->writeNow());
        QVERIFY(QFile::exists(autosaved));
    };

    // A crash after an autosave newer than the scene: offered.
    {
        MainWindow w(a);
        editAndAutosave(w);
    }  // no close(): a crash
    QCOMPARE(askedAtStart(a), 1);

    // A run that closed cleanly (its recovery file left behind anyway, as by a second window):
    // not offered.
    {
        MainWindow w(a);
        editAndAutosave(w);
        const QString kept = dir_.filePath("kept.json"), keptOrigin = dir_.filePath("kept.origin");
        QFile::remove(kept);
        QFile::remove(keptOrigin);
        QVERIFY(QFile::copy(autosaved, kept));
        QVERIFY(QFile::copy(QDir(recovery).filePath("autosave.origin"), keptOrigin));
        w.setSaveQuestion([] { return QMessageBox::Discard; });
        QVERIFY(w.close());
        QVERIFY(!QFile::exists(autosaved));
        QVERIFY(QFile::copy(kept, autosaved));
        QVERIFY(QFile::copy(keptOrigin, QDir(recovery).filePath("autosave.origin")));
    }
    QCOMPARE(askedAtStart(a), 0);

    // A clean switch to another scene, then a crash: the first scene's changes were let go.
    {
        MainWindow w(a);
        editAndAutosave(w);
        QVERIFY(w.openFile(b));
        QVERIFY(!QFile::exists(autosaved));
    }
    QCOMPARE(askedAtStart(a), 0);

    // A crash, but the scene's file was saved after the autosave (by another window): stale.
    {
        MainWindow w(a);
        editAndAutosave(w);
    }
    QFile scene(a);
    QVERIFY(scene.open(QIODevice::ReadWrite));
    QVERIFY(scene.setFileTime(QFileInfo(autosaved).lastModified().addSecs(10), QFileDevice::FileModificationTime));
    scene.close();
    QCOMPARE(askedAtStart(a), 0);
    QVERIFY(!QFile::exists(autosaved));
}

void TestWindowFiles::savedLayoutKeepsHalfForTheViewport() {
    QSettings().clear();  // the first start
    {
        MainWindow w(cornellPath());
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        // The first-start layout already leaves the viewport half the window.
        QTRY_VERIFY2_WITH_TIMEOUT(viewportHasHalf(w), qPrintable(widths(w)), 2000);
        // Docks dragged wide: the viewport squeezed, and saved so at the close.
        w.resizeDocks({w.findChild<QDockWidget*>("outlinerDock"), w.findChild<QDockWidget*>("renderDock")},
                      {w.width() / 3, w.width() / 2}, Qt::Horizontal);
        QTRY_VERIFY2_WITH_TIMEOUT(w.viewport()->width() < w.width() / 2, qPrintable(widths(w)), kTimeout);
        QVERIFY(w.close());
    }
    MainWindow w(cornellPath());
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QTRY_VERIFY2_WITH_TIMEOUT(viewportHasHalf(w), qPrintable(widths(w)), 2000);
    windowShot(w, "layout_restored");
    // View > Reset Layout: docks squeezed again, one floating and one hidden, then the defaults.
    auto* grid = w.findChild<QDockWidget*>("gridDock");
    auto* outliner = w.findChild<QDockWidget*>("outlinerDock");
    w.resizeDocks({outliner, w.findChild<QDockWidget*>("renderDock")}, {w.width() / 3, w.width() / 2}, Qt::Horizontal);
    grid->setFloating(true);
    w.findChild<QDockWidget*>("propertiesDock")->hide();
    QTRY_VERIFY_WITH_TIMEOUT(w.viewport()->width() < w.width() / 2, kTimeout);
    trigger(w, "actionResetLayout");
    QTRY_VERIFY2_WITH_TIMEOUT(viewportHasHalf(w), qPrintable(widths(w)), 2000);
    QVERIFY(!grid->isFloating());
    QVERIFY(w.findChild<QDockWidget*>("propertiesDock")->isVisible());
    windowShot(w, "layout_reset");
}

void TestWindowFiles::shortcutsFromAnyDock() {
    MainWindow w(cornellPath());
    DialogLog dialogs;
    dialogs.attach(w);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    w.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    QCOMPARE(w.findChild<QAction*>("actionSaveAs")->shortcut(), QKeySequence("Ctrl+Shift+S"));
    // The focus in the comparison dock.
    auto* compareDock = w.findChild<QDockWidget*>("compareDock");
    compareDock->raise();
    QWidget* inDock = nullptr;
    for (QWidget* c : w.compareView()->findChildren<QWidget*>())
        if (c->isVisible() && c->focusPolicy() != Qt::NoFocus) {
            inDock = c;
            break;
        }
    QVERIFY(inDock);
    inDock->setFocus();
    QTRY_COMPARE(QApplication::focusWidget(), inDock);
    QTest::keyClick(inDock, Qt::Key_S, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(dialogs.asked, 1);
    QCOMPARE(dialogs.caption, QString("Save scene"));
    QTest::keyClick(inDock, Qt::Key_E, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(dialogs.asked, 2);
    QVERIFY2(dialogs.caption.contains("picture"), qPrintable(dialogs.caption));

    // Letters fly the camera only while the viewport has the focus: a click in a dock (on a
    // label that takes no focus itself) takes it away.
    Viewport* viewport = w.viewport();
    viewport->setFocus();
    QTRY_COMPARE(QApplication::focusWidget(), static_cast<QWidget*>(viewport));
    Camera camera = w.document()->scene().camera;
    QTest::keyClick(viewport, Qt::Key_W);
    QVERIFY(!(w.document()->scene().camera == camera));
    camera = w.document()->scene().camera;
    w.findChild<QDockWidget*>("renderDock")->raise();
    QLabel* label = nullptr;
    for (QLabel* l : w.renderPanel()->findChildren<QLabel*>())
        if (l->isVisible() && l->focusPolicy() == Qt::NoFocus) {
            label = l;
            break;
        }
    QVERIFY(label);
    QTest::mouseClick(label, Qt::LeftButton, {}, QPoint(2, 2));
    QVERIFY(QApplication::focusWidget() != viewport);
    QWidget* focused = QApplication::focusWidget() ? QApplication::focusWidget() : static_cast<QWidget*>(&w);
    QTest::keyClick(focused, Qt::Key_W);
    QVERIFY(w.document()->scene().camera == camera);

    // Ctrl+Q from the comparison dock closes the window (the flight above is let go).
    w.setSaveQuestion([] { return QMessageBox::Discard; });
    inDock->setFocus();
    QTest::keyClick(inDock, Qt::Key_Q, Qt::ControlModifier);
    QTRY_VERIFY(!w.isVisible());
}

void TestWindowFiles::lightDragUpdatesThePreviewBeforeRelease() {
    MainWindow w(cornellPath());
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    trigger(w, "actionAddPointLight");
    Viewport* viewport = w.viewport();
    QVERIFY(previewOf(w, w.document()->snapshot()));
    // With the light's fields in the properties dock, the docks still leave the viewport half.
    QVERIFY2(viewportHasHalf(w), qPrintable(widths(w)));
    QTRY_VERIFY_WITH_TIMEOUT(viewport->lightMarker(0).has_value(), kTimeout);
    const QPointF from = *viewport->lightMarker(0);
    const V3d start = w.document()->scene().lights[0].position;
    const int steps = w.document()->undoStack()->count();

    // Press and move, no release.
    sendMouse(viewport, QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    for (int i = 1; i <= 4; ++i)
        sendMouse(viewport, QEvent::MouseMove, from + QPointF(-15 * i, 8 * i), Qt::NoButton, Qt::LeftButton);
    const V3d during = w.document()->scene().lights[0].position;
    QVERIFY2((during - start).length() > 1e-3, "the document's light moves during the drag");
    // The preview is asked for, and shows, a frame of the moved light while the button is down.
    const SceneSnapshot moved = w.document()->snapshot();
    QVERIFY(moved->lights[0].position == during);
    QVERIFY(previewOf(w, moved));
    windowShot(w, "light_drag_before_release");
    // One more step, then the release: one undo step for the whole drag.
    sendMouse(viewport, QEvent::MouseMove, from + QPointF(-70, 40), Qt::NoButton, Qt::LeftButton);
    sendMouse(viewport, QEvent::MouseButtonRelease, from + QPointF(-70, 40), Qt::LeftButton, Qt::NoButton);
    QCOMPARE(w.document()->undoStack()->count(), steps + 1);
    w.document()->undoStack()->undo();
    QVERIFY(w.document()->scene().lights[0].position == start);
}

QTEST_MAIN(TestWindowFiles)
#include "test_window_files.moc"
