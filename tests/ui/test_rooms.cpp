// Rooms in the window (README, "Rooms"), clicked through as a designer would: an L-shaped room
// drawn corner by corner in the plan (the new scene's floor goes with it), a window added to a
// wall, the room's height edited, each one undo step undone and redone; a room added from the
// menu around the scene; imported objects that close a shell marked as a room, saved and opened
// again, deleted; and the refusals, each a line that says why. Screenshots of the plan, the
// dialogs and the 3D view go to the working folder.

#include "core/scene/room_edit.h"
#include "core/scene/scene_io.h"
#include "ui/plan/plan_view.h"
#include "ui/plan/room_drawing.h"
#include "ui/rendering/live_preview.h"
#include "ui/scene_panels/opening_dialog.h"
#include "ui/scene_panels/outliner.h"
#include "ui/scene_panels/room_dialog.h"
#include "ui/window/main_window.h"
#include "ui/viewport/viewport.h"
#include "ui/window/room_actions.h"
#include "window_test_helpers.h"

#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QToolButton>
#include <QtTest>

using namespace lucerna;
using namespace lucerna::test;

namespace {
// Closes the dialog when the check that opened it returns, also early on a failed check (a
// dialog left open would hold the test until its watchdog).
struct Closes {
    QDialog* dialog;
    ~Closes() {
        if (dialog && dialog->isVisible()) dialog->reject();
    }
};

void pressOk(QDialog* dialog) {
    QPushButton* ok = dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
    QTest::mouseClick(ok, Qt::LeftButton);
}

const Object* named(const Scene& scene, const std::string& name) {
    for (const Object& o : scene.objects)
        if (o.name == name) return &o;
    return nullptr;
}

double area(const Object& o) {
    double sum = 0;
    for (const V3i& t : o.worldMesh->triangles) {
        const V3d& a = o.worldMesh->vertices[size_t(t.x)];
        sum += 0.5 * (o.worldMesh->vertices[size_t(t.y)] - a).cross(o.worldMesh->vertices[size_t(t.z)] - a).length();
    }
    return sum;
}

// The L: 7 x 5 m less a 3 x 2 m notch (29 m²), around the new scene's light at the origin.
const PlanPolygon kL{{-3, -2}, {4, -2}, {4, 1}, {1, 1}, {1, 3}, {-3, 3}};
}  // namespace

class TestRooms : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { useTestSettings("test_rooms"); }

    void drawAddWindowEditAndUndo() {
        MainWindow w(cornellPath());
        w.setSaveQuestion([] { return QMessageBox::Discard; });  // also when a check fails early
        w.resize(1400, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        trigger(w, "actionNew");
        trigger(w, "actionViewPlan");
        Document* doc = w.document();
        QUndoStack* undo = doc->undoStack();
        PlanView* plan = w.planView();
        QTest::qWait(100);
        plan->fitToScene();
        const int start = undo->count();
        const Scene before = doc->scene();
        QCOMPARE(before.objects.size(), size_t(1));  // the new scene's floor

        // Drawn in the plan corner by corner; a stray corner taken back with Backspace.
        QToolButton* tool = plan->roomDrawing()->button();
        QTest::mouseClick(tool, Qt::LeftButton);
        QVERIFY(tool->isChecked());
        for (const V2d& c : kL) click(plan, plan->widgetOf(V3d(c.x, 0, c.y)));
        click(plan, plan->widgetOf(V3d(0, 0, 2)));
        QCOMPARE(plan->roomDrawing()->cornersBeingDrawn().size(), size_t(7));
        plan->setFocus();
        QTest::keyClick(plan, Qt::Key_Backspace);
        QCOMPARE(plan->roomDrawing()->cornersBeingDrawn().size(), size_t(6));
        plan->grab().save("room_drawing.png");
        bool filled = false;
        QTimer::singleShot(0, [&] {
            auto* dialog = qobject_cast<RoomDialog*>(QApplication::activeModalWidget());
            const Closes closes{dialog};
            QVERIFY(dialog);
            QCOMPARE(dialog->cornerField(1, 0)->value(), 4.0);
            QCOMPARE(dialog->cornerField(4, 1)->value(), 3.0);
            auto* name = dialog->findChild<QLineEdit*>("roomName");
            name->selectAll();
            QTest::keyClicks(name, "office");
            typeAndTab(dialog->findChild<QDoubleSpinBox*>("roomHeight"), 2.8);
            typeAndTab(dialog->findChild<QDoubleSpinBox*>("roomWallReflectance"), 60);
            const QString summary = dialog->findChild<QLabel*>("roomSummary")->text();
            QVERIFY2(summary.contains("6 corners: floor 29.00 m², walls 67.20 m²"), qPrintable(summary));
            dialog->grab().save("room_dialog.png");
            filled = true;
            pressOk(dialog);
        });
        click(plan, plan->widgetOf(V3d(-3, 0, -2)));  // the first corner again closes the outline
        QVERIFY(filled);
        QVERIFY(!tool->isChecked());
        {
            const Scene& s = doc->scene();
            QCOMPARE(s.rooms.size(), size_t(1));
            QCOMPARE(s.rooms[0].name, std::string("office"));
            QVERIFY(s.rooms[0].outline == kL);
            QCOMPARE(s.rooms[0].height, 2.8);
            // Floor, ceiling, six walls; the new scene's floor and its material gone with it.
            QCOMPARE(s.objects.size(), size_t(8));
            for (const Object& o : s.objects) QCOMPARE(o.room, std::string("office"));
            QVERIFY(!s.findMaterial("floor"));
            QCOMPARE(s.findMaterial("office walls")->albedo, Rgbd(0.6, 0.6, 0.6));
            QVERIFY(std::abs(area(*named(s, "office floor")) - 29) < 1e-9);
        }
        QCOMPARE(undo->count(), start + 1);
        QVERIFY(w.statusBar()->currentMessage().contains("the new scene's floor under it is removed"));

        // The outliner: the room, its surfaces under it.
        Outliner* outliner = w.outliner();
        QTreeWidgetItem* rooms = outliner->heading(Outliner::Kind::Room);
        QCOMPARE(rooms->childCount(), 1);
        QCOMPARE(rooms->child(0)->text(0), QString("office"));
        QCOMPARE(rooms->child(0)->text(1), QString("Room, 29.0 m²"));
        QCOMPARE(rooms->child(0)->childCount(), 8);
        QCOMPARE(outliner->heading(Outliner::Kind::Object)->childCount(), 0);
        QCOMPARE(outliner->selection().kind, Outliner::Kind::Room);

        // A window in wall 1 (7 m along z = -2): first past the wall's end (refused in the
        // dialog, with the reason), then where it fits.
        bool refused = false;
        QTimer::singleShot(0, [&] {
            auto* dialog = qobject_cast<OpeningDialog*>(QApplication::activeModalWidget());
            const Closes closes{dialog};
            QVERIFY(dialog);
            auto* wall = dialog->findChild<QComboBox*>("openingWall");
            QCOMPARE(wall->itemText(0), QString("Wall 1 (7.00 m)"));
            wall->setCurrentIndex(0);
            typeAndTab(dialog->findChild<QDoubleSpinBox*>("openingWidth"), 2);
            typeAndTab(dialog->findChild<QDoubleSpinBox*>("openingOffset"), 6);
            typeAndTab(dialog->findChild<QDoubleSpinBox*>("openingSill"), 0.9);
            typeAndTab(dialog->findChild<QDoubleSpinBox*>("openingHeight"), 1.4);
            typeAndTab(dialog->findChild<QDoubleSpinBox*>("openingTransmittance"), 65);
            pressOk(dialog);
            const QString problem = dialog->findChild<QLabel*>("openingProblem")->text();
            refused = dialog->isVisible() && problem == "the window does not fit wall 1, which is 7 long: offset 6 + width 2 = 8";
            QVERIFY2(refused, qPrintable(problem));
            typeAndTab(dialog->findChild<QDoubleSpinBox*>("openingOffset"), 2.5);
            dialog->grab().save("opening_dialog.png");
            pressOk(dialog);
        });
        trigger(w, "actionAddOpening");
        QVERIFY(refused);
        {
            const Scene& s = doc->scene();
            QCOMPARE(s.rooms[0].openings.size(), size_t(1));
            const RoomOpening& o = s.rooms[0].openings[0];
            QCOMPARE(o.type, OpeningType::Window);
            QCOMPARE(o.wall, 1);
            QCOMPARE(o.offset, 2.5);
            QCOMPARE(o.width, 2.0);
            const Material* glazing = s.findMaterial(o.glazing);
            QVERIFY(glazing && glazing->type == MaterialType::Glazing && glazing->transmittance == Rgbd(0.65, 0.65, 0.65));
            QCOMPARE(s.objects.size(), size_t(9));  // and the pane
            QVERIFY(std::abs(area(*named(s, "office wall 1")) - (7 * 2.8 - 2 * 1.4)) < 1e-9);
            QVERIFY(std::abs(area(*named(s, "office window 1")) - 2 * 1.4) < 1e-9);
        }
        QCOMPARE(undo->count(), start + 2);
        QCOMPARE(outliner->selection().kind, Outliner::Kind::Opening);
        QCOMPARE(outliner->roomItem(0)->child(9)->text(0), QString("window 1"));  // after the 9 surfaces

        // The height, edited in the room's dialog.
        outliner->select(Outliner::Kind::Room, 0);
        QTimer::singleShot(0, [&] {
            auto* dialog = qobject_cast<RoomDialog*>(QApplication::activeModalWidget());
            const Closes closes{dialog};
            QVERIFY(dialog);
            QCOMPARE(dialog->findChild<QDoubleSpinBox*>("roomWallReflectance")->value(), 60.0);
            typeAndTab(dialog->findChild<QDoubleSpinBox*>("roomHeight"), 3.2);
            pressOk(dialog);
        });
        trigger(w, "actionEditRoom");
        {
            const Scene& s = doc->scene();
            QCOMPARE(s.rooms[0].height, 3.2);
            QVERIFY(s.rooms[0].outline == kL);  // untouched to the last bit
            QVERIFY(std::abs(area(*named(s, "office wall 1")) - (7 * 3.2 - 2 * 1.4)) < 1e-9);
            QCOMPARE(s.objects.size(), size_t(9));
        }
        QCOMPARE(undo->count(), start + 3);
        const Scene edited = doc->scene();

        // Pictures: the plan, and the 3D view from inside the room toward the window.
        QTest::qWait(50);
        const QImage drawn = plan->grab().toImage();
        drawn.save("room_plan.png");
        // The window is drawn across its wall's gap (wall 1 runs along z = -2, the room to +z).
        const QPointF mid = plan->widgetOf(V3d(-3 + 2.5 + 1, 0, -2));
        bool glazingDrawn = false;
        for (int dy = -4; dy <= 4; ++dy) {
            const QColor c = drawn.pixelColor(int(mid.x()), int(mid.y()) + dy);
            glazingDrawn = glazingDrawn || (c.blue() > c.red() + 60);
        }
        QVERIFY(glazingDrawn);
        // Daylight through the window for the picture.
        Sky sky;
        sky.horizontalIlluminance = 10000;
        doc->setSky(sky);
        Camera eye = doc->scene().camera;
        eye.position = V3d(-1.5, 1.6, 2.5);
        eye.target = V3d(1.5, 1.4, -2);
        doc->setCamera(eye);
        trigger(w, "actionViewPerspective");
        QTRY_VERIFY_WITH_TIMEOUT(w.livePreview()->frame() && w.livePreview()->frame()->scene == doc->snapshot(), 60000);
        QTest::qWait(3000);  // the preview converges a while
        w.viewport()->grab().save("room_viewport.png");

        // Each step one undo: the height, the window, the room (the floor back with it).
        undo->undo();
        QCOMPARE(doc->scene().rooms[0].height, 2.8);
        undo->undo();
        QVERIFY(doc->scene().rooms[0].openings.empty());
        QCOMPARE(doc->scene().objects.size(), size_t(8));
        undo->undo();
        QVERIFY(doc->scene().rooms.empty());
        QVERIFY(doc->scene().objects == before.objects);
        QVERIFY(doc->scene().materials == before.materials);
        QCOMPARE(outliner->heading(Outliner::Kind::Room)->childCount(), 0);
        for (int i = 0; i < 3; ++i) undo->redo();
        QVERIFY(doc->scene().rooms == edited.rooms && doc->scene().objects == edited.objects);
        // Saved (to another folder, so opened again from it), the room and its surfaces read back
        // as they were.
        QTemporaryDir dir;
        QVERIFY(w.saveFileAs(dir.filePath("office.json")));
        QVERIFY(doc->scene().rooms == edited.rooms && doc->scene().objects == edited.objects);
        QFile::copy(dir.filePath("office.json"), "room_office.json");
    }

    // The other two ways to draw: a drag from corner to corner, and corners closed by a double
    // click; the dialog opens on the outline drawn (cancelled: nothing changes).
    void drawRectangleAndDoubleClick() {
        MainWindow w(cornellPath());
        w.setSaveQuestion([] { return QMessageBox::Discard; });
        w.resize(1400, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        trigger(w, "actionNew");
        trigger(w, "actionViewPlan");
        PlanView* plan = w.planView();
        QTest::qWait(100);
        plan->fitToScene();
        const int start = w.document()->undoStack()->count();
        PlanPolygon seen;
        const auto readAndCancel = [&] {
            QTimer::singleShot(0, [&] {
                auto* dialog = qobject_cast<RoomDialog*>(QApplication::activeModalWidget());
                const Closes closes{dialog};
                QVERIFY(dialog);
                seen = dialog->room().outline;
            });
        };
        QToolButton* tool = plan->roomDrawing()->button();
        QTest::mouseClick(tool, Qt::LeftButton);
        const QPointF a = plan->widgetOf(V3d(-2, 0, -2)), b = plan->widgetOf(V3d(2, 0, 1));
        sendMouse(plan, QEvent::MouseButtonPress, a, Qt::LeftButton, Qt::LeftButton);
        sendMouse(plan, QEvent::MouseMove, (a + b) / 2, Qt::NoButton, Qt::LeftButton);
        sendMouse(plan, QEvent::MouseMove, b, Qt::NoButton, Qt::LeftButton);
        QCOMPARE(plan->roomDrawing()->cornersBeingDrawn().size(), size_t(4));
        readAndCancel();
        sendMouse(plan, QEvent::MouseButtonRelease, b, Qt::LeftButton, Qt::NoButton);
        QVERIFY(seen == (PlanPolygon{{-2, -2}, {2, -2}, {2, 1}, {-2, 1}}));

        QTest::mouseClick(tool, Qt::LeftButton);
        for (const V3d& c : {V3d(-2, 0, -2), V3d(2, 0, -2), V3d(2, 0, 1)}) click(plan, plan->widgetOf(c));
        const QPointF last = plan->widgetOf(V3d(-1, 0, 1));
        seen.clear();
        readAndCancel();
        sendMouse(plan, QEvent::MouseButtonPress, last, Qt::LeftButton, Qt::LeftButton);
        sendMouse(plan, QEvent::MouseButtonRelease, last, Qt::LeftButton, Qt::NoButton);
        sendMouse(plan, QEvent::MouseButtonDblClick, last, Qt::LeftButton, Qt::LeftButton);
        sendMouse(plan, QEvent::MouseButtonRelease, last, Qt::LeftButton, Qt::NoButton);
        QVERIFY(seen == (PlanPolygon{{-2, -2}, {2, -2}, {2, 1}, {-1, 1}}));
        // A crossed outline makes no room: it is said, and the dialog does not open.
        QTest::mouseClick(tool, Qt::LeftButton);
        for (const V3d& c : {V3d(-2, 0, -2), V3d(2, 0, 1), V3d(2, 0, -2), V3d(-2, 0, 1)}) click(plan, plan->widgetOf(c));
        plan->setFocus();
        QTest::keyClick(plan, Qt::Key_Return);
        QVERIFY2(w.statusBar()->currentMessage().startsWith("No room drawn: the outline crosses itself"),
                 qPrintable(w.statusBar()->currentMessage()));
        QCOMPARE(w.document()->undoStack()->count(), start);
        QVERIFY(w.document()->scene().rooms.empty());
    }

    // Edit > Add Room on File > New: a rectangle around the floor and the camera, typed into.
    void addRoomThroughTheMenu() {
        MainWindow w(cornellPath());
        w.setSaveQuestion([] { return QMessageBox::Discard; });  // also when a check fails early
        w.resize(1400, 900);
        w.show();
        trigger(w, "actionNew");
        Document* doc = w.document();
        bool filled = false;
        QTimer::singleShot(0, [&] {
            auto* dialog = qobject_cast<RoomDialog*>(QApplication::activeModalWidget());
            const Closes closes{dialog};
            QVERIFY(dialog);
            // Around the floor (10 x 10 m) and the camera (at z = 6 m): z to 6.5.
            QCOMPARE(dialog->cornerField(0, 0)->value(), -5.0);
            QCOMPARE(dialog->cornerField(2, 1)->value(), 6.5);
            // A fifth corner splits the wall after the first corner; a crossing outline is refused.
            dialog->findChild<QTableWidget*>("roomCorners")->selectRow(3);
            dialog->findChild<QPushButton*>("roomAddCorner")->click();
            QCOMPARE(dialog->cornerField(4, 0)->value(), -5.0);
            // z first: Tab from x goes on to z of the same corner, which stays chosen (Tab from the
            // table's last field goes round to the first corner, as in any table).
            typeAndTab(dialog->cornerField(4, 1), 8);
            typeAndTab(dialog->cornerField(4, 0), 2);
            pressOk(dialog);
            QVERIFY(dialog->isVisible());
            QVERIFY2(dialog->findChild<QLabel*>("roomSummary")->text().contains("crosses itself"),
                     qPrintable(dialog->findChild<QLabel*>("roomSummary")->text()));
            dialog->findChild<QPushButton*>("roomRemoveCorner")->click();
            typeAndTab(dialog->findChild<QDoubleSpinBox*>("roomCeilingReflectance"), 80);
            pressOk(dialog);
            filled = !dialog->isVisible();
            QVERIFY2(filled, qPrintable(dialog->findChild<QLabel*>("roomSummary")->text()));
        });
        trigger(w, "actionAddRoom");
        QVERIFY(filled);
        const Scene& scene = doc->scene();
        QCOMPARE(scene.rooms.size(), size_t(1));
        QCOMPARE(scene.rooms[0].outline.size(), size_t(4));
        QCOMPARE(scene.objects.size(), size_t(6));  // six quads; the floor under it gone
        QCOMPARE(scene.objects[0].name, std::string("room floor"));
        QCOMPARE(scene.objects[0].mesh.kind, MeshSource::Kind::Quad);
        QVERIFY(std::abs(scene.findMaterial("room ceiling")->albedo.x - 0.8) < 1e-12);
        doc->undoStack()->undo();
        QCOMPARE(doc->scene().objects.size(), size_t(1));
        QCOMPARE(doc->scene().objects[0].name, std::string("floor"));
        // Refusals: one line each, nothing changed.
        Room flat = roomAroundScene(doc->scene());
        flat.height = 0;
        QVERIFY(!w.roomActions()->addRoom(flat, {}));
        QVERIFY2(w.lastError().contains("height must be positive"), qPrintable(w.lastError()));
        QCOMPARE(doc->scene().objects.size(), size_t(1));
    }

    // Imported objects that close a shell, marked as a room: tagged, listed under it, kept
    // through a save and an open, deleted as a room (the objects stay). An open set is refused.
    void markObjectsAsRoom() {
        MainWindow w(cornellPath());
        w.setSaveQuestion([] { return QMessageBox::Discard; });  // also when a check fails early
        w.resize(1400, 900);
        w.show();
        trigger(w, "actionNew");
        Document* doc = w.document();
        Scene scene = doc->scene();
        Room box;
        box.name = "shell";
        box.outline = {{0, 0}, {4, 0}, {4, 3}, {0, 3}};
        box.floorMaterial = box.wallMaterial = box.ceilingMaterial = "floor";
        std::set<std::string> taken{"floor"};
        for (Object o : roomSurfaces(box, scene, taken)) {
            o.room.clear();
            o.name = "imported " + std::to_string(scene.objects.size());
            scene.objects.push_back(o);
        }
        doc->reset(scene);  // objects 1..6 the shell, 0 the new scene's floor
        Outliner* outliner = w.outliner();
        QTreeWidgetItem* objects = outliner->heading(Outliner::Kind::Object);
        QCOMPARE(objects->childCount(), 7);
        // Five of six: not closed.
        outliner->clearSelection();
        for (int i = 1; i <= 5; ++i) objects->child(i)->setSelected(true);
        QVERIFY(outliner->selection().objects == (std::vector<int>{1, 2, 3, 4, 5}));
        QVERIFY(!w.roomActions()->markAsRoom(outliner->selection().objects, "hall"));
        QVERIFY2(w.lastError().contains("do not form a closed shell: 4 edges belong to one face only"), qPrintable(w.lastError()));
        objects->child(6)->setSelected(true);
        QTimer::singleShot(0, [&] {
            auto* input = qobject_cast<QInputDialog*>(QApplication::activeModalWidget());
            QVERIFY(input);
            input->setTextValue("hall");
            input->accept();
        });
        trigger(w, "actionMarkAsRoom");
        QCOMPARE(doc->scene().rooms.size(), size_t(1));
        QVERIFY(!doc->scene().rooms[0].parametric());
        QCOMPARE(roomObjects(doc->scene(), "hall").size(), size_t(6));
        QCOMPARE(outliner->roomItem(0)->text(1), QString("Room, marked"));
        QCOMPARE(outliner->roomItem(0)->childCount(), 6);
        QCOMPARE(outliner->heading(Outliner::Kind::Object)->childCount(), 1);
        // A marked room has no walls of its own to open.
        QVERIFY(!w.roomActions()->addOpening(0, newOpening(box, OpeningType::Window, 1), 0.7));
        QVERIFY(w.lastError().contains("marked on imported objects"));

        // Saved and opened again: the room and its tags.
        QTemporaryDir dir;
        const QString path = dir.filePath("marked.json");
        QVERIFY(w.saveFileAs(path));
        QVERIFY(w.openFile(path));
        QCOMPARE(doc->scene().rooms.size(), size_t(1));
        QCOMPARE(roomObjects(doc->scene(), "hall").size(), size_t(6));

        // Deleted: the room goes, its objects stay, untagged; one undo step.
        w.outliner()->select(Outliner::Kind::Room, 0);
        trigger(w, "actionDelete");
        QVERIFY(doc->scene().rooms.empty());
        QCOMPARE(doc->scene().objects.size(), size_t(7));
        QVERIFY(roomObjects(doc->scene(), "hall").empty());
        doc->undoStack()->undo();
        QCOMPARE(roomObjects(doc->scene(), "hall").size(), size_t(6));
    }
};

QTEST_MAIN(TestRooms)
#include "test_rooms.moc"
