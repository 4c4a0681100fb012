// The plan view and the camera panel (issue 25) driven as a user would, in the real window:
// switch to the plan, find a light's symbol where the plan projection puts it, drag it and see
// it move by the snapped amount in x and z (y unchanged, one undo step); a calculation grid drawn
// in false colour with iso-lux lines; the camera panel's fields, View All and Reset Camera; an
// imported two-room model gets its camera inside the larger room. Expected values come from this
// file's own arithmetic (projections, snapping, ray geometry), not from the code under test.
// Saves screenshots (plan_*.png) in the test's working directory.

#include "core/photometry/calculation_grid.h"
#include "core/image/image.h"
#include "core/mesh/model_import.h"
#include "core/scene/scene_geometry.h"
#include "core/scene/scene_io.h"
#include "render/display/false_colour.h"
#include "render/display/iso_lines.h"
#include "render/display/plan_scales.h"
#include "ui/viewport/camera_navigation.h"
#include "ui/scene_panels/camera_panel.h"
#include "ui/calculation/grid_panel.h"
#include "ui/rendering/live_preview.h"
#include "ui/window/main_window.h"
#include "ui/scene_panels/outliner.h"
#include "ui/plan/plan_view.h"
#include "render/trace/room_camera.h"
#include "ui/window/view_area.h"
#include "ui/viewport/viewport.h"
#include "window_test_helpers.h"

#include <QFile>
#include <QLabel>
#include <QPushButton>
#include <QTemporaryDir>
#include <QtTest>


using namespace lucerna;
using namespace lucerna::test;

namespace {

void drag(QWidget* w, QPointF from, QPointF to, int steps = 6) {
    sendMouse(w, QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    for (int i = 1; i <= steps; ++i)
        sendMouse(w, QEvent::MouseMove, from + (to - from) * (double(i) / steps), Qt::NoButton, Qt::LeftButton);
    sendMouse(w, QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
}

// Two rooms under one ceiling, 2.8 m high: A is 6 x 4 m (x 0..6), B is 3 x 4 m (x 6..9), with a
// partition at x = 6. Coordinates in units of `unit` metres.
QString twoRoomObj(double unit) {
    const auto v = [unit](double x, double y, double z) {
        return QString("v %1 %2 %3\n").arg(x / unit).arg(y / unit).arg(z / unit);
    };
    QString s;
    const auto quad = [&](std::array<double, 12> c) {
        for (int k = 0; k < 4; ++k) s += v(c[size_t(3 * k)], c[size_t(3 * k + 1)], c[size_t(3 * k + 2)]);
        s += "f -4 -3 -2 -1\n";
    };
    const double h = 2.8;
    quad({0, 0, 0, 9, 0, 0, 9, 0, 4, 0, 0, 4});      // floor
    quad({0, h, 0, 0, h, 4, 9, h, 4, 9, h, 0});      // ceiling
    quad({0, 0, 0, 0, h, 0, 9, h, 0, 9, 0, 0});      // wall z = 0
    quad({0, 0, 4, 9, 0, 4, 9, h, 4, 0, h, 4});      // wall z = 4
    quad({0, 0, 0, 0, 0, 4, 0, h, 4, 0, h, 0});      // wall x = 0
    quad({9, 0, 0, 9, h, 0, 9, h, 4, 9, 0, 4});      // wall x = 9
    quad({6, 0, 0, 6, h, 0, 6, h, 4, 6, 0, 4});      // partition x = 6
    return s;
}

}  // namespace

class TestPlanView : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { useTestSettings("test_plan_view"); }
    void planShowsAndMovesALight();
    void gridDrawnWithIsoLux();
    void isoLinesOfARamp();
    void legendAndScaleBarRules();
    void computedGridOnTheInterior();
    void cameraPanelViewAllAndReset();
    void importedRoomsGetACameraInTheLargerRoom();
};

void TestPlanView::planShowsAndMovesALight() {
    MainWindow w(cornellPath());
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    Document* doc = w.document();
    trigger(w, "actionViewPlan");
    QCOMPARE(w.viewArea()->currentWidget(), static_cast<QWidget*>(w.planView()));
    QCOMPARE(w.viewArea()->mode(), ViewArea::Mode::Plan);
    PlanView* plan = w.planView();

    // Two point lights at known places, 100 x 50 mm apart in x and z.
    trigger(w, "actionAddPointLight");
    trigger(w, "actionAddPointLight");
    const int a = int(doc->scene().lights.size()) - 2, b = a + 1;
    doc->modify([&](Scene& s) {
        s.lights[size_t(a)].position = V3d(200, 400, 150);
        s.lights[size_t(b)].position = V3d(300, 300, 200);
    });
    QCoreApplication::processEvents();
    const QPointF pa = *plan->lightSymbol(a), pb = *plan->lightSymbol(b);
    // The plan from above: x to the right, z down the screen, one scale for both, y dropped.
    const double scale = (pb.x() - pa.x()) / 100.0;  // pixels per mm
    QVERIFY2(scale > 0.1, qPrintable(QString::number(scale)));
    QVERIFY2(std::abs((pb.y() - pa.y()) - 50 * scale) < 0.5, qPrintable(QString("%1 %2").arg(pb.y() - pa.y()).arg(50 * scale)));
    // Both inside the widget, over the box's floor, which spans 0..556 mm.
    const QPointF origin = pa - QPointF(200, 150) * scale;  // where x = z = 0 is drawn
    QVERIFY(plan->rect().contains(origin.toPoint()) && plan->rect().contains((origin + QPointF(556, 559) * scale).toPoint()));

    // The symbol is drawn there, in the light colour (the cross's arm right of the centre).
    QImage image = plan->grab().toImage();
    QVERIFY(image.save("plan_cornell_top.png"));
    QVERIFY2(nearestColour(image, pa + QPointF(4, 0), PlanView::lightColour()) < 60,
             qPrintable(image.pixelColor(pa.toPoint() + QPoint(4, 0)).name()));
    QVERIFY(nearestColour(image, pb + QPointF(0, 4), PlanView::lightColour()) < 60);
    // Far from any symbol there is no light colour.
    QVERIFY(nearestColour(image, origin + QPointF(500, 500) * scale, PlanView::lightColour()) > 100);

    // Drag light a by (70, 40) pixels with the 0.25 m (250 mm) snap: x and z move to the nearest
    // multiple of 250 mm of where the mouse put them, y stays.
    QCOMPARE(plan->snapMeters(), 0.25);
    const Light before = doc->scene().lights[size_t(a)];
    const int steps = doc->undoStack()->count();
    const QPointF by(70, 40);
    drag(plan, pa, pa + by);
    const double rawX = 200 + by.x() / scale, rawZ = 150 + by.y() / scale;
    const double wantX = std::round(rawX / 250) * 250, wantZ = std::round(rawZ / 250) * 250;
    const Light& after = doc->scene().lights[size_t(a)];
    QVERIFY2(after.position.x == wantX && after.position.z == wantZ,
             qPrintable(QString("moved to %1, %2; want %3, %4 (raw %5, %6)")
                            .arg(after.position.x).arg(after.position.z).arg(wantX).arg(wantZ).arg(rawX).arg(rawZ)));
    QCOMPARE(after.position.y, before.position.y);
    QCOMPARE(doc->undoStack()->count(), steps + 1);
    QCOMPARE(w.selectedLight(), a);  // the dragged light is selected
    QCoreApplication::processEvents();
    QVERIFY(plan->grab().save("plan_cornell_moved.png"));
    doc->undoStack()->undo();
    QCOMPARE(doc->scene().lights[size_t(a)].position, before.position);

    // Without the snap the light follows the mouse exactly (to the pixel's share of a mm).
    plan->setSnapMeters(0);
    drag(plan, pa, pa + by);
    QVERIFY(std::abs(doc->scene().lights[size_t(a)].position.x - rawX) < 1e-6);
    QVERIFY(std::abs(doc->scene().lights[size_t(a)].position.z - rawZ) < 1e-6);
    QCOMPARE(doc->scene().lights[size_t(a)].position.y, before.position.y);

    // The front elevation: x to the right, y up the screen; z dropped.
    trigger(w, "actionViewFront");
    const QPointF fa = *plan->lightSymbol(a), fb = *plan->lightSymbol(b);
    const double fs = (fb.x() - fa.x()) / (doc->scene().lights[size_t(b)].position.x - doc->scene().lights[size_t(a)].position.x);
    QVERIFY(fs > 0);
    QVERIFY(std::abs((fb.y() - fa.y()) - (400 - 300) * fs) < 0.5);  // b is 100 mm lower: drawn lower
    QVERIFY(plan->grab().save("plan_cornell_front.png"));
    trigger(w, "actionViewPerspective");
    QCOMPARE(w.viewArea()->currentWidget(), static_cast<QWidget*>(w.viewport()));
}

void TestPlanView::gridDrawnWithIsoLux() {
    MainWindow w(cornellPath());
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    trigger(w, "actionViewPlan");
    PlanView* plan = w.planView();
    // A work-plane grid over the floor with a known field: 100 lx at x = 0 rising to 500 lx at
    // the far side in x (scene units mm), uniform in z.
    const Scene& scene = w.document()->scene();
    const SceneBounds bounds = sceneBounds(scene);
    const CalculationGrid grid = workPlaneGrid(bounds.lo, bounds.hi, scene.metersPerUnit, 0.0, 0.05);
    CalculationGrid fine = grid;
    fine.spacingMeters = 0.05;
    const GridLayout layout = layoutGrid(fine, scene.metersPerUnit);
    QVERIFY(layout.nu >= 8 && layout.nv >= 8);
    auto result = std::make_shared<GridResult>();
    const double x0 = layout.points.front().x, x1 = layout.points.back().x;
    for (const V3d& p : layout.points) result->lux.push_back(100 + 400 * (p.x - x0) / (x1 - x0));
    result->errorLux.assign(result->lux.size(), 1.0);
    plan->setGridResult(fine, layout, result);
    QCoreApplication::processEvents();
    const auto legend = plan->gridLegend();
    QVERIFY(legend);
    const std::vector<double> levels = plan->isoLevelsShown();
    QVERIFY2(levels.size() >= 3, qPrintable(QString::number(levels.size())));
    QImage image = plan->grab().toImage();
    QVERIFY(image.save("plan_grid_iso_lux.png"));

    // A cell centre (the middle row, a column whose value is away from every level) is its lux
    // in the legend's colour.
    const int j = layout.nv / 2;
    int checkedCells = 0;
    for (int i = 1; i + 1 < layout.nu; ++i) {
        const size_t k = size_t(j) * size_t(layout.nu) + size_t(i);
        const double e = result->lux[k];
        bool nearLevel = false;
        const double cellLux = 400.0 / (x1 - x0) * (layout.points[1].x - layout.points[0].x);
        for (double level : levels) nearLevel |= std::abs(e - level) < 0.3 * cellLux;  // the line runs through the cell
        if (nearLevel) continue;
        const QPointF at = plan->widgetOf(layout.points[k]);
        QVERIFY2(nearestColour(image, at, legendColour(*legend, e), 0) < 30,
                 qPrintable(QString("cell %1: %2 against %3").arg(i).arg(image.pixelColor(at.toPoint()).name(), legendColour(*legend, e).name())));
        ++checkedCells;
    }
    QVERIFY(checkedCells >= 3);
    // Each level's line crosses the middle row where the ramp reaches it: a dark pixel there.
    for (double level : levels) {
        const double x = x0 + (level - 100) / 400 * (x1 - x0);
        const QPointF at = plan->widgetOf(V3d(x, layout.points[0].y, layout.points[size_t(j) * size_t(layout.nu)].z));
        QVERIFY2(nearestColour(image, at, PlanView::isoLineColour(), 1) < 150,
                 qPrintable(QString("level %1 at %2, %3: %4").arg(level).arg(at.x()).arg(at.y()).arg(image.pixelColor(at.toPoint()).name())));
    }
}

void TestPlanView::computedGridOnTheInterior() {
    // The bundled interior, a work-plane grid computed through the dock (0.5 m spacing, a loose
    // 20% target: the test is about the drawing, not the numbers), then the plan.
    MainWindow w(QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/interior.json"));
    w.resize(1400, 900);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    GridPanel* panel = w.gridPanel();
    child<QDoubleSpinBox>(*panel, "gridSpacing")->setValue(0.5);
    child<QDoubleSpinBox>(*panel, "gridTarget")->setValue(20.0);
    QTest::mouseClick(child<QPushButton>(*panel, "gridCompute"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!panel->isComputing(), 60000);
    const auto result = panel->result();
    QVERIFY(result && !result->lux.empty());
    trigger(w, "actionViewPlan");
    PlanView* plan = w.planView();
    QCoreApplication::processEvents();
    const auto legend = plan->gridLegend();
    QVERIFY(legend);
    QVERIFY(!plan->isoLevelsShown().empty());
    const QImage image = plan->grab().toImage();
    QVERIFY(image.save("plan_interior_grid.png"));
    QVERIFY(w.grab().save("plan_interior_window.png"));
    // Every cell centre no light symbol or label covers shows its point's lux in the legend's colour.
    const GridLayout& layout = panel->layout();
    int matching = 0, checked = 0;
    for (size_t k = 0; k < layout.points.size(); ++k) {
        const QPointF at = plan->widgetOf(layout.points[k]);
        bool nearLight = false;
        for (int i = 0; i < int(w.document()->scene().lights.size()); ++i)
            if (const auto c = plan->lightSymbol(i)) nearLight |= QLineF(*c, at).length() < 30;  // the symbol and its name
        if (nearLight) continue;
        ++checked;
        if (nearestColour(image, at, legendColour(*legend, result->lux[k]), 0) < 30) ++matching;
    }
    // Iso-lux lines and their labels cross some cells' centres.
    QVERIFY2(checked >= 10 && matching >= checked * 8 / 10, qPrintable(QString("%1 of %2").arg(matching).arg(checked)));
    // Moving a light in the plan leaves the grid out of date, and the plan says so; a camera move
    // does not.
    QVERIFY(!plan->gridOutOfDate());
    Camera moved = w.document()->scene().camera;
    moved.position.x += 0.5;
    w.document()->setCamera(moved);
    QVERIFY(!plan->gridOutOfDate());
    const QPointF pendant = *plan->lightSymbol(6);
    drag(plan, pendant, pendant + QPointF(40, 0));
    QVERIFY(plan->gridOutOfDate());
    QVERIFY(plan->grab().save("plan_interior_out_of_date.png"));
}

void TestPlanView::isoLinesOfARamp() {
    // Round levels strictly inside the range.
    const std::vector<double> levels = isoLevels(100, 500);
    QVERIFY(!levels.empty());
    for (double l : levels) QVERIFY(l > 100 && l < 500 && std::fmod(l, 50) == 0);
    QVERIFY(isoLevels(300, 300).empty());
    // A ramp along i on a 5 x 3 lattice: the 250 level crosses each row at i = 1.5.
    std::vector<double> v;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 5; ++i) v.push_back(100 + 100 * i);
    const std::vector<IsoSegment> s = isoSegments(v, 5, 3, {250});
    QCOMPARE(s.size(), size_t(2));  // one per row of cells
    for (const IsoSegment& seg : s) {
        QCOMPARE(seg.i0, 1.5);
        QCOMPARE(seg.i1, 1.5);
        QCOMPARE(std::abs(seg.j1 - seg.j0), 1.0);
    }
}

void TestPlanView::legendAndScaleBarRules() {
    // The one legend rule of every plan (the window's and the report's): values within a factor
    // of ten on a linear scale between round numbers, the iso levels on it.
    GridStatistics s;
    s.minimum = 123, s.maximum = 487;
    const PlanScale linear = planScale(s);
    QVERIFY(!linear.logScale);
    QCOMPARE(linear.lo, 100.0);
    QCOMPARE(linear.hi, 500.0);
    QCOMPARE(linear.levels, isoLevels(123, 487));
    // A sun patch (more than ten times Emin): logarithmic, levels at 1, 2 and 5 times the decades.
    s.minimum = 30, s.maximum = 2500;
    const PlanScale log = planScale(s);
    QVERIFY(log.logScale);
    QCOMPARE(log.lo, 20.0);
    QCOMPARE(log.hi, 5000.0);
    QCOMPARE(log.levels, (std::vector<double>{50, 100, 200, 500, 1000, 2000}));
    // The scale bar: the longest of 1, 2 or 5 times a power of ten metres that fits.
    QCOMPARE(scaleBarMeters(100, 250), 2.0);
    QCOMPARE(scaleBarMeters(100, 99), 0.5);
    QCOMPARE(scaleBarMeters(2, 150), 50.0);
    QCOMPARE(scaleBarMeters(0, 150), 0.0);
}

void TestPlanView::cameraPanelViewAllAndReset() {
    MainWindow w(cornellPath());
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    Document* doc = w.document();
    const Camera opened = loadScene(cornellPath().toStdString()).camera;
    QCOMPARE(doc->scene().camera, opened);
    CameraPanel* panel = w.cameraPanel();
    panel->parentWidget()->show();
    panel->window()->activateWindow();
    // The fields show the camera; a typed value is one undo step.
    auto* fov = child<QDoubleSpinBox>(*panel, "cameraFov");
    QCOMPARE(fov->value(), std::round(opened.fovYDeg * 100) / 100);
    const int steps = doc->undoStack()->count();
    typeInto(fov, 50);
    QCOMPARE(doc->scene().camera.fovYDeg, 50.0);
    QCOMPARE(doc->undoStack()->count(), steps + 1);
    typeInto(child<QDoubleSpinBox>(*panel, "cameraPosition0"), 100);
    QCOMPARE(doc->scene().camera.position.x, 100.0);
    QCOMPARE(doc->scene().camera.position.y, opened.position.y);
    QCOMPARE(doc->undoStack()->count(), steps + 2);
    // A target on the position is refused, with a line, and changes nothing.
    typeInto(child<QDoubleSpinBox>(*panel, "cameraTarget0"), 100);  // (100, 273, 0): still in front
    QCOMPARE(doc->scene().camera.target.x, 100.0);
    const Camera good = doc->scene().camera;
    const int beforeRefusal = doc->undoStack()->count();
    auto* tz = child<QDoubleSpinBox>(*panel, "cameraTarget2");
    typeInto(tz, opened.position.z);
    QCOMPARE(doc->scene().camera, good);
    QCOMPARE(doc->undoStack()->count(), beforeRefusal);
    QCOMPARE(tz->value(), good.target.z);  // the field shows the camera as it is
    QVERIFY(!child<QLabel>(*panel, "cameraError")->text().isEmpty());
    // The undo stack walks the fields back.
    doc->undoStack()->undo();
    QCOMPARE(doc->scene().camera.target.x, opened.target.x);
    doc->undoStack()->undo();
    QCOMPARE(doc->scene().camera.position.x, opened.position.x);
    QCOMPARE(fov->value(), 50.0);
    doc->undoStack()->redo();

    // Orbit far off: View All puts every corner of the scene's bounds in the picture.
    doc->setCamera(orbitCamera(doc->scene().camera, 2.0, 0.6));
    doc->setCamera(dollyCamera(doc->scene().camera, 0.05));
    trigger(w, "actionViewAll");
    const Camera all = doc->scene().camera;
    const SceneBounds b = sceneBounds(doc->scene());
    for (int k = 0; k < 8; ++k) {
        const V3d corner(k & 1 ? b.hi.x : b.lo.x, k & 2 ? b.hi.y : b.lo.y, k & 4 ? b.hi.z : b.lo.z);
        const auto r = projectToRaster(all, corner);
        QVERIFY(r);
        QVERIFY2(r->x >= 0 && r->x <= all.width && r->y >= 0 && r->y <= all.height,
                 qPrintable(QString("corner %1 at %2, %3").arg(k).arg(r->x).arg(r->y)));
    }
    // Reset Camera: the camera the scene was opened with, one undo step.
    const int beforeReset = doc->undoStack()->count();
    trigger(w, "actionResetCamera");
    QCOMPARE(doc->scene().camera, opened);
    QCOMPARE(doc->undoStack()->count(), beforeReset + 1);
    QCOMPARE(fov->value(), std::round(opened.fovYDeg * 100) / 100);
    doc->undoStack()->undo();
    QCOMPARE(doc->scene().camera, all);
    QVERIFY(panel->grab().save("plan_camera_panel.png"));
    doc->undoStack()->setClean();  // nothing to ask about on close
}

void TestPlanView::importedRoomsGetACameraInTheLargerRoom() {
    QTemporaryDir dir;
    const QString path = dir.filePath("two-rooms.obj");
    {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(twoRoomObj(1.0).toUtf8());
    }
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    Document* doc = w.document();
    QVERIFY2(w.importModelFile(path), qPrintable(w.lastError()));
    QCOMPARE(doc->undoStack()->count(), 1);  // the import and its camera: one step
    const Camera c = doc->scene().camera;
    // Inside room A (x 0..6, z 0..4), at eye height, looking horizontally at a point in the room.
    QVERIFY2(c.position.x > 0 && c.position.x < 6 && c.position.z > 0 && c.position.z < 4,
             qPrintable(QString("%1 %2 %3").arg(c.position.x).arg(c.position.y).arg(c.position.z)));
    QVERIFY(std::abs(c.position.y - 1.6) < 1e-6);
    QVERIFY(c.target.x > 0 && c.target.x < 6 && c.target.z > 0 && c.target.z < 4);
    QCOMPARE(c.target.y, c.position.y);
    QVERIFY(std::abs(c.up.y - 1) < 1e-12);
    // The plan draws the camera in the larger room; a light over the middle of that room lights
    // what the camera sees (the first image is not black).
    trigger(w, "actionViewPlan");
    QCoreApplication::processEvents();
    QImage planImage = w.planView()->grab().toImage();
    QVERIFY(planImage.save("plan_two_rooms.png"));
    QVERIFY(nearestColour(planImage, w.planView()->widgetOf(c.position), PlanView::cameraColour()) < 40);
    trigger(w, "actionViewPerspective");
    trigger(w, "actionAddPointLight");
    const int light = int(doc->scene().lights.size()) - 1;
    doc->modify([&](Scene& s) {
        s.lights[size_t(light)].position = V3d(3, 2.5, 2);
        s.lights[size_t(light)].intensity = Rgbd(20, 20, 20);
    });
    const SceneBounds lit = sceneBounds(doc->scene());
    QVERIFY(lit.hi.x <= 9 + 1e-9);
    const SceneSnapshot want = doc->snapshot();
    const bool framed = QTest::qWaitFor([&] { return w.livePreview()->frame() && w.livePreview()->frame()->scene == want; }, 30000);
    QVERIFY(framed);
    const auto shown = w.livePreview()->frame();
    const Image& frame = shown->image;
    double sum = 0;
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) sum += frame.at(x, y).y;
    QVERIFY2(sum / (frame.width * frame.height) > 1e-3, qPrintable(QString::number(sum)));
    QCoreApplication::processEvents();
    QVERIFY(w.viewport()->grab().save("plan_two_rooms_perspective.png"));
    doc->undoStack()->undo();  // the light
    QCOMPARE(doc->scene().camera, c);

    // Reset Camera returns to it after an orbit out of the room.
    doc->setCamera(dollyCamera(orbitCamera(c, 1.0, 0.5), 30.0));
    trigger(w, "actionResetCamera");
    QCOMPARE(doc->scene().camera, c);
    QVERIFY(doc->undoStack()->undoText().size() > 0);
    doc->undoStack()->setClean();

    // The same building in centimetres in a centimetre scene: eye height is 160 units.
    const QString cm = dir.filePath("two-rooms-cm.obj");
    {
        QFile f(cm);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(twoRoomObj(0.01).toUtf8());
    }
    ImportOptions options;
    options.sceneMetersPerUnit = 0.01;
    options.fileMetersPerUnit = 0.01;
    ModelImport m = importModel(cm.toStdString(), options);
    Scene scene;
    scene.metersPerUnit = 0.01;
    scene.materials = m.materials;
    for (Object& o : m.objects) scene.objects.push_back(resolvedObject(scene, std::move(o)));
    const auto placed = cameraInLargestRoom(scene, scene.camera);
    QVERIFY(placed);
    QVERIFY(placed->position.x > 0 && placed->position.x < 600 && placed->position.z > 0 && placed->position.z < 400);
    QVERIFY(std::abs(placed->position.y - 160) < 1e-6);
    // An open model (a floor alone) has no room: nothing.
    Scene open;
    Object floor = scene.objects.front();
    TriangleMesh quad;
    quad.vertices = {V3d(0, 0, 0), V3d(100, 0, 0), V3d(100, 0, 100), V3d(0, 0, 100)};
    quad.triangles = {V3i(0, 1, 2), V3i(0, 2, 3)};
    floor.worldMesh = std::make_shared<TriangleMesh>(quad);
    open.materials = scene.materials;
    open.objects = {floor};
    QVERIFY(!cameraInLargestRoom(open, open.camera));
}

QTEST_MAIN(TestPlanView)
#include "test_plan_view.moc"
