// EXR input and output, atomic writes, the error metrics, the task system, what a scene change is.

#include "core/atomic_file.h"
#include "core/image/exr_io.h"
#include "core/image/image_metrics.h"
#include "core/mesh/mesh_file.h"
#include "core/scene/scene_change.h"
#include "core/sub_task.h"
#include "core/task_system.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <atomic>
#include <limits>
#include <thread>

using namespace lucerna;

class TestCore : public QObject {
    Q_OBJECT
private slots:
    void exrRoundTrip();
    void exrMissingChannelAndGarbage();
    void atomicWriteLeavesNothingOnFailure();
    void metricsByHand();
    void metricsExcludeNonFinite();
    void taskRunsOffTheCallingThread();
    void taskCancellationStopsParallelLoop();
    void taskExceptionIsKept();
    void subTaskEndsAtItsDeadlineOrTheJobs();
    void latestKeepsNewest();
    void plyFilesKeepEveryTriangle();
    void daylightChangesAreLightChanges();
};

void TestCore::exrRoundTrip() {
    QTemporaryDir dir;
    Image img(7, 5);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) img.at(x, y) = Rgb(x * 0.5f, y * 1e-3f, 1e6f + x);
    img.channels["albedo.R"] = std::vector<float>(35, 0.25f);
    img.attributes["lucerna:backend"] = "path";
    img.attributes["lucerna:spp"] = "16";
    const std::string path = dir.filePath("a.exr").toStdString();
    writeExr(path, img);
    const Image back = readExr(path);
    QCOMPARE(back.width, 7);
    QCOMPARE(back.height, 5);
    for (size_t i = 0; i < img.pixels.size(); ++i) QCOMPARE(back.pixels[i], img.pixels[i]);  // 32-bit float, exact
    QCOMPARE(back.channels.at("albedo.R"), img.channels.at("albedo.R"));
    QCOMPARE(back.attributes.at("lucerna:backend"), std::string("path"));
    QCOMPARE(back.attributes.at("lucerna:spp"), std::string("16"));
    // No temporary is left in the folder.
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 1);
}

void TestCore::exrMissingChannelAndGarbage() {
    QTemporaryDir dir;
    const std::string garbage = dir.filePath("g.exr").toStdString();
    {
        QFile f(QString::fromStdString(garbage));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("not an exr file at all");
    }
    QVERIFY_THROWS_EXCEPTION(ImageError, readExr(garbage));
    QVERIFY_THROWS_EXCEPTION(ImageError, readExr(dir.filePath("missing.exr").toStdString()));
    try {
        readExr(garbage);
    } catch (const ImageError& e) {
        QVERIFY(std::string(e.what()).find('\n') == std::string::npos);  // one line
        QVERIFY(std::string(e.what()).find("g.exr") != std::string::npos);
    }
}

void TestCore::atomicWriteLeavesNothingOnFailure() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("out.bin").toStdString();
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, writeAtomically(path, [](const std::string& temp) {
        QFile f(QString::fromStdString(temp));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("half");
        throw std::runtime_error("interrupted");
    }));
    QVERIFY(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).isEmpty());
    // An existing file survives a failed rewrite untouched.
    writeAtomically(path, [](const std::string& temp) {
        QFile f(QString::fromStdString(temp));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("whole");
    });
    try {
        writeAtomically(path, [](const std::string&) { throw std::runtime_error("no"); });
    } catch (const std::runtime_error&) {
    }
    QFile f(QString::fromStdString(path));
    QVERIFY(f.open(QIODevice::ReadOnly));
    QCOMPARE(f.readAll(), QByteArray("whole"));
}

void TestCore::metricsByHand() {
    Image t(2, 1), r(2, 1);
    t.at(0, 0) = Rgb(1, 2, 3);
    r.at(0, 0) = Rgb(1, 1, 1);
    t.at(1, 0) = Rgb(0, 0, 0);
    r.at(1, 0) = Rgb(0.1f, 0.1f, 0.1f);
    const ImageMetrics m = compareImages(t, r);
    // squared errors: 0, 1, 4, 0.01, 0.01, 0.01
    QVERIFY(std::abs(m.rmse - std::sqrt(5.03 / 6)) < 1e-6);
    const double rel = (0 + 1 / 1.01 + 4 / 1.01 + 3 * (0.01 / (0.01 + 0.01))) / 6;
    QVERIFY(std::abs(m.relmse - rel) < 1e-6);
    QVERIFY(std::abs(m.meanTest - 1.0) < 1e-9);
    QVERIFY(std::abs(m.meanRef - 0.55) < 1e-6);
    QCOMPARE(m.nonfinite, 0L);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, compareImages(Image(2, 2), Image(2, 1)));
    QCOMPARE(formatMetrics(m).substr(0, 6), std::string("rmse: "));
}

void TestCore::metricsExcludeNonFinite() {
    Image t(3, 1), r(3, 1);
    t.at(0, 0) = Rgb(NAN, 0, 0);
    t.at(1, 0) = Rgb(1, 1, 1);
    r.at(1, 0) = Rgb(1, 1, 1);
    r.at(2, 0) = Rgb(INFINITY, 0, 0);
    const ImageMetrics m = compareImages(t, r);
    QCOMPARE(m.nonfinite, 1L);       // only the test image's non-finite pixels are counted
    QCOMPARE(m.includedPixels, 1L);  // both are excluded
    QCOMPARE(m.rmse, 0.0);
}

void TestCore::taskRunsOffTheCallingThread() {
    TaskSystem tasks(2);
    std::thread::id worker;
    auto h = tasks.submit([&](TaskContext& ctx) {
        worker = std::this_thread::get_id();
        ctx.setProgress(1.0);
    });
    h->wait();
    QVERIFY(h->isFinished());
    QVERIFY(worker != std::this_thread::get_id());
    QCOMPARE(h->progress(), 1.0);
}

void TestCore::taskCancellationStopsParallelLoop() {
    TaskSystem tasks(2);
    std::atomic<int> done{0};
    std::atomic<bool> started{false};
    auto h = tasks.submit([&](TaskContext& ctx) {
        ctx.parallelFor(0, 100000, [&](int) {
            started = true;
            std::this_thread::sleep_for(std::chrono::microseconds(200));
            ++done;
        });
    });
    while (!started) std::this_thread::yield();
    h->cancel();
    h->wait();
    QVERIFY(h->isCancelled());
    QVERIFY2(done < 100000 / 2, qPrintable(QString::number(done)));
}

void TestCore::taskExceptionIsKept() {
    TaskSystem tasks(1);
    auto h = tasks.submit([](TaskContext&) { throw std::runtime_error("boom"); });
    h->wait();
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, h->rethrowIfFailed());
}

// A sub-task (a grid auto's pilot) is cancelled at its deadline, by its own cancel() or when the
// job is, and never cancels the job; a deadline moved to infinity holds.
void TestCore::subTaskEndsAtItsDeadlineOrTheJobs() {
    const auto waitCancelled = [](const TaskContext& ctx, double seconds) {
        const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        while (!ctx.isCancelled() && std::chrono::steady_clock::now() < until)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        return ctx.isCancelled();
    };
    CancellationToken jobToken;
    const TaskContext job(jobToken);
    {
        SubTask part(job, 0.05);
        QVERIFY(!part.context().isCancelled());
        QVERIFY(waitCancelled(part.context(), 5));
        QVERIFY(!job.isCancelled());
    }
    {
        SubTask part(job, 0.05);
        part.setDeadline(std::numeric_limits<double>::infinity());
        QVERIFY(!waitCancelled(part.context(), 0.2));
        part.cancel();
        QVERIFY(part.context().isCancelled() && !job.isCancelled());
    }
    {
        SubTask part(job, std::numeric_limits<double>::infinity());
        jobToken.cancel();
        QVERIFY(waitCancelled(part.context(), 5));
    }
}

void TestCore::latestKeepsNewest() {
    Latest<int> latest;
    QVERIFY(!latest.get());
    latest.publish(std::make_shared<const int>(1));
    latest.publish(std::make_shared<const int>(2));
    QCOMPARE(*latest.get(), 2);
    QCOMPARE(latest.version(), uint64_t(2));
}

QTEST_GUILESS_MAIN(TestCore)
// writePlyFile and readMeshFile: every triangle in order, non-manifold ones included (three
// triangles on one edge, a repeated vertex), vertices to float precision.
void TestCore::plyFilesKeepEveryTriangle() {
    TriangleMesh mesh;
    mesh.vertices = {V3d(0, 0, 0), V3d(1, 0, 0), V3d(0, 1, 0), V3d(0, -1, 0), V3d(0, 0, 1), V3d(0.1, 0.2, 0.3)};
    mesh.triangles = {V3i(0, 1, 2), V3i(1, 0, 3), V3i(0, 1, 4), V3i(2, 5, 4), V3i(5, 2, 4)};
    QTemporaryDir dir;
    const std::string path = dir.filePath("fan.ply").toStdString();
    writePlyFile(path, mesh);
    const TriangleMesh back = readMeshFile(path);
    QCOMPARE(back.triangles, mesh.triangles);
    QCOMPARE(back.vertices.size(), mesh.vertices.size());
    for (size_t i = 0; i < mesh.vertices.size(); ++i)
        QVERIFY((back.vertices[i] - mesh.vertices[i]).length() < 1e-6);
}

// Site, sky and sun (SPEC.md section 5) are what lights a daylit scene: a change of any is a change
// the preview and the converging render answer, never "nothing" nor a re-mix of light layers. A
// site change moves a sun placed by time; switching a sun under a sky changes the ground's light.
void TestCore::daylightChangesAreLightChanges() {
    Scene base;
    base.site = Site{51.5, -0.1, 0, V3d(0, 0, -1), false};
    Sky sky;
    sky.horizontalIlluminance = 10000;
    base.sky = sky;
    Light sun;
    sun.name = "sun";
    sun.type = LightType::Sun;
    sun.sun = SunSpec();
    sun.sun->illuminanceLux = 75000;
    sun.sun->time = "2025-06-21T12:00";
    Light lamp;
    lamp.name = "lamp";
    lamp.intensity = Rgbd(1, 1, 1);
    base.lights = {lamp, sun};
    QVERIFY(diff(base, base).none());

    Scene moved = base;
    moved.site->latitudeDeg = 48.9;
    SceneChange c = diff(base, moved);
    QVERIFY(!c.none());
    QVERIFY(c.daylight);
    QVERIFY(!c.emissionOnly);
    QCOMPARE(c.lights, std::vector<size_t>{1});  // the sun placed by time moves with its site

    Scene overcast = base;
    overcast.sky->groundReflectance = 0.3;
    c = diff(base, overcast);
    QVERIFY(c.daylight && !c.emissionOnly && !c.none());
    QVERIFY(c.lights.empty());
    Scene skyless = base;
    skyless.sky.reset();
    QVERIFY(diff(base, skyless).daylight);

    Scene later = base;
    later.lights[1].sun->time = "2025-06-21T15:30";
    c = diff(base, later);
    QVERIFY(!c.daylight && !c.emissionOnly);
    QCOMPARE(c.lights, std::vector<size_t>{1});

    // Switching the sun off under a sky is no re-mix (the ground loses the sun's share); without
    // a sky, or switching the lamp, it is one.
    Scene dark = base;
    dark.lights[1].on = false;
    QVERIFY(!diff(base, dark).emissionOnly);
    Scene noSky = base, noSkyDark = base;
    noSky.sky.reset();
    noSkyDark.sky.reset();
    noSkyDark.lights[1].on = false;
    QVERIFY(diff(noSky, noSkyDark).emissionOnly);
    Scene lampOff = base;
    lampOff.lights[0].on = false;
    QVERIFY(diff(base, lampOff).emissionOnly);
}

#include "test_core.moc"
