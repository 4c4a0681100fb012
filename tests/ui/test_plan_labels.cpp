// The plan with a hundred luminaires (issue 40): names placed without overlap and hidden by
// View > Luminaire Labels, a symbol per luminaire type with its key, legends on round steps with
// the target marked; and the placement's rules on constructed symbols.
#include "core/photometry/calculation_grid.h"
#include "core/image/image.h"
#include "core/mesh/model_import.h"
#include "core/scene/scene_geometry.h"
#include "core/scene/scene_io.h"
#include "render/display/false_colour.h"
#include "render/display/iso_lines.h"
#include "render/display/luminaire_symbols.h"
#include "render/display/plan_scales.h"
#include "ui/viewport/camera_navigation.h"
#include "ui/scene_panels/camera_panel.h"
#include "ui/calculation/grid_panel.h"
#include "ui/rendering/live_preview.h"
#include "ui/window/main_window.h"
#include "ui/scene_panels/outliner.h"
#include "ui/plan/label_placement.h"
#include "ui/plan/plan_view.h"
#include "render/trace/room_camera.h"
#include "ui/window/view_area.h"
#include "ui/viewport/viewport.h"
#include "window_test_helpers.h"
#include <QFile>
#include <QLabel>
#include <QMenuBar>
#include <QPushButton>
#include <QTemporaryDir>
#include <QtTest>
#include <random>

#include <cmath>

using namespace lucerna;
using namespace lucerna::test;

namespace {

}  // namespace

class TestPlanLabels : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { useTestSettings("test_plan_labels"); }
    void officeFloorLabelsAndLegends();
    void labelPlacementRules();
};

void TestPlanLabels::officeFloorLabelsAndLegends() {
    // The bundled office floor (108 luminaires of two files) at the designer's window size: the
    // names drawn must not overlap one another, the symbols or the legends, and stay in the view.
    MainWindow w(QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/office_floor.json"));
    w.resize(1600, 1000);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    trigger(w, "actionViewPlan");
    PlanView* plan = w.planView();
    const Scene& scene = w.document()->scene();
    QCOMPARE(scene.lights.size(), size_t(108));

    // Two types, two shapes: a panel's symbol fills its square's corner, a pendant's does not.
    const PlanLightTypes types = planLightTypes(scene);
    QCOMPARE(types.types.size(), size_t(2));
    QCOMPARE(types.types[0].count + types.types[1].count, 108);
    QVERIFY(types.types[0].shape != types.types[1].shape);
    QImage bare = plan->grab().toImage();
    int squares = 0, diamonds = 0;
    const double r = PlanView::kSymbolRadius;
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const QPointF corner = *plan->lightSymbol(int(i)) + QPointF(r, r);
        const bool filled = nearestColour(bare, corner, PlanView::lightColour(), 1) < 60;
        const SymbolShape shape = types.types[size_t(types.typeOfLight[i])].shape;
        if (shape == SymbolShape::Square && filled) ++squares;
        if (shape == SymbolShape::Diamond && !filled) ++diamonds;
    }
    QCOMPARE(squares, 84);
    QCOMPARE(diamonds, 24);

    // The open-plan desks' task area as the grid, 483 to 703 lx as the designer's was.
    const TaskArea& area = scene.taskAreas.at(0);
    const GridLayout layout = layoutGrid(area.grid, scene.metersPerUnit);
    auto result = std::make_shared<GridResult>();
    for (size_t k = 0; k < layout.points.size(); ++k) result->lux.push_back(483.2 + 220.2 * double(k % 7) / 6);
    result->errorLux.assign(result->lux.size(), 1.0);
    plan->setGridResult(area.grid, layout, result);
    QImage image = plan->grab().toImage();
    QVERIFY(image.save("plan_office_floor.png"));
    QVERIFY(w.grab().save("plan_office_floor_window.png"));

    // The legend marks the area's Em (EN 12464-1 5.26.2: 500 lx) and centres on it: 0 to 2 Em,
    // ticked at round values.
    const auto legend = plan->gridLegend();
    QVERIFY(legend && legend->target);
    QCOMPARE(*legend->target, 500.0);
    QCOMPARE(legend->lo, 0.0);
    QCOMPARE(legend->hi, 1000.0);
    QCOMPARE(legendTicks(*legend), (std::vector<double>{0, 200, 400, 600, 800, 1000}));
    QCOMPARE(legendPosition(*legend, 500), 0.5);
    const std::vector<QRectF> legends = plan->legendRects();
    QCOMPARE(legends.size(), size_t(2));  // the false-colour legend, the key of types
    QCOMPARE(legends[0], QRectF(legendFrame(plan->rect())));
    QVERIFY(!legends[0].intersects(legends[1]));

    const auto overlap = [](const QRectF& a, const QRectF& b) {
        return std::min(a.right(), b.right()) > std::max(a.left(), b.left()) + 1e-9 &&
               std::min(a.bottom(), b.bottom()) > std::max(a.top(), b.top()) + 1e-9;
    };
    const std::vector<QRectF> labels = plan->visibleLabelRects();
    QVERIFY2(labels.size() >= 10, qPrintable(QString::number(labels.size())));
    for (size_t i = 0; i < labels.size(); ++i) {
        QVERIFY(QRectF(plan->rect()).contains(labels[i]));
        for (size_t j = i + 1; j < labels.size(); ++j) QVERIFY2(!overlap(labels[i], labels[j]), qPrintable(QString("%1 %2").arg(i).arg(j)));
        for (const QRectF& l : legends) QVERIFY(!overlap(labels[i], l));
        for (size_t k = 0; k < scene.lights.size(); ++k) {
            const QPointF c = *plan->lightSymbol(int(k));
            QVERIFY(!overlap(labels[i], QRectF(c - QPointF(r, r), c + QPointF(r, r))));
        }
    }
    // The legend's box is opaque and on top: its background colour fills its margin right of the
    // labels, all the way down.
    const QRect frame = legendFrame(plan->rect());
    const QColor background = image.pixelColor(frame.right() - 1, frame.center().y());
    for (int y = frame.top() + 1; y < frame.bottom(); y += 3) QCOMPARE(image.pixelColor(frame.right() - 1, y), background);

    // View > Luminaire Labels: off hides every name.
    QAction* toggle = plan->labelsAction();
    QVERIFY(toggle->isCheckable() && toggle->isChecked());
    bool inViewMenu = false;
    for (QAction* m : w.menuBar()->actions())
        if (m->menu() && m->menu()->actions().contains(toggle)) inViewMenu = m->text().remove('&') == "View";
    QVERIFY(inViewMenu);
    trigger(w, "actionLuminaireLabels");
    QVERIFY(!toggle->isChecked());
    const QImage unlabelled = plan->grab().toImage();
    QVERIFY(plan->visibleLabelRects().empty());
    QVERIFY(unlabelled != image);
    trigger(w, "actionLuminaireLabels");
    plan->grab();
    QCOMPARE(plan->visibleLabelRects().size(), labels.size());

    // Bands: one colour per band between round values.
    plan->setLegendScale(LegendScale::Bands);
    const auto banded = plan->gridLegend();
    QVERIFY(banded && banded->scale() == LegendScale::Bands);
    QCOMPARE(banded->bands, (std::vector<double>{0, 200, 400, 600, 800, 1000}));
    QCOMPARE(legendColour(*banded, 510), legendColour(*banded, 590));
    QVERIFY(legendColour(*banded, 590) != legendColour(*banded, 610));
    QVERIFY(plan->grab().save("plan_office_floor_bands.png"));
}

void TestPlanLabels::labelPlacementRules() {
    // Right first; where the right is taken, the left; then above, then below; else none.
    const QRectF bounds(0, 0, 400, 300);
    const QSizeF size(40, 12);
    const QRectF symbol(100, 100, 10, 10);
    auto placed = placeLabels({{symbol, size}}, {}, bounds, 3);
    QCOMPARE(*placed[0], QRectF(QPointF(113, 99), size));
    placed = placeLabels({{symbol, size}}, {QRectF(115, 100, 5, 5)}, bounds, 3);
    QCOMPARE(*placed[0], QRectF(QPointF(100 - 3 - 40, 99), size));
    placed = placeLabels({{symbol, size}}, {QRectF(115, 100, 5, 5), QRectF(60, 100, 5, 5), QRectF(100, 88, 5, 5)}, bounds, 3);
    QCOMPARE(*placed[0], QRectF(QPointF(85, 113), size));
    placed = placeLabels({{symbol, size}}, {QRectF(115, 100, 5, 5), QRectF(60, 100, 5, 5), QRectF(100, 88, 5, 5), QRectF(100, 120, 5, 5)},
                         bounds, 3);
    QVERIFY(!placed[0]);
    // At the view's edge the outward places are refused.
    placed = placeLabels({{QRectF(390, 5, 8, 8), size}}, {}, bounds, 3);
    QCOMPARE(*placed[0], QRectF(QPointF(390 - 3 - 40, 3), size));

    // A thousand symbols at random: whatever is placed keeps the promise.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> x(0, 800), y(0, 600), w(20, 90);
    std::vector<LabelRequest> requests;
    std::vector<QRectF> obstacles{QRectF(700, 0, 100, 300)};  // a legend
    for (int i = 0; i < 1000; ++i) {
        const QRectF s(x(rng), y(rng), 10, 10);
        requests.push_back({s, QSizeF(w(rng), 12)});
        obstacles.push_back(s);
    }
    const QRectF view(0, 0, 800, 600);
    placed = placeLabels(requests, obstacles, view, 3);
    std::vector<QRectF> labels;
    for (const auto& p : placed)
        if (p) labels.push_back(*p);
    QVERIFY2(labels.size() > 50 && labels.size() < 1000, qPrintable(QString::number(labels.size())));
    const auto overlap = [](const QRectF& a, const QRectF& b) { return a.intersected(b).width() > 1e-9 && a.intersected(b).height() > 1e-9; };
    for (size_t i = 0; i < labels.size(); ++i) {
        QVERIFY(view.contains(labels[i]));
        for (size_t j = i + 1; j < labels.size(); ++j) QVERIFY(!overlap(labels[i], labels[j]));
        for (const QRectF& o : obstacles) QVERIFY(!overlap(labels[i], o));
    }
}

QTEST_MAIN(TestPlanLabels)
#include "test_plan_labels.moc"
