// Viewport editing (issue 6) driven as a user would, in the real window on the Cornell box:
// place a point light by clicking the floor and a spot by clicking the ceiling, aim the spot by
// clicking the floor, drag the gizmo's axis arrow and aim handle, select by clicking, fly with
// the keys, undo and redo, save and reopen. Expected positions come from this file's own camera
// rays (SPEC.md section 1) against the box's planes, not from the code under test. Saves
// screenshots (viewport_*.png) in the test's working directory, the build's tests/ folder.

#include "core/image/image.h"
#include "core/scene/scene_io.h"
#include "render/trace/surface_pick.h"
#include "ui/viewport/camera_navigation.h"
#include "ui/viewport/light_gizmo.h"
#include "ui/viewport/light_placement.h"
#include "ui/viewport/light_symbols.h"
#include "ui/rendering/live_preview.h"
#include "ui/window/main_window.h"
#include "ui/scene_panels/outliner.h"
#include "ui/viewport/viewport.h"
#include "window_test_helpers.h"

#include <QAction>
#include <QApplication>
#include <QFile>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>

#include <numeric>

using namespace lucerna;
using namespace lucerna::test;

namespace {

QString str(const V3d& v) { return QString("(%1, %2, %3)").arg(v.x, 0, 'g', 12).arg(v.y, 0, 'g', 12).arg(v.z, 0, 'g', 12); }

void drag(QWidget* w, QPointF from, QPointF to, int steps = 6) {
    sendMouse(w, QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    for (int i = 1; i <= steps; ++i)
        sendMouse(w, QEvent::MouseMove, from + (to - from) * (double(i) / steps), Qt::NoButton, Qt::LeftButton);
    sendMouse(w, QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
}

void key(QWidget* w, QEvent::Type type, int k, bool autoRepeat) {
    QKeyEvent e(type, k, Qt::NoModifier, QString(), autoRepeat);
    QApplication::sendEvent(w, &e);
}

// SPEC.md section 1, written out again here: the ray through raster (x, y).
V3d specRay(const Camera& c, double x, double y) {
    const V3d f = (c.target - c.position).normalized();
    const V3d r = f.cross(c.up).normalized();
    const V3d u = r.cross(f);
    const double t = std::tan(c.fovYDeg * std::numbers::pi / 360);
    return (f + r * ((2 * x / c.width - 1) * (double(c.width) / c.height) * t) + u * ((1 - 2 * y / c.height) * t))
        .normalized();
}

// Where the ray through a widget point of the viewport meets the plane y = planeY.
V3d hitOnPlaneY(Viewport* vp, const Camera& c, QPointF widget, double planeY) {
    const QRectF r = vp->imageRect();
    const double x = (widget.x() - r.left()) / r.width() * c.width, y = (widget.y() - r.top()) / r.height() * c.height;
    const V3d d = specRay(c, x, y);
    return c.position + d * ((planeY - c.position.y) / d.y);
}

// Widget position of a world point (the test's own projection, through specRay's inverse).
QPointF widgetOf(Viewport* vp, const Camera& c, const V3d& p) {
    const auto raster = projectToRaster(c, p);
    const QRectF r = vp->imageRect();
    return {r.left() + raster->x / c.width * r.width(), r.top() + raster->y / c.height * r.height()};
}

double geometryDiagonal(const Scene& scene) {
    V3d lo(1e300), hi(-1e300);
    for (const Object& o : scene.objects)
        for (const V3d& v : o.worldMesh->vertices)
            for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
    return (hi - lo).length();
}

// Mean luminance of the preview in a square of half-size `r` preview pixels around a world point.
double meanAround(const LiveFrame& frame, const Camera& c, const V3d& p, int r) {
    const auto raster = projectToRaster(c, p);
    const int cx = int(raster->x / c.width * frame.image.width), cy = int(raster->y / c.height * frame.image.height);
    double sum = 0;
    int n = 0;
    for (int y = std::max(0, cy - r); y < std::min(frame.image.height, cy + r); ++y)
        for (int x = std::max(0, cx - r); x < std::min(frame.image.width, cx + r); ++x, ++n)
            sum += luminance(frame.image.at(x, y));
    return n ? sum / n : 0;
}

bool near(const V3d& a, const V3d& b, double tolerance) { return (a - b).length() <= tolerance; }
}  // namespace

class TestViewportEditing : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void gizmoGeometry();
    void lightSymbolsShrinkAndStayInThePicture();
    void pickerFollowsTheSpecCamera();
    void placeAimMoveUndoSaveInTheWindow();
    void selectAndFly();

private:
    QTemporaryDir dir_;
};

void TestViewportEditing::initTestCase() {
    useTestSettings("test_viewport_editing");
    QVERIFY(dir_.isValid());
}

void TestViewportEditing::gizmoGeometry() {
    // A camera at the origin looking down -z, drawn into a 400x300 rectangle at (10, 20).
    Camera c;
    c.position = V3d(0, 0, 0);
    c.target = V3d(0, 0, -1);
    c.width = 400;
    c.height = 300;
    c.fovYDeg = 50;
    const ViewMapping view(c, QRectF(10, 20, 400, 300));
    QVERIFY(near(view.rayThrough(view.fromRaster(200, 150)), V3d(0, 0, -1), 1e-12));
    QVERIFY(near(view.rayThrough(QPointF(57, 233)), specRay(c, 47, 213), 1e-12));

    // Dragging along an axis: the point under the mouse on the axis's screen line is where the
    // light goes, exactly, under perspective.
    const V3d start(1, -2, -10), axis = V3d(1, 0.5, -2).normalized();
    const QPointF pressed = *view.toWidget(start + axis * 1.0), now = *view.toWidget(start + axis * 3.5);
    QVERIFY2(near(dragAlongAxis(view, start, axis, pressed, now), start + axis * 2.5, 1e-9),
             qPrintable(str(dragAlongAxis(view, start, axis, pressed, now))));
    // An axis pointing at the viewer cannot be dragged along.
    const V3d towards = (c.position - start).normalized();
    QCOMPARE(dragAlongAxis(view, start, towards, pressed, now), start);

    // Aiming through the plane of the handle's tip, parallel to the image plane.
    const V3d tip(2, 0, -12), target(-1, 3, -12);
    const auto dir = aimThroughPlane(view, start, tip, *view.toWidget(target));
    QVERIFY(dir);
    QVERIFY2(near(*dir, (target - start).normalized(), 1e-9), qPrintable(str(*dir)));

    // Handles: the x arrow goes right, y up, z away; the middle of an arrow takes it, the
    // marker's disc and empty space do not.
    Light spot;
    spot.type = LightType::Spot;
    spot.position = V3d(0, 0, -10);
    spot.direction = V3d(0, -1, -1);
    const auto g = LightGizmo::of(spot, view);
    QVERIFY(g && g->aimTip && g->axisTips[0] && g->axisTips[1]);
    QCOMPARE_LT(std::abs(g->axisTips[0]->x() - g->centre.x() - LightGizmo::kAxisPixels), 1e-9);
    QCOMPARE_LT(std::abs(g->centre.y() - g->axisTips[1]->y() - LightGizmo::kAxisPixels), 1e-9);
    QCOMPARE(g->handleAt((g->centre + *g->axisTips[0]) / 2 + QPointF(0, 3)), GizmoHandle::X);
    QCOMPARE(g->handleAt((g->centre + *g->axisTips[1]) / 2), GizmoHandle::Y);
    QCOMPARE(g->handleAt(*g->aimTip), GizmoHandle::Aim);
    QCOMPARE(g->handleAt(g->centre), GizmoHandle::None);
    QCOMPARE(g->handleAt(g->centre + QPointF(-40, -40)), GizmoHandle::None);
    // The z arrow points straight away from this camera: a dot on the marker, never taken.
    QCOMPARE_LT(std::hypot(g->axisTips[2]->x() - g->centre.x(), g->axisTips[2]->y() - g->centre.y()), 1e-9);
    for (const QPointF d : {QPointF(9, 0), QPointF(0, 9), QPointF(-9, 0)})
        QVERIFY(g->handleAt(g->centre + d) != GizmoHandle::Z);
    Light sun;
    sun.type = LightType::Directional;
    QVERIFY(!LightGizmo::of(sun, view));

    // Placement distance: a quarter metre, at most a tenth of the geometry's diagonal.
    QCOMPARE(placementOffset(0.001, 5000), 250.0);
    QCOMPARE(placementOffset(0.001, 965), 96.5);
    QCOMPARE(placementOffset(1.0, 10), 0.25);
    // Aiming: a spot at the point, a directional light against the normal, a point light not at all.
    SurfaceHit hit;
    hit.point = V3d(0, 0, -20);
    hit.normal = V3d(0, 1, 0);
    QVERIFY(near(aimedLight(spot, hit)->direction, V3d(0, 0, -1), 1e-12));
    sun.direction = V3d(1, 1, 1);
    QCOMPARE(aimedLight(sun, hit)->direction, V3d(0, -1, 0));
    QVERIFY(!aimedLight(Light{}, hit));
    // A luminaire has a position and a nadir: arrows and an aim handle, aimed like a spot.
    Light luminaire = spot;
    luminaire.type = LightType::Luminaire;
    const auto lg = LightGizmo::of(luminaire, view);
    QVERIFY(lg && lg->aimTip && lg->axisTips[0]);
    QVERIFY(near(aimedLight(luminaire, hit)->direction, V3d(0, 0, -1), 1e-12));
}

// The office floor (108 luminaires) in a square viewport, its wide picture letterboxed: the
// lights' balls shrink with distance, none is drawn (or picked) behind or just beside the camera
// or outside the picture, and nothing of the overlays reaches the bands, even with every light
// selected (their aim lines drawn) and the one just above the camera among them.
void TestViewportEditing::lightSymbolsShrinkAndStayInThePicture() {
    Scene scene = loadScene(LUCERNA_RESOURCE_DIR "/scenes/office_floor.json");
    const Camera cam = scene.camera;
    const V3d f = (cam.target - cam.position).normalized();
    const double mpu = scene.metersPerUnit;
    // Three more: behind the camera, a tenth of a metre in front of it, and above the picture.
    const auto extra = [&](const char* name, const V3d& at) {
        Light l = scene.lights.front();
        l.name = name;
        l.position = at;
        scene.lights.push_back(l);
        return int(scene.lights.size()) - 1;
    };
    const int behind = extra("behind", cam.position - f * (2 / mpu) + V3d(0, 0.4 / mpu, 0));
    const int tooNear = extra("too_near", cam.position + f * (0.1 / mpu) + V3d(0, 0.05 / mpu, 0));
    const int above = extra("above", cam.position + specRay(cam, cam.width / 2.0, -40) * (3 / mpu));
    Document doc(scene);
    YieldGate gate;
    Viewport vp(&doc, gate);
    vp.resize(600, 600);
    QImage grey(cam.width, cam.height, QImage::Format_RGB32);
    grey.fill(QColor(128, 128, 128));
    vp.setImage(grey);
    vp.show();
    QVERIFY(QTest::qWaitForWindowExposed(&vp));
    const QRectF picture = vp.imageRect();
    QCOMPARE_GT(picture.top(), 100.0);  // bands above and below

    const ViewMapping view = vp.mapping();
    QVERIFY(!vp.lightMarker(behind) && !vp.lightMarker(tooNear));
    QVERIFY(view.toWidget(scene.lights[size_t(above)].position));  // in front, but over the picture
    QVERIFY(!vp.lightMarker(above));
    QVERIFY(!lightSymbol(scene.lights[size_t(tooNear)], view, mpu));
    // Balls that shrink with distance, within their bounds; picked where drawn.
    int drawn = 0;
    double nearest = 1e300, farthest = 0, nearRadius = 0, farRadius = 0;
    for (int i = 0; i < 108; ++i) {
        const auto s = lightSymbol(doc.scene().lights[size_t(i)], view, mpu);
        QCOMPARE(bool(s), bool(vp.lightMarker(i)));
        if (!s) continue;
        ++drawn;
        QVERIFY(picture.contains(s->centre));
        QVERIFY(s->radius >= kSmallestSymbolPx && s->radius <= kLargestSymbolPx);
        const double depth = depthAlongView(view, doc.scene().lights[size_t(i)].position);
        if (depth < nearest) nearest = depth, nearRadius = s->radius;
        if (depth > farthest) farthest = depth, farRadius = s->radius;
    }
    QCOMPARE_GT(drawn, 50);
    QCOMPARE_GT(nearRadius, 2 * farRadius);
    QCOMPARE(farRadius, kSmallestSymbolPx);  // dots far away

    // Every light selected, the one nearest above the camera the gizmo's: the bands stay empty.
    std::vector<int> all(doc.scene().lights.size());
    std::iota(all.begin(), all.end(), 0);
    vp.setSelectedLights(all);
    vp.setSelectedLight(tooNear);
    QVERIFY(!vp.gizmo());  // its light is not drawn: no gizmo either
    int nearestDrawn = -1;
    for (int i = 0; i < 108; ++i)
        if (vp.lightMarker(i) && (nearestDrawn < 0 || depthAlongView(view, doc.scene().lights[size_t(i)].position) <
                                                          depthAlongView(view, doc.scene().lights[size_t(nearestDrawn)].position)))
            nearestDrawn = i;
    vp.setSelectedLight(nearestDrawn);
    QVERIFY(vp.gizmo());
    const QImage shot = vp.grab().toImage();
    shot.save("viewport_office_overlays.png");
    const QRgb band = QColor(32, 32, 36).rgb();
    int inBand = 0;
    for (int y = 0; y < shot.height(); ++y)
        for (int x = 0; x < shot.width(); ++x)
            if ((y < picture.top() - 1 || y > picture.bottom() + 1) && shot.pixel(x, y) != band) ++inBand;
    QCOMPARE(inBand, 0);
    // The picture does show them: the selected light's ball is white-ringed yellow.
    const QPointF c = *vp.lightMarker(nearestDrawn);
    QCOMPARE(QColor(shot.pixel(c.toPoint())), QColor(255, 210, 60));

    // An aim line is cut where it passes the near plane, and ends where the aim meets the floor.
    const auto cut = projectedSegment(view, cam.position - f * 1.0, cam.position + f * 5.0, nearPlaneDepth(mpu));
    QVERIFY(cut);
    QVERIFY(!projectedSegment(view, cam.position - f * 1.0, cam.position + f * 0.01, nearPlaneDepth(mpu)));
    QCOMPARE(aimLineLength(2.6 / mpu, mpu), 2.6 / mpu);
    QCOMPARE(aimLineLength(std::nullopt, mpu), kLongestAimLineM / mpu);
    QCOMPARE(aimLineLength(100 / mpu, mpu), kLongestAimLineM / mpu);
}

void TestViewportEditing::pickerFollowsTheSpecCamera() {
    Document doc(loadScene(cornellPath().toStdString()));
    const Scene& scene = doc.scene();
    const SurfacePicker picker(scene);
    QCOMPARE_LT(std::abs(picker.diagonal() - geometryDiagonal(scene)), 1e-9);
    // The floor, through a raster point low in the image: the y = 0 plane, seen from above.
    const Camera& c = scene.camera;
    const V3d d = specRay(c, 150.5, 240.25);
    const V3d expected = c.position + d * (-c.position.y / d.y);
    const auto hit = picker.pick(c, 150.5, 240.25);
    QVERIFY(hit);
    QCOMPARE(scene.objects[size_t(hit->object)].name, std::string("floor"));
    QVERIFY2(near(hit->point, expected, 1e-9), qPrintable(str(hit->point) + " " + str(expected)));
    QCOMPARE(hit->normal, V3d(0, 1, 0));
    // The right wall (x = 0, green) is seen from inside: its normal turned toward the camera.
    const auto wall = picker.intersect(V3d(278, 273, 200), V3d(-1, 0, 0));
    QVERIFY(wall);
    QCOMPARE(scene.objects[size_t(wall->object)].name, std::string("right_wall"));
    QCOMPARE(wall->normal, V3d(1, 0, 0));
    QCOMPARE_LT(std::abs(wall->distance - 278), 1e-9);
    // Out of the open front: nothing.
    QVERIFY(!picker.pick(c, 0.5, 0.5));
    QVERIFY(!picker.intersect(V3d(278, 273, 200), V3d(0, 0, -1)));

    // One picker serves every snapshot with the same geometry: not after lights or the camera
    // change, but after an object does.
    doc.modify([](Scene& s) {
        s.lights.push_back(Light{});
        s.camera.position.x += 10;
    });
    QVERIFY(picker.sameGeometry(doc.scene()));
    doc.modify([](Scene& s) {
        auto mesh = std::make_shared<TriangleMesh>(*s.objects[1].worldMesh);
        mesh->vertices[0].y += 1;
        s.objects[1].worldMesh = mesh;
    });
    QVERIFY(!picker.sameGeometry(doc.scene()));

    // A room in metres: a placed light stands a quarter metre off its surface.
    const Scene room = loadScene(LUCERNA_RESOURCE_DIR "/scenes/interior.json");
    const SurfacePicker roomPicker(room);
    QCOMPARE_GT(roomPicker.diagonal(), 2.5);
    QCOMPARE(placementOffset(room.metersPerUnit, roomPicker.diagonal()), 0.25);
    QVERIFY(roomPicker.pick(room.camera, room.camera.width / 2.0, room.camera.height / 2.0));
}

void TestViewportEditing::placeAimMoveUndoSaveInTheWindow() {
    const QString scenePath = dir_.filePath("cornell.json");
    QVERIFY(QFile::copy(cornellPath(), scenePath));
    MainWindow w(scenePath);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    Document* doc = w.document();
    Viewport* vp = w.viewport();
    QUndoStack* undo = doc->undoStack();
    const auto before = previewOfCurrent(w);
    QVERIFY(before);
    QVERIFY(!vp->imageRect().isEmpty());
    const Camera cam = doc->scene().camera;
    const double offset = std::min(250.0, 0.1 * geometryDiagonal(doc->scene()));  // 0.25 m in mm, or less

    // Place a point light: the tool, then a click on the floor (clear of both blocks).
    const QPointF floorAt = widgetOf(vp, cam, V3d(450, 0, 100)) + QPointF(0.3, -0.2);
    const V3d floorHit = hitOnPlaneY(vp, cam, floorAt, 0.0);
    trigger(w, "actionPlacePointLight");
    QCOMPARE(vp->tool(), Viewport::Tool::PlacePoint);
    QVERIFY(w.findChild<QAction*>("actionPlacePointLight")->isChecked());
    // While the tool is on, the surface under the mouse shows where the light would go.
    sendMouse(vp, QEvent::MouseMove, floorAt, Qt::NoButton, Qt::NoButton);
    screenshot(w, "viewport_place_mode.png");
    screenshot(*vp, "viewport_place_mode_closeup.png");
    click(vp, floorAt);
    QCOMPARE(doc->scene().lights.size(), size_t(1));
    const Light point = doc->scene().lights[0];
    QCOMPARE(point.type, LightType::Point);
    QVERIFY2(near(point.position, floorHit + V3d(0, offset, 0), 1e-6),
             qPrintable(str(point.position) + " expected " + str(floorHit + V3d(0, offset, 0))));
    QCOMPARE(undo->count(), 1);
    QCOMPARE(vp->tool(), Viewport::Tool::Navigate);
    QVERIFY(!w.findChild<QAction*>("actionPlacePointLight")->isChecked());
    QCOMPARE(w.selectedLight(), 0);

    // The preview brightens around it: a bulb a tenth of a metre over the floor.
    const auto placed = previewOfCurrent(w);
    QVERIFY(placed);
    const double dimFloor = meanAround(*before, cam, floorHit, 12), litFloor = meanAround(*placed, cam, floorHit, 12);
    QVERIFY2(litFloor > 2 * dimFloor, qPrintable(QString("%1 -> %2").arg(dimFloor).arg(litFloor)));

    // Undo takes it away, redo brings it back as it was.
    trigger(w, "actionUndo");
    QVERIFY(doc->scene().lights.empty());
    trigger(w, "actionRedo");
    QCOMPARE(doc->scene().lights.size(), size_t(1));
    QVERIFY(doc->scene().lights[0] == point);

    // A click on nothing (out of the open front of the box) places nothing and says so; the
    // tool stays until Escape, after which a click on the floor places nothing either.
    trigger(w, "actionPlacePointLight");
    const QPointF outside = vp->imageRect().topLeft() + QPointF(1, 1);
    QVERIFY(!vp->surfaceAt(outside));
    click(vp, outside);
    QCOMPARE(doc->scene().lights.size(), size_t(1));
    QVERIFY2(w.statusBar()->currentMessage().contains("No surface"), qPrintable(w.statusBar()->currentMessage()));
    QCOMPARE(vp->tool(), Viewport::Tool::PlacePoint);
    QTest::keyClick(vp, Qt::Key_Escape);
    QCOMPARE(vp->tool(), Viewport::Tool::Navigate);
    click(vp, floorAt);
    QCOMPARE(doc->scene().lights.size(), size_t(1));
    QCOMPARE(undo->count(), 1);

    // A spot on the ceiling, beside the lamp: it hangs below and shines straight down.
    const QPointF ceilingAt = widgetOf(vp, cam, V3d(120, 548.8, 450)) + QPointF(-0.4, 0.1);
    const V3d ceilingHit = hitOnPlaneY(vp, cam, ceilingAt, 548.8);
    trigger(w, "actionPlaceSpotLight");
    click(vp, ceilingAt);
    QCOMPARE(doc->scene().lights.size(), size_t(2));
    const Light spot = doc->scene().lights[1];
    QCOMPARE(spot.type, LightType::Spot);
    QVERIFY2(near(spot.position, ceilingHit - V3d(0, offset, 0), 1e-6), qPrintable(str(spot.position)));
    QVERIFY2(near(spot.direction, V3d(0, -1, 0), 1e-12), qPrintable(str(spot.direction)));
    QCOMPARE(w.selectedLight(), 1);
    QCOMPARE(undo->count(), 2);

    // Aim it at a point of the floor in front of the short block: Edit > Aim, then a click.
    const QPointF aimAt = widgetOf(vp, cam, V3d(150, 0, 30)) + QPointF(0.25, 0.25);
    const V3d aimHit = hitOnPlaneY(vp, cam, aimAt, 0.0);
    trigger(w, "actionAimLight");
    QCOMPARE(vp->tool(), Viewport::Tool::Aim);
    sendMouse(vp, QEvent::MouseMove, aimAt, Qt::NoButton, Qt::NoButton);
    screenshot(*vp, "viewport_aim_mode.png");
    click(vp, aimAt);
    QVERIFY2(near(doc->scene().lights[1].direction, (aimHit - spot.position).normalized(), 1e-9),
             qPrintable(str(doc->scene().lights[1].direction)));
    QCOMPARE(doc->scene().lights[1].position, spot.position);
    QCOMPARE(undo->count(), 3);
    QCOMPARE(vp->tool(), Viewport::Tool::Navigate);
    // Ctrl+click aims too, without the tool.
    const QPointF aimAt2 = widgetOf(vp, cam, V3d(500, 0, 300));
    const V3d aimHit2 = hitOnPlaneY(vp, cam, aimAt2, 0.0);
    click(vp, aimAt2, Qt::ControlModifier);
    QVERIFY(near(doc->scene().lights[1].direction, (aimHit2 - spot.position).normalized(), 1e-9));
    QCOMPARE(undo->count(), 4);
    trigger(w, "actionUndo");
    QVERIFY(near(doc->scene().lights[1].direction, (aimHit - spot.position).normalized(), 1e-9));
    // Aiming a point light makes no sense: the action is off while one is selected.
    w.outliner()->select(Outliner::Kind::Light, 0);
    QVERIFY(!w.findChild<QAction*>("actionAimLight")->isEnabled());
    w.outliner()->select(Outliner::Kind::Light, 1);
    QVERIFY(w.findChild<QAction*>("actionAimLight")->isEnabled());

    // The gizmo: drag the x arrow of the selected spot along its own screen line. Only x
    // changes, the light stays under the mouse, and the drag is one undo step.
    QVERIFY(previewOfCurrent(w));
    auto g = vp->gizmo();
    QVERIFY(g && g->axisTips[0] && g->aimTip);
    screenshot(w, "viewport_gizmo.png");
    screenshot(*vp, "viewport_gizmo_closeup.png");
    const Light beforeDrag = doc->scene().lights[1];
    const QPointF xDir = (*g->axisTips[0] - g->centre) / std::hypot(g->axisTips[0]->x() - g->centre.x(),
                                                                  g->axisTips[0]->y() - g->centre.y());
    const QPointF grab = g->centre + (*g->axisTips[0] - g->centre) * 0.7;
    QCOMPARE(g->handleAt(grab), GizmoHandle::X);
    const int steps = undo->index();
    drag(vp, grab, grab + xDir * 30);
    const Light moved = doc->scene().lights[1];
    QCOMPARE(undo->index(), steps + 1);
    QVERIFY2(moved.position.x > beforeDrag.position.x + 5, qPrintable(str(moved.position)));  // toward the x tip
    QCOMPARE(moved.position.y, beforeDrag.position.y);
    QCOMPARE(moved.position.z, beforeDrag.position.z);
    QCOMPARE(moved.direction, beforeDrag.direction);
    const QPointF markerNow = *vp->lightMarker(1), markerWant = g->centre + xDir * 30;
    QVERIFY2(std::hypot(markerNow.x() - markerWant.x(), markerNow.y() - markerWant.y()) < 0.5,
             qPrintable(QString("%1,%2 vs %3,%4").arg(markerNow.x()).arg(markerNow.y()).arg(markerWant.x()).arg(markerWant.y())));
    trigger(w, "actionUndo");
    QVERIFY(doc->scene().lights[1] == beforeDrag);
    trigger(w, "actionRedo");
    QVERIFY(doc->scene().lights[1] == moved);

    // The y arrow moves it up and down only.
    g = vp->gizmo();
    const QPointF yGrab = g->centre + (*g->axisTips[1] - g->centre) * 0.7;
    drag(vp, yGrab, yGrab + QPointF(0, 25));
    QCOMPARE(undo->index(), steps + 2);
    QVERIFY(doc->scene().lights[1].position.y < moved.position.y - 5);
    QCOMPARE(doc->scene().lights[1].position.x, moved.position.x);
    QCOMPARE(doc->scene().lights[1].position.z, moved.position.z);
    trigger(w, "actionUndo");

    // The aim handle re-aims the spot (its position stays), one undo step.
    g = vp->gizmo();
    const QPointF aimFrom = *g->aimTip, aimTo = *g->aimTip + QPointF(35, -10);
    drag(vp, aimFrom, aimTo);
    QCOMPARE(undo->index(), steps + 2);
    const Light reaimed = doc->scene().lights[1];
    QCOMPARE(reaimed.position, moved.position);
    QVERIFY(!near(reaimed.direction, moved.direction, 1e-3));
    // The handle followed the mouse: its new tip lies on the line from the light to the mouse.
    g = vp->gizmo();
    const QPointF a = aimTo - g->centre, b = *g->aimTip - g->centre;
    QCOMPARE_LT(std::abs(a.x() * b.y() - a.y() * b.x()) / std::hypot(a.x(), a.y()), 0.5);
    QCOMPARE_GT(a.x() * b.x() + a.y() * b.y(), 0.0);
    trigger(w, "actionUndo");
    QVERIFY(doc->scene().lights[1] == moved);
    trigger(w, "actionRedo");

    // Save, reopen: both lights as they were.
    const QString savedPath = dir_.filePath("placed.json");
    const Scene edited = doc->scene();
    QVERIFY2(w.saveFileAs(savedPath), qPrintable(w.lastError()));
    QVERIFY(w.openFile(scenePath));
    QVERIFY(doc->scene().lights.empty());
    QVERIFY(w.openFile(savedPath));
    QCOMPARE(doc->scene().lights.size(), size_t(2));
    QVERIFY(doc->scene().lights[0] == edited.lights[0]);
    QVERIFY(doc->scene().lights[1] == edited.lights[1]);
    QVERIFY(doc->scene() == edited);
}

void TestViewportEditing::selectAndFly() {
    MainWindow w(cornellPath());
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    Document* doc = w.document();
    Viewport* vp = w.viewport();
    QVERIFY(previewOfCurrent(w));
    const Camera cam = doc->scene().camera;

    // A click on the back wall selects that object; a click on nothing clears the selection.
    click(vp, widgetOf(vp, cam, V3d(278, 420, 559.2)));
    const Outliner::Selection wall = w.outliner()->selection();
    QCOMPARE(wall.kind, Outliner::Kind::Object);
    QCOMPARE(doc->scene().objects[size_t(wall.index)].name, std::string("back_wall"));
    click(vp, widgetOf(vp, cam, V3d(200, 165, 150)));  // the top of the short block
    QCOMPARE(doc->scene().objects[size_t(w.outliner()->selection().index)].name, std::string("short_block"));
    screenshot(*vp, "viewport_object_selected.png");
    click(vp, vp->imageRect().topLeft() + QPointF(1, 1));
    QCOMPARE(w.outliner()->selection().kind, Outliner::Kind::None);
    QCOMPARE(doc->undoStack()->count(), 0);  // selecting is no edit
    // A click on a light's marker selects the light.
    trigger(w, "actionAddPointLight");
    w.outliner()->select(Outliner::Kind::None, -1);
    click(vp, *vp->lightMarker(0));
    QCOMPARE(w.selectedLight(), 0);
    // Ctrl+click with a directional light selected: it falls straight onto the clicked floor.
    trigger(w, "actionAddDirectionalLight");
    QCOMPARE(w.selectedLight(), 1);
    QVERIFY(doc->scene().lights[1].direction != V3d(0, -1, 0));
    click(vp, widgetOf(vp, cam, V3d(450, 0, 100)), Qt::ControlModifier);
    QCOMPARE(doc->scene().lights[1].direction, V3d(0, -1, 0));
    trigger(w, "actionUndo");
    QVERIFY(doc->scene().lights[1].direction != V3d(0, -1, 0));

    // Keys fly the camera: W forward by a twentieth of the distance to the target, target along.
    const int steps = doc->undoStack()->index();
    vp->setFocus();
    const double dist = (cam.target - cam.position).length();
    QTest::keyClick(vp, Qt::Key_W);
    QVERIFY(near(doc->scene().camera.position, cam.position + V3d(0, 0, 0.05 * dist), 1e-9));
    QVERIFY(near(doc->scene().camera.target, cam.target + V3d(0, 0, 0.05 * dist), 1e-9));
    QCOMPARE(doc->undoStack()->index(), steps + 1);
    // Held keys (auto-repeat) are one undo step: D (right is -x here) held for four steps,
    // E (up) joining while D is down.
    key(vp, QEvent::KeyPress, Qt::Key_D, false);
    key(vp, QEvent::KeyPress, Qt::Key_D, true);
    key(vp, QEvent::KeyPress, Qt::Key_D, true);
    key(vp, QEvent::KeyPress, Qt::Key_E, false);
    key(vp, QEvent::KeyRelease, Qt::Key_E, false);
    key(vp, QEvent::KeyPress, Qt::Key_D, true);
    key(vp, QEvent::KeyRelease, Qt::Key_D, false);
    QCOMPARE(doc->undoStack()->index(), steps + 2);
    const V3d flown = cam.position + V3d(0, 0, 0.05 * dist) + V3d(-4 * 0.05 * dist, 0.05 * dist, 0);
    QVERIFY2(near(doc->scene().camera.position, flown, 1e-9), qPrintable(str(doc->scene().camera.position)));
    // With Ctrl the key is not a fly step.
    const Camera flownCamera = doc->scene().camera;
    QTest::keyClick(vp, Qt::Key_W, Qt::ControlModifier);
    QCOMPARE(doc->scene().camera, flownCamera);
    trigger(w, "actionUndo");
    trigger(w, "actionUndo");
    QCOMPARE(doc->scene().camera, cam);
    doc->markSaved();
}

QTEST_MAIN(TestViewportEditing)
#include "test_viewport_editing.moc"
