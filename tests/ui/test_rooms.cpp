// Rooms built in the window (Edit > Add Room): the room's six quads face into it, carry the three
// reflectances, take names that are free in the scene and refuse dimensions that make no room;
// through the menu's dialog, typed into as a designer would, the room is one undo step.

#include "core/scene/room_geometry.h"
#include "ui/rendering/live_preview.h"
#include "ui/scene_panels/room_dialog.h"
#include "ui/window/main_window.h"
#include "window_test_helpers.h"

#include <QApplication>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QPushButton>
#include <QTimer>
#include <QtTest>

using namespace lucerna;
using namespace lucerna::test;

namespace {
// Typed as a designer types, then Tab (Return would press the dialog's default button).
void typeAndTab(QDoubleSpinBox* spin, double value) {
    spin->setFocus();
    spin->selectAll();
    QTest::keyClicks(spin, QString::number(value));
    QTest::keyClick(spin, Qt::Key_Tab);
}
}  // namespace

class TestRooms : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { useTestSettings("test_rooms"); }

    void facesPointIntoTheRoom() {
        Scene scene;
        RoomSpec spec;
        spec.corner = V3d(1, 0, 2);
        spec.width = 5;
        spec.depth = 4;
        spec.height = 2.8;
        const RoomParts room = makeRoom(spec, scene);
        QCOMPARE(int(room.materials.size()), 3);
        QCOMPARE(room.materials[1].albedo, Rgbd(0.5, 0.5, 0.5));
        QCOMPARE(int(room.objects.size()), 6);
        const V3d centre(1 + 2.5, 1.4, 2 + 2);
        double floorArea = 0, total = 0;
        for (const Object& o : room.objects) {
            QVERIFY(o.worldMesh);
            for (const V3i& t : o.worldMesh->triangles) {
                const V3d& a = o.worldMesh->vertices[t.x];
                const V3d cross = (o.worldMesh->vertices[t.y] - a).cross(o.worldMesh->vertices[t.z] - a);
                QVERIFY2(cross.dot(centre - a) > 0, o.name.c_str());  // the front faces the room
                total += 0.5 * cross.length();
                if (o.name == "room floor") floorArea += 0.5 * cross.length();
            }
        }
        QVERIFY(std::abs(floorArea - 20) < 1e-9);
        QVERIFY(std::abs(total - (2 * 20 + 2 * 2.8 * (5 + 4))) < 1e-9);
        // Names free in the scene: a second room beside the first.
        scene.objects = room.objects;
        scene.materials = room.materials;
        const RoomParts second = makeRoom(spec, scene);
        QCOMPARE(second.objects[0].name, std::string("room floor 2"));
        QCOMPARE(second.materials[0].name, std::string("room floor 2"));
        spec.height = 0;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, makeRoom(spec, scene));
        spec.height = 3;
        spec.wallReflectance = 1.2;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, makeRoom(spec, scene));
    }

    // File > New, then Edit > Add Room typed into: the room's default plan holds the floor and
    // the camera, so the view is of the room.
    void addRoomThroughTheMenu() {
        MainWindow w(cornellPath());
        w.resize(1400, 900);
        w.show();
        trigger(w, "actionNew");
        QCOMPARE(w.document()->scene().objects.size(), size_t(1));  // the new scene's floor
        const size_t objects = w.document()->scene().objects.size(), materials = w.document()->scene().materials.size();
        bool filled = false;
        QTimer::singleShot(0, [&] {
            auto* dialog = qobject_cast<RoomDialog*>(QApplication::activeModalWidget());
            QVERIFY(dialog);
            dialog->findChild<QLineEdit*>("roomName")->setText("office");
            // Around the floor (10 x 10 m) and the camera (at z = 6 m): 11.5 m deep.
            QCOMPARE(dialog->findChild<QDoubleSpinBox*>("roomWidth")->value(), 10.0);
            QCOMPARE(dialog->findChild<QDoubleSpinBox*>("roomDepth")->value(), 11.5);
            typeAndTab(dialog->findChild<QDoubleSpinBox*>("roomHeight"), 2.8);
            typeAndTab(dialog->findChild<QDoubleSpinBox*>("roomCeilingReflectance"), 80);
            filled = true;
            QTest::mouseClick(dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok), Qt::LeftButton);
        });
        trigger(w, "actionAddRoom");
        QVERIFY(filled);
        const Scene& scene = w.document()->scene();
        QCOMPARE(scene.objects.size(), objects + 6);
        QCOMPARE(scene.materials.size(), materials + 3);
        QCOMPARE(scene.objects[objects].name, std::string("office floor"));
        const Material* ceiling = scene.findMaterial("office ceiling");
        QVERIFY(ceiling && std::abs(ceiling->albedo.x - 0.8) < 1e-12);
        QTRY_VERIFY_WITH_TIMEOUT(w.livePreview()->frame() && w.livePreview()->frame()->scene == w.document()->snapshot(), 60000);
        QTest::qWait(500);
        w.grab().save("room_added.png");
        // One undo step.
        w.document()->undoStack()->undo();
        QCOMPARE(w.document()->scene().objects.size(), objects);
        QCOMPARE(w.document()->scene().materials.size(), materials);
        w.document()->undoStack()->redo();
        QCOMPARE(w.document()->scene().objects.size(), objects + 6);
        // Dimensions that make no room: one line, nothing added.
        RoomSpec flat;
        flat.height = 0;
        QVERIFY(!w.addRoom(flat));
        QVERIFY(w.lastError().contains("must be positive"));
        QCOMPARE(w.document()->scene().objects.size(), objects + 6);
        w.setSaveQuestion([] { return QMessageBox::Discard; });
    }
};

QTEST_MAIN(TestRooms)
#include "test_rooms.moc"
