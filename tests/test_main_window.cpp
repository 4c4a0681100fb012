// The application window on the bundled default scene: the converging render arrives, is shown,
// and keeps converging. Saves a screenshot (main_window.png in the working directory).

#include "ui/main_window.h"

#include <QApplication>
#include <QLabel>
#include <QStatusBar>
#include <QtTest>

using namespace lucerna;

class TestMainWindow : public QObject {
    Q_OBJECT
private slots:
    void showsConvergingRender();
    void badSceneShowsErrorAndKeepsRunning();
};

void TestMainWindow::showsConvergingRender() {
    MainWindow window(std::string(LUCERNA_RESOURCE_DIR) + "/scenes/cornell-box.json");
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QTRY_VERIFY_WITH_TIMEOUT(window.shownFrame() != nullptr, 20000);
    const double firstSpp = window.shownFrame()->samplesPerPixel;
    QTRY_VERIFY_WITH_TIMEOUT(window.shownFrame()->samplesPerPixel > firstSpp, 20000);
    const auto* label = window.findChild<QLabel*>();
    QVERIFY(label);
    const QImage shown = label->pixmap().toImage();
    QCOMPARE(shown.width(), shown.height());  // the square image keeps its aspect when fitted
    QVERIFY(shown.width() >= 256);
    // The red wall is on the left, the green wall on the right (SPEC.md).
    const int w = shown.width();
    const QColor left = shown.pixelColor(w * 20 / 256, w / 2), right = shown.pixelColor(w * 236 / 256, w / 2);
    QVERIFY2(left.red() > 2 * left.green(), qPrintable(left.name()));
    QVERIFY2(right.green() > 1.3 * right.red() && right.green() > right.blue(), qPrintable(right.name()));
    QVERIFY(window.statusBar()->currentMessage().contains("spp"));
    window.grab().save("main_window.png");
}

void TestMainWindow::badSceneShowsErrorAndKeepsRunning() {
    MainWindow window("/nonexistent/scene.json");
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.statusBar()->currentMessage().contains("scene.json"));
    QVERIFY(window.shownFrame() == nullptr);
}

QTEST_MAIN(TestMainWindow)
#include "test_main_window.moc"
