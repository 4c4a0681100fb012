// How soon a scene opened in the application shows a picture (issue 40: the office's first
// picture within 2 s on llvmpipe):
//
//   QT_QPA_PLATFORM=offscreen bench_first_picture SCENE.json [RUNS]
//
// opens the scene in the main window as `lucerna SCENE.json` does and prints, per run, the time
// the window takes to open, then from the start until the live preview's first frame, its first
// frame at full quality (LiveFrame::coarse false), and the converging render's first frame.

#include "ui/rendering/converging_render.h"
#include "ui/rendering/live_preview.h"
#include "ui/window/main_window.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include <cstdio>
#include <cstdlib>

using namespace lucerna;

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_first_picture SCENE.json [RUNS]\n");
        return 2;
    }
    const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 1;
    for (int run = 0; run < runs; ++run) {
        QElapsedTimer clock;
        clock.start();
        MainWindow window(QString::fromLocal8Bit(argv[1]));
        window.resize(1600, 1000);
        window.show();
        const double openMs = double(clock.nsecsElapsed()) / 1e6;
        double previewMs = -1, fullMs = -1, renderMs = -1;
        QEventLoop loop;
        const auto now = [&] { return double(clock.nsecsElapsed()) / 1e6; };
        const auto check = [&] {
            if (previewMs >= 0 && fullMs >= 0 && renderMs >= 0) loop.exit(0);
        };
        QObject::connect(window.livePreview(), &LivePreview::frameReady, &loop, [&] {
            const auto frame = window.livePreview()->frame();
            if (!frame) return;
            if (previewMs < 0) previewMs = now();
            if (fullMs < 0 && !frame->coarse) fullMs = now();
            check();
        });
        QObject::connect(window.convergingRender(), &ConvergingRender::frameReady, &loop, [&] {
            if (renderMs < 0) renderMs = now();
            check();
        });
        QTimer timeout;
        timeout.setSingleShot(true);
        QObject::connect(&timeout, &QTimer::timeout, &loop, [&] { loop.exit(1); });
        timeout.start(120000);
        const int rc = loop.exec();
        std::printf("run %d: window open %.0f ms, live preview's first frame %.0f ms, at full quality %.0f ms, "
                    "converging render's first frame %.0f ms%s\n",
                    run + 1, openMs, previewMs, fullMs, renderMs, rc ? " (timed out at 120 s)" : "");
        std::fflush(stdout);
    }
    return 0;
}
