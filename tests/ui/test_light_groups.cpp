// Light groups and the arrangement tool (issue 19): a field of luminaires by count and by spacing
// at the closed-form positions (the centres of the rectangle's cells, y = ceiling - suspension),
// one undo step; group edits of flux and colour temperature, one step for all; a multi-selection
// edits what its lights share; the outliner's group node (collapsed, a check box that switches
// the group); the window's refusal of too many layers; the drawn field in the plan view; a field
// of 100 x 100 lights (its times printed, never asserted). How switched-off lights and per-group
// layers render: test_light_group_rendering.

#include "core/photometry/light_output.h"
#include "core/photometry/luminaire.h"
#include "core/scene/scene_geometry.h"
#include "core/scene/scene_io.h"
#include "render/backend/light_layers/layered_backend.h"
#include "render/backend/light_layers/light_groups.h"
#include "render_helpers.h"
#include "ui/scene_panels/arrangement_dialog.h"
#include "ui/commands/light_group_commands.h"
#include "ui/rendering/converging_render.h"
#include "ui/scene_panels/light_arrangement.h"
#include "ui/properties/light_properties.h"
#include "ui/properties/light_set_properties.h"
#include "ui/io/luminaire_import.h"
#include "ui/window/main_window.h"
#include "ui/scene_panels/outliner.h"
#include "ui/plan/plan_view.h"
#include "ui/properties/properties_panel.h"
#include "window_test_helpers.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QToolButton>
#include <QtTest>

#include <cmath>

using namespace lucerna;
using namespace lucerna::test;

namespace {

// A room of 4 x 3 m, 3 m high (floor at y = 0, ceiling at y = 3), a table top at y = 0.75, and
// two point lights of 1000 lm.
std::string roomJson(double metersPerUnit = 1.0) {
    const double u = 1.0 / metersPerUnit;  // one metre in the scene's unit
    const auto n = [](double x) { return QString::number(x, 'g', 17).toStdString(); };
    const auto quad = [&](double y, double x0, double z0, double x1, double z1, bool down) {
        const std::string a = "[" + n(x0 * u) + ", " + n(y * u) + ", " + n(z0 * u) + "]";
        const std::string b = "[" + n(x1 * u) + ", " + n(y * u) + ", " + n(z0 * u) + "]";
        const std::string c = "[" + n(x1 * u) + ", " + n(y * u) + ", " + n(z1 * u) + "]";
        const std::string d = "[" + n(x0 * u) + ", " + n(y * u) + ", " + n(z1 * u) + "]";
        return down ? "[" + a + ", " + b + ", " + c + ", " + d + "]" : "[" + a + ", " + d + ", " + c + ", " + b + "]";
    };
    return R"({"lucerna": 1, "meters_per_unit": )" + n(metersPerUnit) + R"(,
  "camera": {"position": [)" + n(2 * u) + ", " + n(1.5 * u) + ", " + n(8 * u) + R"(], "target": [)" + n(2 * u) + ", " +
           n(1.5 * u) + ", " + n(1.5 * u) + R"(], "fov_y": 50, "resolution": [32, 24]},
  "materials": {"white": {"type": "diffuse", "albedo": [0.6, 0.6, 0.6]}},
  "objects": [{"name": "floor", "material": "white", "mesh": {"quad": )" + quad(0, 0, 0, 4, 3, false) + R"(}},
              {"name": "table", "material": "white", "mesh": {"quad": )" + quad(0.75, 1, 1, 2, 2, false) + R"(}},
              {"name": "ceiling", "material": "white", "mesh": {"quad": )" + quad(3, 0, 0, 4, 3, true) + R"(}}],
  "lights": [{"name": "a", "type": "point", "position": [)" + n(1 * u) + ", " + n(2 * u) + ", " + n(1 * u) +
           R"(], "lumens": 1000, "temperature": 3000},
             {"name": "b", "type": "spot", "position": [)" + n(3 * u) + ", " + n(2 * u) + ", " + n(2 * u) +
           R"(], "direction": [0, -1, 0], "lumens": 500, "temperature": 4000, "cone_angle": 40}]}
)";
}

Scene room(double metersPerUnit = 1.0) { return parseScene(roomJson(metersPerUnit), "room.json"); }

Light pointPrototype() {
    Light l;
    l.type = LightType::Point;
    PhotometricSpec lamp;
    lamp.value = 1000;
    lamp.temperatureK = 3000;
    return withPhotometric(l, lamp);
}

FieldArrangement field4x3() {
    FieldArrangement f;
    f.x0 = 0, f.z0 = 0, f.x1 = 4, f.z1 = 3;
    f.columns = 4, f.rows = 3;
    f.ceilingY = 3;
    f.suspensionM = 0.2;
    return f;
}

bool near(double a, double b, double eps = 1e-12) { return std::abs(a - b) <= eps; }

}  // namespace

class TestLightGroups : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { useTestSettings("test_light_groups"); }

    // A 4 x 3 field by count over the 4 x 3 m room: the centres of its 1 m cells, 0.2 m under the
    // ceiling, named by row and column, all in the group; one undo step adds and removes them all.
    void arrangesByCount() {
        Document doc(room());
        const int added = arrangeField(doc, field4x3(), pointPrototype(), "field");
        QCOMPARE(added, 12);
        const Scene& s = doc.scene();
        QCOMPARE(int(s.lights.size()), 14);
        QCOMPARE(doc.undoStack()->count(), 1);
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 4; ++i) {
                const Light& l = s.lights[size_t(2 + 4 * j + i)];
                QVERIFY(near(l.position.x, 0.5 + i) && near(l.position.y, 2.8) && near(l.position.z, 0.5 + j));
                QCOMPARE(l.group, std::string("field"));
                QCOMPARE(l.name, "field-" + std::to_string(j + 1) + "-" + std::to_string(i + 1));
                QVERIFY(std::abs(luminousFluxLm(l) - 1000) < 1e-9);
            }
        QCOMPARE(groupMembers(s, "field").size(), size_t(12));
        doc.undoStack()->undo();
        QCOMPARE(int(doc.scene().lights.size()), 2);
        QVERIFY(groupMembers(doc.scene(), "field").empty());
        doc.undoStack()->redo();
        QCOMPARE(int(doc.scene().lights.size()), 14);
        // A second field of the same name joins the group; names already taken get a suffix.
        arrangeField(doc, field4x3(), pointPrototype(), "field");
        QCOMPARE(doc.scene().lights.back().name, std::string("field-3-4-2"));
        QCOMPARE(groupMembers(doc.scene(), "field").size(), size_t(24));
    }

    // By spacing: 1 m gives the field by count exactly; 1.5 m fits two along each side, centred;
    // in a centimetre scene the spacing and the suspension are still metres.
    void arrangesBySpacing() {
        FieldArrangement f = field4x3();
        f.bySpacing = true;
        f.spacingXm = f.spacingZm = 1;
        const FieldLayout exact = layoutField(f, 1.0);
        const FieldLayout counted = layoutField(field4x3(), 1.0);
        QCOMPARE(exact.columns, 4);
        QCOMPARE(exact.rows, 3);
        for (size_t k = 0; k < counted.positions.size(); ++k) QVERIFY((exact.positions[k] - counted.positions[k]).length() < 1e-12);

        f.spacingXm = f.spacingZm = 1.5;
        const FieldLayout wide = layoutField(f, 1.0);
        QCOMPARE(wide.columns, 2);
        QCOMPARE(wide.rows, 2);
        const double xs[2] = {1.25, 2.75}, zs[2] = {0.75, 2.25};
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) QVERIFY((wide.positions[size_t(2 * j + i)] - V3d(xs[i], 2.8, zs[j])).length() < 1e-12);

        // Centimetres: the room is 400 x 300 units, 1 m = 100 units.
        FieldArrangement cm = f;
        cm.x1 = 400, cm.z1 = 300, cm.ceilingY = 300;
        cm.spacingXm = cm.spacingZm = 1;
        const FieldLayout inCm = layoutField(cm, 0.01);
        QCOMPARE(inCm.columns * inCm.rows, 12);
        QVERIFY((inCm.positions[0] - V3d(50, 280, 50)).length() < 1e-9);
        QVERIFY((inCm.positions.back() - V3d(350, 280, 250)).length() < 1e-9);

        // Through the document: one step, the spacing field in the group.
        Document doc(room());
        f.spacingXm = f.spacingZm = 1;
        QCOMPARE(arrangeField(doc, f, pointPrototype(), "by spacing"), 12);
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(groupMembers(doc.scene(), "by spacing").size(), size_t(12));
    }

    void refusesFieldsThatMakeNoSense() {
        const auto reason = [](FieldArrangement f) -> std::string {
            try {
                layoutField(f, 1.0);
            } catch (const std::invalid_argument& e) {
                return e.what();
            }
            return "(accepted)";
        };
        FieldArrangement flat = field4x3();
        flat.z1 = 0;
        QVERIFY(reason(flat).find("no area") != std::string::npos);
        FieldArrangement none = field4x3();
        none.rows = 0;
        QVERIFY(reason(none).find("at least one") != std::string::npos);
        FieldArrangement huge = field4x3();
        huge.columns = 101, huge.rows = 100;
        QVERIFY(reason(huge).find("at most 10000") != std::string::npos);
        FieldArrangement fine = field4x3();
        fine.bySpacing = true;
        fine.spacingXm = fine.spacingZm = 0.001;  // millions of lights: refused before any is made
        QVERIFY(reason(fine).find("at most 10000") != std::string::npos);
        FieldArrangement zero = fine;
        zero.spacingXm = 0;
        QVERIFY(reason(zero).find("positive") != std::string::npos);
        for (const std::string& r : {reason(flat), reason(none), reason(huge), reason(fine)}) QVERIFY(r.find('\n') == std::string::npos);

        // Nothing changes in the document, and no directional field.
        Document doc(room());
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, arrangeField(doc, flat, pointPrototype(), "x"));
        Light sun;
        sun.type = LightType::Directional;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, arrangeField(doc, field4x3(), sun, "x"));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, arrangeField(doc, field4x3(), pointPrototype(), ""));
        QCOMPARE(doc.undoStack()->count(), 0);
    }

    void findsTheCeiling() {
        const Scene s = room();
        QVERIFY(near(ceilingAbove(s, 2, 1.5), 3));
        QVERIFY(near(ceilingAbove(s, 1.5, 1.5), 3));  // over the table too: the highest surface
        QVERIFY(near(ceilingAbove(s, 9, 9), sceneBounds(s).hi.y));  // nothing over it
    }

    // The arrangement dialog: the scene's plan and ceiling by default, the field it would make,
    // and OK refused with a reason while the values make none.
    void dialogDescribesAndRefuses() {
        Document doc(room());
        ArrangementDialog dialog(doc, 0, nullptr);
        FieldArrangement f = dialog.arrangement();
        QVERIFY(near(f.x0, 0) && near(f.x1, 4) && near(f.z0, 0) && near(f.z1, 3));
        QVERIFY(near(f.ceilingY, 3));
        QVERIFY(dialog.problem().isEmpty());
        QCOMPARE(dialog.prototype().name, std::string("a"));  // the selected light is offered first
        dialog.setArrangement(field4x3());
        QVERIFY(dialog.findChild<QLabel*>("arrangeSummary")->text().startsWith("4 x 3 = 12 lights"));
        dialog.findChild<QDoubleSpinBox*>("arrangeX1")->setValue(0);
        QVERIFY(dialog.problem().contains("no area"));
        dialog.accept();
        QVERIFY(dialog.result() != QDialog::Accepted);
        QVERIFY(dialog.findChild<QLabel*>("arrangeError")->text().contains("no area"));
        dialog.setArrangement(field4x3());
        dialog.setLuminaireFile(QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/luminaires/no-such.ies"));
        dialog.accept();
        QVERIFY(dialog.result() != QDialog::Accepted);
        QVERIFY(dialog.findChild<QLabel*>("arrangeError")->text().contains("cannot read"));
        dialog.setLuminaireFile(QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/luminaires/downlight.ies"));
        QCOMPARE(dialog.prototype().type, LightType::Luminaire);
    }

    // A group's flux and colour temperature, each typed once: every light of the group changes,
    // one undo step restores them all.
    void groupEditIsOneUndoStep() {
        Document doc(room());
        arrangeField(doc, field4x3(), pointPrototype(), "field");
        LightSetProperties panel(&doc);
        panel.setGroup("field");
        QCOMPARE(panel.lights().size(), size_t(12));
        QVERIFY(panel.titleLabel()->text().contains("12 lights"));
        QCOMPARE(panel.fluxField()->value(), 1000.0);
        const int steps = doc.undoStack()->count();
        typeInto(panel.fluxField(), 2500);
        QCOMPARE(doc.undoStack()->count(), steps + 1);
        for (int i : groupMembers(doc.scene(), "field")) QVERIFY(std::abs(luminousFluxLm(doc.scene().lights[size_t(i)]) - 2500) < 1e-6);
        QVERIFY(std::abs(luminousFluxLm(doc.scene().lights[0]) - 1000) < 1e-6);  // not in the group
        typeInto(panel.temperatureField(), 4000);
        QCOMPARE(doc.undoStack()->count(), steps + 2);
        for (int i : groupMembers(doc.scene(), "field"))
            QCOMPARE(photometricOf(doc.scene().lights[size_t(i)]).temperatureK.value_or(0), 4000.0);
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        for (int i : groupMembers(doc.scene(), "field")) {
            const Light& l = doc.scene().lights[size_t(i)];
            QVERIFY(std::abs(luminousFluxLm(l) - 1000) < 1e-6);
            QCOMPARE(photometricOf(l).temperatureK.value_or(0), 3000.0);
        }
        // Switched off and on as one: the check box, one step.
        panel.onField()->click();
        QCOMPARE(doc.undoStack()->count(), steps + 1);
        for (int i : groupMembers(doc.scene(), "field")) QVERIFY(!doc.scene().lights[size_t(i)].on);
        QVERIFY(doc.scene().lights[0].on);
        QCOMPARE(panel.onField()->checkState(), Qt::Unchecked);
        doc.undoStack()->undo();
        QCOMPARE(panel.onField()->checkState(), Qt::Checked);
    }

    // Lights selected together: the fields show what they share ("mixed" otherwise), and an edit
    // sets it on all of them; grouping them is one step; the luminaire file replaces each one's
    // output at its own place.
    void multiSelectionEditsWhatTheyShare() {
        Document doc(room());
        LightSetProperties panel(&doc);
        panel.setLights({0, 1});
        QVERIFY(panel.titleLabel()->text().contains("2 lights selected"));
        QCOMPARE(panel.fluxField()->value(), panel.fluxField()->minimum());  // 1000 and 500: mixed
        QCOMPARE(panel.fluxField()->text(), QString("mixed"));
        QCOMPARE(panel.temperatureField()->text(), QString("mixed"));
        typeInto(panel.temperatureField(), 5000);
        QCOMPARE(doc.undoStack()->count(), 1);
        for (int i : {0, 1}) QCOMPARE(photometricOf(doc.scene().lights[size_t(i)]).temperatureK.value_or(0), 5000.0);
        QVERIFY(std::abs(luminousFluxLm(doc.scene().lights[0]) - 1000) < 1e-6);  // each keeps its flux
        QVERIFY(std::abs(luminousFluxLm(doc.scene().lights[1]) - 500) < 1e-6);
        QCOMPARE(panel.temperatureField()->value(), 5000.0);  // shared now
        typeInto(panel.fluxField(), 800);
        for (int i : {0, 1}) QVERIFY(std::abs(luminousFluxLm(doc.scene().lights[size_t(i)]) - 800) < 1e-6);

        panel.groupField()->setText("pair");
        QMetaObject::invokeMethod(panel.groupField(), "editingFinished");
        QCOMPARE(doc.undoStack()->count(), 3);
        QCOMPARE(groupMembers(doc.scene(), "pair"), (std::vector<int>{0, 1}));

        QString error;
        QVERIFY(!panel.replaceLuminaireFile("/no/such/file.ies", &error));
        QVERIFY(error.contains("file.ies") && !error.contains('\n'));
        QCOMPARE(doc.undoStack()->count(), 3);
        QVERIFY(panel.replaceLuminaireFile(QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/luminaires/downlight.ies"), &error));
        QCOMPARE(doc.undoStack()->count(), 4);
        for (int i : {0, 1}) {
            const Light& l = doc.scene().lights[size_t(i)];
            QCOMPARE(l.type, LightType::Luminaire);
            QVERIFY(l.luminaire && l.luminaire->distribution);
            QCOMPARE(l.luminaire->temperatureK.value_or(0), 5000.0);
            QCOMPARE(l.group, std::string("pair"));
        }
        QCOMPARE(doc.scene().lights[0].position, V3d(1, 2, 1));
        QVERIFY(panel.fileLabel()->text().contains("downlight.ies"));
        doc.undoStack()->undo();
        QCOMPARE(doc.scene().lights[1].type, LightType::Spot);
    }

    // The outliner: a group is one node, collapsed, after the lights before it; its check box is
    // partly checked when some of its lights are off and switches them all in one step;
    // selecting the node selects the group, Ctrl-selecting lights gives a multi-selection.
    void outlinerShowsGroups() {
        Document doc(room());
        arrangeField(doc, field4x3(), pointPrototype(), "field");
        Outliner outliner(&doc);
        QTreeWidgetItem* lights = outliner.heading(Outliner::Kind::Light);
        QCOMPARE(lights->childCount(), 3);  // a, b, the group
        QTreeWidgetItem* group = outliner.groupItem("field");
        QVERIFY(group);
        QCOMPARE(lights->child(2), group);
        QVERIFY(!group->isExpanded());
        QCOMPARE(group->childCount(), 12);
        QCOMPARE(group->text(1), QString("Group, 12 lights"));
        QCOMPARE(group->checkState(0), Qt::Checked);

        Outliner::Selection seen;
        connect(&outliner, &Outliner::selectionChangedTo, this, [&seen](const Outliner::Selection& s) { seen = s; });
        outliner.selectGroup("field");
        QCOMPARE(seen.kind, Outliner::Kind::Group);
        QCOMPARE(seen.group, std::string("field"));
        QCOMPARE(seen.lights.size(), size_t(12));
        outliner.selectLights({0, 5});
        QCOMPARE(seen.kind, Outliner::Kind::Lights);
        QCOMPARE(seen.lights, (std::vector<int>{0, 5}));
        outliner.select(Outliner::Kind::Light, 7);  // inside the group: the group opens
        QCOMPARE(seen.kind, Outliner::Kind::Light);
        QCOMPARE(seen.index, 7);
        QVERIFY(group->isExpanded());

        // One light off: the group is partly on; the group's box switches the rest in one step.
        outliner.lightItem(4)->setCheckState(0, Qt::Unchecked);
        QCOMPARE(doc.undoStack()->count(), 2);
        QVERIFY(!doc.scene().lights[4].on);
        QCOMPARE(group->checkState(0), Qt::PartiallyChecked);
        group->setCheckState(0, Qt::Unchecked);
        QCOMPARE(doc.undoStack()->count(), 3);
        for (int i : groupMembers(doc.scene(), "field")) QVERIFY(!doc.scene().lights[size_t(i)].on);
        QCOMPARE(outliner.lightItem(9)->checkState(0), Qt::Unchecked);
        doc.undoStack()->undo();
        QCOMPARE(group->checkState(0), Qt::PartiallyChecked);
        QVERIFY(doc.scene().lights[5].on && !doc.scene().lights[4].on);

        // A renamed group keeps its selection; the node opens as it was.
        outliner.selectGroup("field");
        std::vector<int> members = groupMembers(doc.scene(), "field");
        std::vector<Light> renamed;
        for (int i : members) {
            renamed.push_back(doc.scene().lights[size_t(i)]);
            renamed.back().group = "hall";
        }
        doc.undoStack()->push(new EditLightsCommand(&doc, members, renamed, 0, "rename"));
        QCOMPARE(seen.kind, Outliner::Kind::Group);
        QCOMPARE(seen.group, std::string("hall"));
        QVERIFY(!outliner.groupItem("field"));
    }

    // A single light's panel moves it into a group and out again, one step each.
    void singleLightJoinsAGroup() {
        Document doc(room());
        LightProperties panel(&doc);
        panel.setLight(1);
        QVERIFY(panel.groupField()->text().isEmpty());
        panel.groupField()->setText("spots");
        QMetaObject::invokeMethod(panel.groupField(), "editingFinished");
        QCOMPARE(doc.scene().lights[1].group, std::string("spots"));
        QCOMPARE(doc.undoStack()->count(), 1);
        panel.groupField()->setText("");
        QMetaObject::invokeMethod(panel.groupField(), "editingFinished");
        QVERIFY(doc.scene().lights[1].group.empty());
        doc.undoStack()->undo();
        QCOMPARE(panel.groupField()->text(), QString("spots"));
    }

    // The window's converging render with per-light layers on a scene of 65 lone lights: refused
    // with the one-line reason, shown as the render's error.
    void windowRefusesTooManyLayers() {
        Scene many = room();
        many.lights.clear();
        for (int i = 0; i < 65; ++i) {
            Light l = pointPrototype();
            l.name = "l" + std::to_string(i);
            l.position = V3d(0.1 + 0.05 * i, 2, 1.5);
            many.lights.push_back(l);
        }
        TaskSystem tasks(1);
        YieldGate gate;
        ConvergingRender render(tasks, gate);
        render.setBackend("path");
        render.setLightLayers(true);
        render.setScene(std::make_shared<const Scene>(many));
        render.start();
        QTRY_VERIFY_WITH_TIMEOUT(!render.error().isEmpty(), 30000);
        QVERIFY(render.error().contains("more than 64"));
        QVERIFY(!render.error().contains('\n'));
    }

    // The plan view: Draw Field, a drag in the plan, gives the rectangle (snapped) to the window.
    void planDrawsAField() {
        Document doc(room());
        YieldGate gate;
        PlanView plan(&doc, gate);
        plan.resize(600, 450);
        plan.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plan));
        plan.setDrawingField(true);
        QVERIFY(plan.drawFieldButton()->isChecked());
        std::array<double, 4> drawn{};
        connect(&plan, &PlanView::fieldDrawn, this,
                [&drawn](double x0, double z0, double x1, double z1) { drawn = {x0, z0, x1, z1}; });
        const QPointF a = plan.widgetOf(V3d(0.52, 0, 0.49)), b = plan.widgetOf(V3d(3.49, 0, 2.51));
        sendMouse(&plan, QEvent::MouseButtonPress, a, Qt::LeftButton, Qt::LeftButton);
        sendMouse(&plan, QEvent::MouseMove, (a + b) / 2, Qt::NoButton, Qt::LeftButton);
        sendMouse(&plan, QEvent::MouseMove, b, Qt::NoButton, Qt::LeftButton);
        sendMouse(&plan, QEvent::MouseButtonRelease, b, Qt::LeftButton, Qt::NoButton);
        QCOMPARE(drawn[0], 0.5);  // snapped to the 0.25 m grid
        QCOMPARE(drawn[1], 0.5);
        QCOMPARE(drawn[2], 3.5);
        QCOMPARE(drawn[3], 2.5);
        QVERIFY(!plan.drawFieldButton()->isChecked());  // one rectangle per use
        QCOMPARE(doc.undoStack()->count(), 0);
    }

    // The window: a field arranged selects its group, whose panel shows; Delete removes the group
    // in one step and Undo brings it back.
    void windowArrangesAndDeletesAGroup() {
        const QString path = QDir::temp().filePath("lucerna_test_light_groups_room.json");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QByteArray::fromStdString(roomJson()));
        f.close();
        MainWindow w(path);
        QVERIFY(w.document()->scene().lights.size() == 2);
        QVERIFY(w.arrangeField(field4x3(), pointPrototype(), "field"));
        QCOMPARE(w.outliner()->selection().kind, Outliner::Kind::Group);
        QCOMPARE(w.propertiesPanel()->currentWidget(), static_cast<QWidget*>(w.propertiesPanel()->lightSetProperties()));
        QVERIFY(!w.arrangeField(FieldArrangement{}, pointPrototype(), ""));
        QVERIFY(w.lastError().contains("group needs a name"));
        w.deleteSelection();
        QCOMPARE(int(w.document()->scene().lights.size()), 2);
        w.document()->undoStack()->undo();
        QCOMPARE(int(w.document()->scene().lights.size()), 14);
        QFile::remove(path);
    }

    // 100 x 100 = 10,000 luminaires: the arrangement, the outliner's rebuild, a group edit of the
    // flux and the plan's drawing, each timed and printed (not asserted: machines differ).
    void tenThousandLights() {
        Document doc(room());
        Outliner outliner(&doc);
        LightSetProperties panel(&doc);
        FieldArrangement f = field4x3();
        f.columns = 100, f.rows = 100;
        QElapsedTimer clock;
        clock.start();
        const Light downlight = luminaireFromFile(doc, QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/luminaires/downlight.ies"));
        QCOMPARE(arrangeField(doc, f, downlight, "hall"), 10000);
        const qint64 arrangeMs = clock.restart();
        QCOMPARE(outliner.groupItem("hall")->childCount(), 10000);
        QVERIFY(!outliner.groupItem("hall")->isExpanded());
        outliner.selectGroup("hall");
        panel.setGroup("hall");
        const qint64 selectMs = clock.restart();
        QVERIFY(std::abs(panel.fluxField()->value() - luminaireFlux(downlight)) <= 0.05);  // shown to 0.1 lm
        typeInto(panel.fluxField(), 1500);
        const qint64 editMs = clock.restart();
        QCOMPARE(doc.undoStack()->count(), 2);
        QVERIFY(std::abs(luminaireFlux(doc.scene().lights.back()) - 1500) < 1e-6);
        doc.undoStack()->undo();
        const qint64 undoMs = clock.restart();
        QVERIFY(std::abs(luminaireFlux(doc.scene().lights.back()) - luminaireFlux(downlight)) < 1e-6);
        YieldGate gate;
        PlanView plan(&doc, gate);
        plan.resize(800, 600);
        clock.restart();
        const QPixmap picture = plan.grab();
        const qint64 planMs = clock.restart();
        chooseAutoBackend(doc.scene());
        const qint64 autoMs = clock.restart();
        qInfo("auto backend choice %lld ms", autoMs);
        QVERIFY(!picture.isNull());
        qInfo("10,000 lights: arrangement (with the outliner's rebuild) %lld ms, group selection %lld ms, "
              "flux edit %lld ms, undo %lld ms, plan drawn %lld ms",
              arrangeMs, selectMs, editMs, undoMs, planMs);
    }
};

QTEST_MAIN(TestLightGroups)
#include "test_light_groups.moc"
