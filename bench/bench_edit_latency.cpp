// How long a light edit takes to reach the converging render in the application (issue 19: a
// 10,000-light floor must edit without stalls, a light edit in the render within a second):
//
//   QT_QPA_PLATFORM=offscreen bench_edit_latency SCENE.json [EDITS]
//
// opens the scene in the main window as a user would, starts the converging render, and then
// EDITS times (5) changes one light's intensity through the document (as the light panel does):
// prints the time the edit itself holds the window (the document, outliner, panels, preview
// updates) and the time until the converging render shows its first frame of the edited scene.

#include "ui/rendering/converging_render.h"
#include "ui/document/document.h"
#include "ui/window/main_window.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include <cstdio>
#include <cstdlib>

using namespace lucerna;

namespace {

// Runs the event loop until `render` shows a frame, at most `ms`; false on timeout.
bool waitForFrame(ConvergingRender& render, int ms) {
    QEventLoop loop;
    QTimer timeout;
    timeout.setSingleShot(true);
    QObject::connect(&timeout, &QTimer::timeout, &loop, [&] { loop.exit(1); });
    const auto c = QObject::connect(&render, &ConvergingRender::frameReady, &loop, [&] { loop.exit(0); });
    timeout.start(ms);
    const int rc = loop.exec();
    QObject::disconnect(c);
    return rc == 0;
}

}  // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_edit_latency SCENE.json [EDITS]\n");
        return 2;
    }
    const int edits = argc > 2 ? std::atoi(argv[2]) : 5;
    QElapsedTimer clock;
    clock.start();
    MainWindow window(QString::fromLocal8Bit(argv[1]));
    window.resize(1400, 900);
    window.show();
    const double openMs = double(clock.nsecsElapsed()) / 1e6;
    Document& doc = *window.document();
    if (doc.scene().lights.empty()) {
        std::fprintf(stderr, "bench_edit_latency: the scene has no lights\n");
        return 2;
    }
    ConvergingRender& render = *window.convergingRender();
    render.setBackend("path");
    render.start();
    clock.restart();
    if (!waitForFrame(render, 120000)) {
        std::fprintf(stderr, "bench_edit_latency: no first frame in 120 s\n");
        return 1;
    }
    std::printf("lights %zu: window open %.0f ms, first frame %.0f ms\n", doc.scene().lights.size(), openMs,
                double(clock.nsecsElapsed()) / 1e6);
    for (int e = 0; e < edits; ++e) {
        const int index = int((size_t(e) * 7919) % doc.scene().lights.size());
        Light light = doc.scene().lights[size_t(index)];
        light.intensity *= 0.5;
        light.photometric.reset();
        clock.restart();
        doc.setLight(index, light);
        const double editMs = double(clock.nsecsElapsed()) / 1e6;
        const bool shown = waitForFrame(render, 60000);
        std::printf("edit %d (light %d): the edit holds the window %.0f ms; in the converging render after %.0f ms%s\n",
                    e + 1, index, editMs, double(clock.nsecsElapsed()) / 1e6, shown ? "" : " (timed out)");
        std::fflush(stdout);
    }
    return 0;
}
