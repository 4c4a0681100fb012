// `lucerna import` and File > Import Model through the real window, on the glTF model of
// gltf_test_model.h: the command's scene (unit, camera, PLY meshes beside it, one-line error),
// and in the window on the Cornell box one undo step, the report, the preview's pixels and fresh
// names on a second import. The importer itself: test_model_import.

#include "core/scene/scene_io.h"
#include "gltf_test_model.h"
#include "import_test_helpers.h"
#include "render/trace/camera.h"
#include "ui/rendering/live_preview.h"
#include "ui/window/main_window.h"
#include "window_test_helpers.h"

#include <QAction>
#include <QFile>
#include <QPlainTextEdit>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <set>

using namespace lucerna;
using namespace lucerna::test;

class TestModelImportWindow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void importCommand();
    void importThroughTheWindow();

private:
    QTemporaryDir dir_;
};

namespace {
constexpr int kTimeout = 30000;  // ms; generous for a loaded 2-core machine, never a timing assertion
}  // namespace

void TestModelImportWindow::initTestCase() {
    useTestSettings("test_model_import_window");
    QVERIFY(dir_.isValid());
}

void TestModelImportWindow::importCommand() {
    const QString out = dir_.filePath("imported.json");
    QProcess p;
    p.start(LUCERNA_BINARY, {"import", gltfModelPath(dir_), "-o", out, "--meters-per-unit", "0.001"});
    QVERIFY(p.waitForFinished(60000));
    const QString stdoutText = QString::fromUtf8(p.readAllStandardOutput());
    QVERIFY2(p.exitCode() == 0, qPrintable(QString::fromUtf8(p.readAllStandardError())));
    QVERIFY2(stdoutText.contains("5 object(s), 10 triangles") && stdoutText.contains("-> mirror"), qPrintable(stdoutText));
    const Scene scene = loadScene(out.toStdString());
    QCOMPARE(scene.metersPerUnit, 0.001);
    QCOMPARE(scene.objects.size(), size_t(5));
    QCOMPARE(scene.materials.size(), size_t(5));
    QCOMPARE(scene.lights.size(), size_t(2));
    QVERIFY(scene.lights[0].photometric && near(scene.lights[0].photometric->value, 100.0));
    // The camera looks at the middle of the model's bounds (100..500, 50..400, 30..100 mm).
    QVERIFY(near(scene.camera.target, V3d(300, 225, 65), 1e-6));
    // Meshes in PLY files beside the scene, read back as the inline ones, to the float precision
    // that OpenMesh's PLY reader keeps (and the renderer traces in).
    const QString inlineOut = dir_.filePath("imported-inline.json");
    p.start(LUCERNA_BINARY, {"import", gltfModelPath(dir_), "-o", inlineOut, "--meters-per-unit", "0.001", "--inline-meshes"});
    QVERIFY(p.waitForFinished(60000));
    QCOMPARE(p.exitCode(), 0);
    const Scene inlined = loadScene(inlineOut.toStdString());
    QCOMPARE(inlined.objects.size(), scene.objects.size());
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const MeshSource& m = scene.objects[i].mesh;
        QCOMPARE(m.kind, MeshSource::Kind::File);
        QVERIFY2(m.file.rfind("imported-meshes/", 0) == 0 && QFile::exists(dir_.filePath(QString::fromStdString(m.file))),
                 m.file.c_str());
        QCOMPARE(inlined.objects[i].mesh.kind, MeshSource::Kind::Inline);
        const TriangleMesh &a = *scene.objects[i].worldMesh, &b = *inlined.objects[i].worldMesh;
        QCOMPARE(a.triangles, b.triangles);
        QCOMPARE(a.vertices.size(), b.vertices.size());
        for (size_t k = 0; k < a.vertices.size(); ++k)
            QVERIFY2((a.vertices[k] - b.vertices[k]).length() <= 1e-6 * b.vertices[k].length(), qPrintable(QString("%1: %2 %3 %4 / %5 %6 %7").arg(k)
                .arg(a.vertices[k].x, 0, 'g', 17).arg(a.vertices[k].y, 0, 'g', 17).arg(a.vertices[k].z, 0, 'g', 17)
                .arg(b.vertices[k].x, 0, 'g', 17).arg(b.vertices[k].y, 0, 'g', 17).arg(b.vertices[k].z, 0, 'g', 17)));
    }
    for (const Object& o : scene.objects)
        for (const V3d& v : o.worldMesh->vertices) {
            const V3d d = (v - scene.camera.position).normalized(), f = (scene.camera.target - scene.camera.position).normalized();
            QVERIFY(d.dot(f) > std::cos(scene.camera.fovYDeg * M_PI / 360.0));  // inside the view cone
        }

    const QString bad = dir_.filePath("broken-cli.gltf");
    writeFile(bad, "{ not json");
    const QString none = dir_.filePath("none.json");
    p.start(LUCERNA_BINARY, {"import", bad, "-o", none});
    QVERIFY(p.waitForFinished(60000));
    QCOMPARE(p.exitCode(), 2);
    const QString err = QString::fromUtf8(p.readAllStandardError()).trimmed();
    QVERIFY2(!err.isEmpty() && !err.contains('\n') && err.contains("broken-cli.gltf"), qPrintable(err));
    QVERIFY(!QFile::exists(none));
}

void TestModelImportWindow::importThroughTheWindow() {
    MainWindow w(cornellPath());
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    Document* doc = w.document();
    QVERIFY(w.findChild<QAction*>("actionImportModel"));
    const size_t objects = doc->scene().objects.size(), lights = doc->scene().lights.size(),
                 materials = doc->scene().materials.size();
    const int steps = doc->undoStack()->count();
    const SceneSnapshot original = doc->snapshot();

    const auto previewOfCurrent = [&]() -> std::shared_ptr<const LiveFrame> {
        const SceneSnapshot want = doc->snapshot();
        const auto ok = [&] { return w.livePreview()->frame() && w.livePreview()->frame()->scene == want; };
        if (!QTest::qWaitFor(ok, kTimeout)) return nullptr;
        return w.livePreview()->frame();
    };
    const auto before = previewOfCurrent();
    QVERIFY(before);

    // A bad file: one line, nothing changes.
    const QString bad = dir_.filePath("broken.gltf");
    writeFile(bad, "{ not json");
    QVERIFY(!w.importModelFile(bad));
    QVERIFY(!w.lastError().isEmpty() && !w.lastError().contains('\n'));
    QCOMPARE(doc->undoStack()->count(), steps);
    QVERIFY(doc->snapshot() == original);

    QVERIFY2(w.importModelFile(gltfModelPath(dir_)), qPrintable(w.lastError()));
    QCOMPARE(doc->scene().objects.size(), objects + 5);
    QCOMPARE(doc->scene().lights.size(), lights + 2);
    QCOMPARE(doc->scene().materials.size(), materials + 5);
    QCOMPARE(doc->undoStack()->count(), steps + 1);
    for (size_t i = objects; i < doc->scene().objects.size(); ++i) QVERIFY(doc->scene().objects[i].worldMesh);
    // The report window shows the lines without blocking.
    auto* text = w.findChild<QPlainTextEdit*>("importReportText");
    QVERIFY(text);
    QVERIFY(text->window()->isVisible() && !text->window()->isModal());
    QVERIFY2(text->toPlainText().contains("5 object(s), 10 triangles") && text->toPlainText().contains("glazing"),
             qPrintable(text->toPlainText()));

    // The green square turns its pixels green: its projected bounds in the preview.
    const auto after = previewOfCurrent();
    QVERIFY(after);
    const Object* plain = nullptr;
    for (const Object& o : doc->scene().objects)
        if (o.name == "Plain") plain = &o;
    QVERIFY(plain);
    const PinholeCamera cam(doc->scene().camera, after->image.width, after->image.height);
    float x0 = 1e9f, x1 = -1e9f, y0 = 1e9f, y1 = -1e9f;
    for (const V3d& v : plain->worldMesh->vertices) {
        float x = 0, y = 0;
        cam.rasterPoint(toFloat(v) - cam.position(), x, y);
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    QCoreApplication::processEvents();
    QVERIFY(w.grab().save("model_import_window.png"));
    QVERIFY(text->window()->grab().save("model_import_report.png"));
    QVERIFY(x1 - x0 > 4 && y1 - y0 > 4);
    int greener = 0, n = 0;
    for (int y = int(y0) + 2; y < int(y1) - 1; ++y)
        for (int x = int(x0) + 2; x < int(x1) - 1; ++x) {
            const Rgb a = before->image.at(x, y), b = after->image.at(x, y);
            ++n;
            // Before: the white back wall or floor (G/R about 1); after: albedo 0.2, 0.8, 0.3.
            if (b.y > 2.0f * b.x && !(a.y > 2.0f * a.x)) ++greener;
        }
    const Rgb mid = after->image.at(int(x0 + x1) / 2, int(y0 + y1) / 2), was = before->image.at(int(x0 + x1) / 2, int(y0 + y1) / 2);
    QVERIFY2(n > 0 && greener > 0.9 * n, qPrintable(QString("%1 of %2 pixels turned green; bounds %3..%4 x %5..%6 of %7x%8; middle %9 %10 %11 was %12 %13 %14")
                                                        .arg(greener).arg(n).arg(x0).arg(x1).arg(y0).arg(y1).arg(after->image.width).arg(after->image.height)
                                                        .arg(mid.x).arg(mid.y).arg(mid.z).arg(was.x).arg(was.y).arg(was.z)));

    // Undo removes everything in one step; redo brings it back.
    w.findChild<QAction*>("actionUndo")->trigger();
    QVERIFY(doc->snapshot()->objects == original->objects);
    QVERIFY(doc->snapshot()->lights == original->lights);
    QVERIFY(doc->snapshot()->materials == original->materials);
    w.findChild<QAction*>("actionRedo")->trigger();
    QCOMPARE(doc->scene().objects.size(), objects + 5);
    QCOMPARE(doc->scene().lights.size(), lights + 2);
    // A second import of the same file gets fresh names (SPEC.md: unique across objects and lights).
    QVERIFY(w.importModelFile(gltfModelPath(dir_)));
    std::set<std::string> names;
    for (const Object& o : doc->scene().objects) names.insert(o.name);
    for (const Light& l : doc->scene().lights) names.insert(l.name);
    QCOMPARE(names.size(), doc->scene().objects.size() + doc->scene().lights.size());
    w.findChild<QAction*>("actionUndo")->trigger();
    w.findChild<QAction*>("actionUndo")->trigger();
    QVERIFY(doc->snapshot()->objects == original->objects);
    doc->undoStack()->setClean();  // no unsaved-changes question when the window closes
}

QTEST_MAIN(TestModelImportWindow)
#include "test_model_import_window.moc"
