// The material and object panels, mesh import and luminaires, driven through the real window on
// the Cornell box: edit the red wall's albedo, move and reassign an object, add a luminaire,
// import a mesh. Checks the document, the undo stack and the pixels. The exports with their
// layers: test_export_layers.

#include "sanitizers.h"
#include "core/image/exr_io.h"
#include "core/photometry/luminaire.h"
#include "core/scene/scene_io.h"
#include "file_helpers.h"
#include "render/trace/camera.h"
#include "ui/properties/colour_edit.h"
#include "ui/commands/material_commands.h"
#include "ui/rendering/converging_render.h"
#include "ui/rendering/live_preview.h"
#include "ui/window/main_window.h"
#include "ui/properties/material_properties.h"
#include "ui/properties/object_properties.h"
#include "ui/scene_panels/outliner.h"
#include "ui/properties/properties_panel.h"
#include "ui/viewport/viewport.h"
#include "window_test_helpers.h"

#include <QAction>
#include <QCheckBox>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QProcess>
#include <QSettings>
#include <QSlider>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <set>

using namespace lucerna;
using namespace lucerna::test;

namespace {
// ms; generous for a loaded 2-core machine (32 settled preview frames took over 30 s there under a
// parallel build), never a timing assertion
constexpr int kTimeout = int(60000 * kResourceScale);

QString icospherePath() { return QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/meshes/icosphere.ply"); }

// The live preview of the document's current scene once it has averaged `frames` idle frames:
// single frames of two scenes differ by their VPL sets' noise (one changed light path reorders
// the whole resampled set), which would drown what an edit changed.
std::shared_ptr<const LiveFrame> settledPreviewOfCurrent(MainWindow& w, int frames) {
    const SceneSnapshot want = w.document()->snapshot();
    const auto ok = [&] {
        const auto f = w.livePreview()->frame();
        return f && f->scene == want && f->frames >= frames;
    };
    if (!QTest::qWaitFor(ok, kTimeout)) return nullptr;
    return w.livePreview()->frame();
}

// Mean of each channel over a rectangle given in fractions of the image.
Rgbd regionMean(const Image& image, double x0, double x1, double y0, double y1) {
    Rgbd sum(0, 0, 0);
    int n = 0;
    for (int y = int(y0 * image.height); y < int(y1 * image.height); ++y)
        for (int x = int(x0 * image.width); x < int(x1 * image.width); ++x) {
            const Rgb& p = image.at(x, y);
            sum += Rgbd(p.x, p.y, p.z);
            ++n;
        }
    return sum / double(std::max(n, 1));
}


// The red wall in the Cornell box's view (SPEC.md: on the left), away from its edges.
Rgbd redWallMean(const Image& image) { return regionMean(image, 0.03, 0.09, 0.3, 0.7); }

struct Window {
    explicit Window(const QString& path) : w(path) {
        w.show();
        exposed = QTest::qWaitForWindowExposed(&w);
    }
    MainWindow w;
    bool exposed = false;
};
}  // namespace

class TestEditingPanels : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void materialPanelEditsTheMaterial();
    void objectPanelMovesAndReassigns();
    void importMesh();
    void addLuminaire();

private:
    QTemporaryDir dir_;
};

void TestEditingPanels::initTestCase() {
    useTestSettings("test_editing_panels");
    QVERIFY(dir_.isValid());
}

void TestEditingPanels::materialPanelEditsTheMaterial() {
    Window win(copyOfCornell(dir_, "materials.json"));
    QVERIFY(win.exposed);
    MainWindow& w = win.w;
    Document* doc = w.document();
    const int red = doc->scene().materialIndex("red");
    QVERIFY(red >= 0);
    const Material original = doc->scene().materials[size_t(red)];
    const auto before = previewOfCurrent(w, kTimeout);
    QVERIFY(before);
    const Rgbd wallBefore = redWallMean(before->image);
    QVERIFY2(wallBefore.x > 3 * wallBefore.y, "the red wall is red");

    // Selecting the material in the outliner shows its panel with its values.
    w.outliner()->select(Outliner::Kind::Material, red);
    MaterialProperties* panel = w.propertiesPanel()->materialProperties();
    QCOMPARE(panel->material(), red);
    QVERIFY(panel->isVisibleTo(&w));
    QCOMPARE(panel->typeField()->currentText(), QString("diffuse"));
    QVERIFY(panel->albedoField()->isVisibleTo(panel));
    QVERIFY(!panel->radianceField()->isVisibleTo(panel));
    QCOMPARE(panel->albedoField()->channel(0)->value(), 0.63);
    screenshot(*w.propertiesPanel(), "editing_panels_material.png");

    // Make it green through the fields: one undo step per typed value.
    const int steps = doc->undoStack()->count();
    typeInto(panel->albedoField()->channel(1), 0.6);
    typeInto(panel->albedoField()->channel(0), 0.05);
    QCOMPARE(doc->scene().materials[size_t(red)].albedo, Rgbd(0.05, 0.6, 0.05));
    QCOMPARE(doc->undoStack()->count(), steps + 2);
    // SPEC.md: albedo in [0, 1]; the field does not go past 1.
    typeInto(panel->albedoField()->channel(2), 1.5);
    QCOMPARE(doc->scene().materials[size_t(red)].albedo.z, 1.0);
    w.findChild<QAction*>("actionUndo")->trigger();
    QCOMPARE(doc->scene().materials[size_t(red)].albedo, Rgbd(0.05, 0.6, 0.05));

    // The preview answers: the wall's G/R ratio rises by far.
    const auto green = previewOfCurrent(w, kTimeout);
    QVERIFY(green);
    const Rgbd wallGreen = redWallMean(green->image);
    const double ratioBefore = wallBefore.y / wallBefore.x, ratioGreen = wallGreen.y / wallGreen.x;
    QVERIFY2(ratioGreen > 5 * ratioBefore, qPrintable(QString("G/R %1 -> %2").arg(ratioBefore).arg(ratioGreen)));
    // The converging render restarts on the edited scene.
    QTRY_VERIFY_WITH_TIMEOUT(w.convergingRender()->scene() == doc->snapshot(), kTimeout);

    // Undo restores the material, the panel and the pixels.
    w.findChild<QAction*>("actionUndo")->trigger();
    w.findChild<QAction*>("actionUndo")->trigger();
    QCOMPARE(doc->scene().materials[size_t(red)], original);
    QCOMPARE(panel->albedoField()->channel(0)->value(), 0.63);
    const auto restored = previewOfCurrent(w, kTimeout);
    QVERIFY(restored);
    const Rgbd wallRestored = redWallMean(restored->image);
    QVERIFY2(std::abs(wallRestored.y / wallRestored.x - ratioBefore) < 0.1 * ratioBefore + 1e-3,
             qPrintable(QString("G/R %1, restored %2").arg(ratioBefore).arg(wallRestored.y / wallRestored.x)));

    // A value with more digits than a field shows survives an edit of another channel.
    {
        Material precise = original;
        precise.albedo = Rgbd(0.63, 0.0654321, 0.05);
        doc->undoStack()->push(new EditMaterialCommand(doc, red, precise, 0, "precise"));
        typeInto(panel->albedoField()->channel(2), 0.1);
        QCOMPARE(doc->scene().materials[size_t(red)].albedo, Rgbd(0.63, 0.0654321, 0.1));
        w.findChild<QAction*>("actionUndo")->trigger();
        w.findChild<QAction*>("actionUndo")->trigger();
        QCOMPARE(doc->scene().materials[size_t(red)], original);
    }

    // The colour picker sets all three channels at once: one step.
    const int beforePick = doc->undoStack()->index();
    panel->albedoField()->pick(QColor(255, 255, 255));
    QCOMPARE(doc->scene().materials[size_t(red)].albedo, Rgbd(1, 1, 1));
    QCOMPARE(doc->undoStack()->index(), beforePick + 1);
    w.findChild<QAction*>("actionUndo")->trigger();

    // Glossy: the type's own fields; a slider drag is one undo step.
    panel->typeField()->setCurrentIndex(panel->typeField()->findText("glossy"));
    emit panel->typeField()->activated(panel->typeField()->currentIndex());
    QCOMPARE(doc->scene().materials[size_t(red)].type, MaterialType::Glossy);
    QVERIFY(panel->roughnessSlider()->isVisibleTo(panel));
    QVERIFY(panel->specularField()->isVisibleTo(panel));
    QVERIFY(!panel->iorField()->isVisibleTo(panel));
    const int beforeDrag = doc->undoStack()->index();
    QSlider* slider = panel->roughnessSlider();
    slider->setSliderDown(true);
    for (int v : {300, 400, 500, 600}) slider->setValue(v);
    slider->setSliderDown(false);  // emits sliderReleased
    QCOMPARE(doc->undoStack()->index(), beforeDrag + 1);
    QCOMPARE(doc->scene().materials[size_t(red)].roughness, 0.6);
    QCOMPARE(panel->roughnessField()->value(), 0.6);
    // Clicks on the track or keys (no drag) are a step each, not merged into one another.
    const int beforeClicks = doc->undoStack()->index();
    slider->setValue(700);
    slider->setValue(800);
    QCOMPARE(doc->undoStack()->index(), beforeClicks + 2);
    w.findChild<QAction*>("actionUndo")->trigger();
    QCOMPARE(doc->scene().materials[size_t(red)].roughness, 0.7);
    w.findChild<QAction*>("actionUndo")->trigger();
    QCOMPARE(doc->scene().materials[size_t(red)].roughness, 0.6);
    screenshot(*w.propertiesPanel(), "editing_panels_glossy.png");

    // Emitter: radiance with its luminance in cd/m^2; the saved file holds what the document does.
    panel->typeField()->setCurrentIndex(panel->typeField()->findText("emitter"));
    emit panel->typeField()->activated(panel->typeField()->currentIndex());
    QCOMPARE(doc->scene().materials[size_t(red)].type, MaterialType::Emitter);
    typeInto(panel->radianceField()->channel(0), 2);
    typeInto(panel->radianceField()->channel(1), 2);
    typeInto(panel->radianceField()->channel(2), 2);
    QCOMPARE(doc->scene().materials[size_t(red)].radiance, Rgbd(2, 2, 2));
    QCOMPARE(panel->luminanceLabel()->text(), QString("1366 cd/m²"));
    screenshot(*w.propertiesPanel(), "editing_panels_emitter.png");
    const QString saved = dir_.filePath("materials-saved.json");
    QVERIFY2(w.saveFileAs(saved), qPrintable(w.lastError()));
    QVERIFY(loadScene(saved.toStdString()) == doc->scene());
}

void TestEditingPanels::objectPanelMovesAndReassigns() {
    Window win(copyOfCornell(dir_, "objects.json"));
    QVERIFY(win.exposed);
    MainWindow& w = win.w;
    Document* doc = w.document();
    int block = -1;
    for (size_t i = 0; i < doc->scene().objects.size(); ++i)
        if (doc->scene().objects[i].name == "short_block") block = int(i);
    QVERIFY(block >= 0);
    const Object original = doc->scene().objects[size_t(block)];
    QVERIFY(original.worldMesh);

    // Selecting the object shows its panel and its material's panel below.
    w.outliner()->select(Outliner::Kind::Object, block);
    ObjectProperties* panel = w.propertiesPanel()->objectProperties();
    MaterialProperties* material = w.propertiesPanel()->materialProperties();
    QCOMPARE(panel->object(), block);
    QVERIFY(panel->isVisibleTo(&w));
    QCOMPARE(panel->nameField()->text(), QString("short_block"));
    QCOMPARE(panel->materialField()->currentText(), QString("white"));
    QCOMPARE(material->material(), doc->scene().materialIndex("white"));
    // Units: the translation in the scene's unit, the size in metres.
    QCOMPARE(panel->findChild<QLabel*>("objectSize")->text().right(2), QString(" m"));
    QVERIFY(panel->sizeLabel()->text().startsWith("0.2"));  // 208 mm wide
    screenshot(*w.propertiesPanel(), "editing_panels_object.png");

    // Move it 50 mm along x: every world vertex moves with it, one undo step, and the preview
    // shows the scene as it is now.
    const int steps = doc->undoStack()->count();
    typeInto(panel->translateFields()[0], 50);
    QCOMPARE(doc->undoStack()->count(), steps + 1);
    const Object& moved = doc->scene().objects[size_t(block)];
    QVERIFY(moved.transform);
    QCOMPARE(moved.transform->translate, V3d(50, 0, 0));
    QCOMPARE(moved.worldMesh->vertices.size(), original.worldMesh->vertices.size());
    for (size_t k = 0; k < moved.worldMesh->vertices.size(); ++k)
        QCOMPARE(moved.worldMesh->vertices[k], original.worldMesh->vertices[k] + V3d(50, 0, 0));
    QVERIFY(previewOfCurrent(w, kTimeout));

    // Arrow steps of one field are one undo step until its editing finishes.
    for (int i = 0; i < 3; ++i) panel->translateFields()[2]->stepBy(1);
    QCOMPARE(doc->undoStack()->count(), steps + 2);
    QCOMPARE(doc->scene().objects[size_t(block)].transform->translate, V3d(50, 0, 3));
    emit panel->translateFields()[2]->editingFinished();
    w.findChild<QAction*>("actionUndo")->trigger();
    QCOMPARE(doc->scene().objects[size_t(block)].transform->translate, V3d(50, 0, 0));

    // Rotate it a quarter turn about y: a vertex turns about the origin as SPEC.md says
    // (scale, rotate, then translate).
    typeInto(panel->angleField(), 90);
    const V3d v0 = original.worldMesh->vertices[0];
    const V3d r0 = doc->scene().objects[size_t(block)].worldMesh->vertices[0];
    QCOMPARE_LT((r0 - (V3d(v0.z, v0.y, -v0.x) + V3d(50, 0, 0))).length(), 1e-9);
    QCOMPARE(doc->undoStack()->count(), steps + 2);
    // A zero scale is refused (SPEC.md): nothing changes.
    typeInto(panel->scaleFields()[1], 0);
    QCOMPARE(doc->undoStack()->count(), steps + 2);
    QCOMPARE(panel->scaleFields()[1]->value(), 1.0);

    // Assign another material through the combo box: the material panel follows.
    const int green = doc->scene().materialIndex("green");
    panel->materialField()->setCurrentIndex(green);
    emit panel->materialField()->activated(green);
    QCOMPARE(doc->scene().objects[size_t(block)].material, std::string("green"));
    QCOMPARE(material->material(), green);
    QCOMPARE(doc->undoStack()->count(), steps + 3);

    // Rename; a name in use is refused.
    panel->nameField()->setText("left_wall");
    emit panel->nameField()->editingFinished();
    QCOMPARE(doc->scene().objects[size_t(block)].name, std::string("short_block"));
    panel->nameField()->setText("cube");
    emit panel->nameField()->editingFinished();
    QCOMPARE(doc->scene().objects[size_t(block)].name, std::string("cube"));

    // Mark it as an opening (a daylight portal): one undo step; its material no longer applies.
    panel->portalField()->click();
    QVERIFY(doc->scene().objects[size_t(block)].portal);
    QVERIFY(!panel->materialField()->isEnabled());
    QCOMPARE(doc->undoStack()->count(), steps + 5);
    w.findChild<QAction*>("actionUndo")->trigger();
    QVERIFY(!doc->scene().objects[size_t(block)].portal && !panel->portalField()->isChecked());

    // Undo it all: the object as it was, world mesh included; the panels follow.
    for (int i = 0; i < 4; ++i) w.findChild<QAction*>("actionUndo")->trigger();
    QVERIFY(doc->scene().objects[size_t(block)] == original);
    QVERIFY(*doc->scene().objects[size_t(block)].worldMesh == *original.worldMesh);
    QCOMPARE(panel->translateFields()[0]->value(), 0.0);
    QCOMPARE(material->material(), doc->scene().materialIndex("white"));
    QVERIFY(!doc->isModified());
}

// Edit > Add Luminaire (without its file dialog): the bundled downlight's IES file becomes a
// luminaire hung over the middle of the room, nadir down, at the file's flux; one undo step,
// selected, saved with a path relative to the scene and read back; the floor under it brightens.
void TestEditingPanels::addLuminaire() {
    const QString scenePath = copyOfCornell(dir_, "luminaire.json");
    Window win(scenePath);
    QVERIFY(win.exposed);
    MainWindow& w = win.w;
    Document* doc = w.document();
    const auto before = previewOfCurrent(w, kTimeout);
    QVERIFY(before);
    const size_t lights = doc->scene().lights.size();
    const int steps = doc->undoStack()->count();

    const QString bad = dir_.filePath("broken.ies");
    QVERIFY(writeTestFile(bad, "IESNA:LM-63-2002\nTILT=NONE\n1 1000 1\n"));
    QVERIFY(!w.addLuminaireFile(bad));
    QVERIFY(!w.lastError().isEmpty() && !w.lastError().contains('\n'));
    QCOMPARE(doc->scene().lights.size(), lights);
    QCOMPARE(doc->undoStack()->count(), steps);

    const QString ies = QString(LUCERNA_RESOURCE_DIR) + "/scenes/luminaires/downlight.ies";
    QVERIFY2(w.addLuminaireFile(ies), qPrintable(w.lastError()));
    QCOMPARE(doc->scene().lights.size(), lights + 1);
    QCOMPARE(doc->undoStack()->count(), steps + 1);
    const Light added = doc->scene().lights.back();
    QCOMPARE(added.name, std::string("downlight"));
    QCOMPARE(added.type, LightType::Luminaire);
    QVERIFY(added.luminaire && added.luminaire->distribution);
    QVERIFY(!QDir::isAbsolutePath(QString::fromStdString(added.luminaire->file)));
    QCOMPARE(added.direction, V3d(0, -1, 0));
    const double fileFlux = luminaireFlux(added);
    QVERIFY(fileFlux > 0);
    QVERIFY(w.saveFileAs(dir_.filePath("luminaire-saved.json")));
    const Scene reloaded = loadScene(dir_.filePath("luminaire-saved.json").toStdString());
    QCOMPARE(reloaded.lights.back().luminaire->file,
             QDir(dir_.path()).relativeFilePath(QFileInfo(ies).absoluteFilePath()).toStdString());
    QVERIFY(std::abs(luminaireFlux(reloaded.lights.back()) / fileFlux - 1) < 1e-9);

    // The floor in the middle of the image brightens (the downlight points at it).
    const auto after = previewOfCurrent(w, kTimeout);
    QVERIFY(after);
    const double floorBefore = luminance(regionMean(before->image, 0.35, 0.65, 0.8, 0.95));
    const double floorAfter = luminance(regionMean(after->image, 0.35, 0.65, 0.8, 0.95));
    QVERIFY2(floorAfter > 1.2 * floorBefore, qPrintable(QString("%1 -> %2").arg(floorBefore).arg(floorAfter)));
    w.grab().save("add_luminaire.png");

    w.findChild<QAction*>("actionUndo")->trigger();
    QCOMPARE(doc->scene().lights.size(), lights);
}

void TestEditingPanels::importMesh() {
    const QString scenePath = copyOfCornell(dir_, "import.json");
    Window win(scenePath);
    QVERIFY(win.exposed);
    MainWindow& w = win.w;
    Document* doc = w.document();
    const auto before = settledPreviewOfCurrent(w, 32);
    QVERIFY(before);
    const size_t objects = doc->scene().objects.size(), materials = doc->scene().materials.size();
    const int steps = doc->undoStack()->count();

    // A bad file: a one-line error, nothing changes.
    const QString bad = dir_.filePath("broken.ply");
    QVERIFY(writeTestFile(bad, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1 2\n"));
    QVERIFY(!w.importMeshFile(bad));
    QVERIFY(!w.lastError().isEmpty());
    QVERIFY(!w.lastError().contains('\n'));
    QVERIFY(!w.importMeshFile(dir_.filePath("missing.obj")));
    QVERIFY(w.lastError().contains("missing.obj"));
    QCOMPARE(doc->scene().objects.size(), objects);
    QCOMPARE(doc->undoStack()->count(), steps);

    // The icosphere: one object with its own diffuse material, one undo step, selected.
    QVERIFY2(w.importMeshFile(icospherePath()), qPrintable(w.lastError()));
    QCOMPARE(doc->scene().objects.size(), objects + 1);
    QCOMPARE(doc->scene().materials.size(), materials + 1);
    QCOMPARE(doc->undoStack()->count(), steps + 1);
    const Object sphere = doc->scene().objects.back();
    QCOMPARE(sphere.name, std::string("icosphere"));
    QCOMPARE(sphere.mesh.kind, MeshSource::Kind::File);
    // Relative to the scene's folder, and it resolves to the file.
    QVERIFY(!QDir::isAbsolutePath(QString::fromStdString(sphere.mesh.file)));
    QCOMPARE(QFileInfo(QDir(QString::fromStdString(doc->scene().baseDir)).absoluteFilePath(QString::fromStdString(sphere.mesh.file))).canonicalFilePath(),
             QFileInfo(icospherePath()).canonicalFilePath());
    QCOMPARE(sphere.worldMesh->triangles.size(), size_t(1280));
    const Material* mat = doc->scene().findMaterial(sphere.material);
    QVERIFY(mat && mat->type == MaterialType::Diffuse);
    QCOMPARE(w.propertiesPanel()->objectProperties()->object(), int(objects));
    // A unit sphere in a millimetre scene is scaled to a third of the room and stands on the floor.
    double lowest = 1e30, highest = -1e30;
    for (const V3d& v : sphere.worldMesh->vertices) {
        lowest = std::min(lowest, v.y);
        highest = std::max(highest, v.y);
    }
    QCOMPARE_LT(std::abs(lowest), 1e-6);
    QCOMPARE_LT(std::abs(highest - 559.2 / 3.0), 1.0);  // a third of the box's depth, its largest side

    // It renders: many pixels change, most of them inside its projected bounds.
    const auto after = settledPreviewOfCurrent(w, 32);
    QVERIFY(after);
    const PinholeCamera cam(doc->scene().camera, after->image.width, after->image.height);
    float x0 = 1e9f, x1 = -1e9f, y0 = 1e9f, y1 = -1e9f;
    for (const V3d& v : sphere.worldMesh->vertices) {
        float x = 0, y = 0;
        cam.rasterPoint(toFloat(v) - cam.position(), x, y);
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    int inside = 0, outside = 0;
    for (int y = 0; y < after->image.height; ++y)
        for (int x = 0; x < after->image.width; ++x) {
            const float a = luminance(before->image.at(x, y)), b = luminance(after->image.at(x, y));
            if (std::abs(b - a) <= 0.3f * std::max(a, 1e-3f)) continue;
            (x >= x0 && x <= x1 && y >= y0 && y <= y1 ? inside : outside)++;
        }
    // Outside, its shadow and the light it reflects change pixels too, but far fewer. Inside, the
    // sphere covers pi/4 of its box and, lit from above, is about as bright as the wall and the
    // block behind much of it: with the previews settled (32 frames), 30% of the box changes.
    const double box = double(x1 - x0) * double(y1 - y0), rest = double(after->image.width) * after->image.height - box;
    QVERIFY2(inside > 0.2 * box && outside < 0.05 * rest,
             qPrintable(QString("changed inside %1 of %2, outside %3 of %4").arg(inside).arg(box).arg(outside).arg(rest)));
    screenshot(w, "editing_panels_import.png");

    // Move it through its panel (the file's mesh is read once for the steps of an edit): the
    // world mesh is the one the loader makes of the saved transform.
    ObjectProperties* panel = w.propertiesPanel()->objectProperties();
    const double x = panel->translateFields()[0]->value();
    typeInto(panel->translateFields()[0], x + 40);
    for (int i = 0; i < 3; ++i) panel->translateFields()[2]->stepBy(-10);
    const Object movedSphere = doc->scene().objects.back();
    QCOMPARE(movedSphere.worldMesh->vertices[0], sphere.worldMesh->vertices[0] + V3d(40, 0, -30));

    // Save As to another folder: the relative mesh path is rebased and still resolves.
    QVERIFY(QDir(dir_.path()).mkpath("elsewhere/deeper"));
    const QString moved = dir_.filePath("elsewhere/deeper/moved.json");
    QVERIFY2(w.saveFileAs(moved), qPrintable(w.lastError()));
    const Scene reloaded = loadScene(moved.toStdString());
    QCOMPARE(reloaded.objects.size(), objects + 1);
    QVERIFY(*reloaded.objects.back().worldMesh == *movedSphere.worldMesh);
    QCOMPARE(doc->scene().objects.back().worldMesh->vertices, movedSphere.worldMesh->vertices);

    // Undo of the import (reopen to the original first: Save As to another folder reloads).
    QVERIFY(w.openFile(scenePath));
    QVERIFY(w.importMeshFile(icospherePath()));
    w.findChild<QAction*>("actionUndo")->trigger();
    QCOMPARE(doc->scene().objects.size(), objects);
    QCOMPARE(doc->scene().materials.size(), materials);

    // An untitled scene has no folder: the path stays absolute.
    doc->setPath({});
    Scene untitled = doc->scene();
    untitled.baseDir.clear();
    doc->reset(untitled);
    QVERIFY(w.importMeshFile(icospherePath()));
    QVERIFY(QDir::isAbsolutePath(QString::fromStdString(doc->scene().objects.back().mesh.file)));
}

QTEST_MAIN(TestEditingPanels)
#include "test_editing_panels.moc"
