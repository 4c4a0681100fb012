// Exports with their layers (README, "Exporting"), driven through the real window on the Cornell
// box: the preview's EXR with albedo, normal and depth read back (the red wall's albedo, unit
// normals, the floor's depth from SPEC.md's camera), a channel that would shadow R, G or B
// refused, the converged image and both at once, the PNG as the display shows it; and `lucerna
// render --layers`, whose layers change nothing else.

#include "sanitizers.h"
#include "core/image/exr_io.h"
#include "core/scene/scene_io.h"
#include "render/trace/camera.h"
#include "ui/rendering/converging_render.h"
#include "ui/window/main_window.h"
#include "window_test_helpers.h"

#include <QAction>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <set>

using namespace lucerna;
using namespace lucerna::test;

namespace {
// ms; generous for a loaded 2-core machine, never a timing assertion
constexpr int kTimeout = int(60000 * kResourceScale);

// The unit direction through the centre of pixel (x, y) of a W x H image, from SPEC.md's camera
// formula (independent of render/trace/camera.h).
V3d specRay(const Camera& c, int x, int y, int W, int H) {
    const V3d f = (c.target - c.position).normalized(), r = f.cross(c.up).normalized(), u = r.cross(f);
    const double t = std::tan(c.fovYDeg * M_PI / 360.0);
    const double sx = 2.0 * (x + 0.5) / W - 1.0, sy = 1.0 - 2.0 * (y + 0.5) / H;
    return (f + r * (sx * t * double(W) / H) + u * (sy * t)).normalized();
}
}  // namespace

class TestExportLayers : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        useTestSettings("test_export_layers");
        QVERIFY(dir_.isValid());
    }
    void exportImagesWithLayers();
    void renderCommandWritesLayers();

private:
    QTemporaryDir dir_;
};

void TestExportLayers::exportImagesWithLayers() {
    MainWindow w(copyOfCornell(dir_, "export.json"));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    Document* doc = w.document();
    const auto frame = previewOfCurrent(w, kTimeout);
    QVERIFY(frame);

    // The File menu offers the exports (their dialogs are modal; the test calls what they call).
    for (const char* name : {"actionExportExr", "actionExportPreviewExr", "actionExportBothExr", "actionExportPng",
                             "actionImportMesh"}) {
        auto* action = w.findChild<QAction*>(name);
        QVERIFY2(action && action->isEnabled(), name);
    }
    QCOMPARE(w.findChild<QAction*>("actionExportPng")->shortcut(), QKeySequence("Ctrl+Shift+E"));

    // The preview with its layers.
    const QString previewPath = dir_.filePath("preview.exr");
    QVERIFY2(w.exportPreviewExr(previewPath), qPrintable(w.lastError()));
    const Image p = readExr(previewPath.toStdString());
    QCOMPARE(p.width, frame->image.width);
    QCOMPARE(p.height, frame->image.height);
    QVERIFY(p.pixels == frame->image.pixels);
    std::set<std::string> names;
    for (const auto& [name, data] : p.channels) names.insert(name);
    QCOMPARE(names, (std::set<std::string>{"albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y", "normal.Z",
                                           "depth.Z"}));
    for (const char* key : {"lucerna:backend", "lucerna:spp", "lucerna:seconds", "lucerna:seed"})
        QVERIFY2(p.attributes.count(key), key);
    const auto at = [&](const char* channel, int x, int y) { return p.channels.at(channel)[size_t(y) * p.width + x]; };

    // A pixel on the red wall carries the red wall's albedo.
    const int W = p.width, H = p.height;
    const Rgbd redAlbedo = doc->scene().findMaterial("red")->albedo;
    QCOMPARE(at("albedo.R", W / 20, H / 2), float(redAlbedo.x));
    QCOMPARE(at("albedo.G", W / 20, H / 2), float(redAlbedo.y));
    QCOMPARE(at("albedo.B", W / 20, H / 2), float(redAlbedo.z));
    // Normals unit and depths positive wherever something is hit (nearly everywhere: the box
    // fills the view but for its open front's rim); no normal and infinite depth elsewhere.
    int hits = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const float d = at("depth.Z", x, y);
            const V3f n(at("normal.X", x, y), at("normal.Y", x, y), at("normal.Z", x, y));
            if (std::isfinite(d)) {
                ++hits;
                QVERIFY(d > 0);
                QCOMPARE_LT(std::abs(n.length() - 1.0f), 1e-4f);
            } else {
                QCOMPARE(n.length(), 0.0f);
            }
        }
    QVERIFY2(hits > 0.9 * W * H, qPrintable(QString::number(hits)));
    // A floor pixel: the depth is the distance along the ray through the pixel's centre to the
    // plane y = 0, computed here from SPEC.md's camera, and the normal is the floor's.
    const Camera& c = doc->scene().camera;
    const int fx = W / 2, fy = H - 1 - H / 20;
    const V3d dir = specRay(c, fx, fy, W, H);
    QVERIFY(dir.y < 0);
    const double floorDistance = -c.position.y / dir.y;
    QCOMPARE_LT(std::abs(at("depth.Z", fx, fy) - floorDistance), 1e-4 * floorDistance);
    QCOMPARE_LT(std::abs(std::abs(at("normal.Y", fx, fy)) - 1.0f), 1e-5f);
    QCOMPARE(at("albedo.R", fx, fy), float(doc->scene().findMaterial("white")->albedo.x));

    // An extra channel may not shadow R, G or B.
    Image clash = p;
    clash.channels["G"] = clash.channels.at("depth.Z");
    QVERIFY_THROWS_EXCEPTION(ImageError, writeExr(dir_.filePath("clash.exr").toStdString(), clash));
    QVERIFY(!QFile::exists(dir_.filePath("clash.exr")));

    // The converged image with its layers, and both at once.
    QTRY_VERIFY_WITH_TIMEOUT(w.convergingRender()->frame() != nullptr, kTimeout);
    const QString convergedPath = dir_.filePath("converged.exr");
    QVERIFY2(w.exportExr(convergedPath), qPrintable(w.lastError()));
    const Image cimg = readExr(convergedPath.toStdString());
    QCOMPARE(cimg.width, c.width);
    QCOMPARE(cimg.channels.size(), size_t(7));
    QCOMPARE(cimg.channels.at("albedo.R")[size_t(c.height / 2) * c.width + c.width / 20], float(redAlbedo.x));
    QCOMPARE(cimg.attributes.at("lucerna:backend"), w.convergingRender()->backendInUse());
    QVERIFY2(w.exportBothExr(dir_.filePath("both.exr")), qPrintable(w.lastError()));
    QCOMPARE(readExr(dir_.filePath("both-preview.exr").toStdString()).attributes.at("lucerna:backend"),
             p.attributes.at("lucerna:backend"));
    QCOMPARE(readExr(dir_.filePath("both-converged.exr").toStdString()).channels.size(), size_t(7));

    // The PNG of the converged image at full resolution (the camera's), as the display shows it.
    const QString pngPath = dir_.filePath("screen.png");
    QVERIFY2(w.exportPng(pngPath), qPrintable(w.lastError()));
    const QImage png(pngPath);
    QCOMPARE(png.size(), QSize(c.width, c.height));
    std::set<QRgb> colours;
    for (int y = 0; y < png.height(); y += 4)
        for (int x = 0; x < png.width(); x += 4) colours.insert(png.pixel(x, y));
    QVERIFY2(colours.size() > 50, qPrintable(QString::number(colours.size())));
    const QColor wall = png.pixelColor(png.width() / 20, png.height() / 2);
    QVERIFY2(wall.red() > 2 * wall.green(), qPrintable(wall.name()));
}

void TestExportLayers::renderCommandWritesLayers() {
    const auto run = [](const QStringList& args, QString* err = nullptr) {
        QProcess proc;
        proc.start(LUCERNA_BINARY, args);
        if (!proc.waitForFinished(120000)) return -1;
        if (err) *err = QString::fromUtf8(proc.readAllStandardError());
        return proc.exitStatus() == QProcess::NormalExit ? proc.exitCode() : -1;
    };
    const QString plain = dir_.filePath("plain.exr"), layered = dir_.filePath("layered.exr");
    const QStringList common = {"--backend", "path", "--spp", "1", "--width", "32", "--height", "32", "--seed", "3",
                                "--threads", "1"};
    QCOMPARE(run(QStringList{"render", cornellPath(), "-o", plain} + common), 0);
    QCOMPARE(run(QStringList{"render", cornellPath(), "-o", layered, "--layers", "albedo,depth"} + common), 0);
    const Image a = readExr(plain.toStdString()), b = readExr(layered.toStdString());
    QVERIFY(a.channels.empty());  // the default output is exactly SPEC.md's
    QCOMPARE(b.channels.size(), size_t(4));
    QVERIFY(b.channels.count("albedo.G") && b.channels.count("depth.Z") && !b.channels.count("normal.X"));
    QVERIFY(a.pixels == b.pixels);  // the layers change nothing else
    QCOMPARE(b.width, 32);
    // The red wall on the left; above the blocks, the depth of the back wall (z = 559.2).
    QCOMPARE(b.channels.at("albedo.R")[size_t(16) * 32 + 1], 0.63f);
    const Scene cornell = loadScene(cornellPath().toStdString());
    const V3d dir = specRay(cornell.camera, 16, 9, 32, 32);
    const double backWall = (559.2 - cornell.camera.position.z) / dir.z;
    QCOMPARE_LT(std::abs(b.channels.at("depth.Z")[size_t(9) * 32 + 16] - backWall), 1e-4 * backWall);
    QString err;
    QCOMPARE(run(QStringList{"render", cornellPath(), "-o", plain, "--layers", "albedo,colour"}, &err), 2);
    QVERIFY2(err.trimmed().count('\n') == 0 && err.contains("colour"), qPrintable(err));
}

QTEST_MAIN(TestExportLayers)
#include "test_export_layers.moc"
