// The comparison view and the display controls on synthetic images whose every pixel is known:
// the difference of equal images is the ramp's zero colour, the split shows each image on its
// side of the divider and the divider follows a drag, both panes of side by side share zoom and
// pan, false colour puts a known luminance on the legend's colour for it, the probe reads the
// float pixel under the cursor, and the relmse shown is compareImages'. Screenshots of the modes
// go to the test's working directory (the build's tests/ folder).

#include "core/image/image_metrics.h"
#include "core/photometry/photometric_units.h"
#include "render/display/display.h"
#include "render/display/false_colour.h"
#include "ui/compare/compare_canvas.h"
#include "ui/compare/compare_view.h"
#include "ui/rendering/display_controls.h"
#include "ui/rendering/pixel_probe.h"
#include "ui/compare/view_transform.h"

#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QWheelEvent>
#include <QtTest>

#include <cmath>
#include <numbers>

using namespace lucerna;

namespace {

Image uniform(int w, int h, Rgb c) {
    Image image(w, h);
    for (Rgb& p : image.pixels) p = c;
    return image;
}

// A smooth, deterministic picture: a horizontal ramp in red, a vertical one in green.
Image gradient(int w, int h, float scale = 1.0f) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            image.at(x, y) = Rgb(scale * (x + 0.5f) / w, scale * (y + 0.5f) / h, scale * 0.25f);
    return image;
}

// Equal within `tolerance` per channel: ramp colours are interpolated in integers, and a float
// luminance of 10 / 683 cd/m^2 may land a hair below the ramp position it stands for.
bool near(const QColor& a, const QColor& b, int tolerance) {
    return std::abs(a.red() - b.red()) <= tolerance && std::abs(a.green() - b.green()) <= tolerance &&
           std::abs(a.blue() - b.blue()) <= tolerance;
}
#define QVERIFY_NEAR_COLOUR(a, b, tol) \
    QVERIFY2(near((a), (b), (tol)), qPrintable(QString("%1 vs %2").arg((a).name(), (b).name())))

QImage grabbed(QWidget* w) {
    QCoreApplication::processEvents();
    return w->grab().toImage().convertToFormat(QImage::Format_RGB32);
}

void sendMouse(QWidget* w, QEvent::Type type, QPointF pos, Qt::MouseButton button, Qt::MouseButtons buttons) {
    QMouseEvent e(type, pos, w->mapToGlobal(pos), button, buttons, Qt::NoModifier);
    QApplication::sendEvent(w, &e);
}

void drag(QWidget* w, QPointF from, QPointF to) {
    sendMouse(w, QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    for (int i = 1; i <= 4; ++i)
        sendMouse(w, QEvent::MouseMove, from + (to - from) * (i / 4.0), Qt::NoButton, Qt::LeftButton);
    sendMouse(w, QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
}

// The widget position of the centre of pixel (x, y) of an image of width x height on a canvas.
QPointF centreOfPixel(const CompareCanvas* canvas, int x, int y, int width, int height) {
    const QRectF r = canvas->imageRect();
    return {r.x() + (x + 0.5) * r.width() / width, r.y() + (y + 0.5) * r.height() / height};
}

std::unique_ptr<CompareView> shownView() {
    auto view = std::make_unique<CompareView>();
    view->resize(1000, 420);
    view->show();
    if (!QTest::qWaitForWindowExposed(view.get())) return nullptr;
    return view;
}

}  // namespace

class TestCompareView : public QObject {
    Q_OBJECT
private slots:
    void differenceOfEqualImagesIsTheZeroColour();
    void differenceLegendReadsTheDifference();
    void splitShowsEachImageOnItsSide();
    void sideBySideSharesZoomAndPan();
    void falseColourPutsALuminanceOnTheLegendsColour();
    void falseColourLuxFromTheAlbedoLayer();
    void luxRangeFromTheImageAndAsTyped();
    void exposureAndToneCurve();
    void probeReadsThePixelUnderTheCursor();
    void relmseIsCompareImages();
};

void TestCompareView::differenceOfEqualImagesIsTheZeroColour() {
    auto view = shownView();
    QVERIFY(view);
    const Image image = gradient(64, 48);
    view->setPreview(image);
    view->setConverged(image);
    QCOMPARE(*view->relmse(), 0.0);
    for (auto mode : {CompareView::Mode::AbsoluteDifference, CompareView::Mode::RelativeDifference}) {
        view->setMode(mode);
        QVERIFY(!view->secondCanvas()->isVisible());
        const QImage shot = grabbed(view->firstCanvas());
        const QRect r = view->firstCanvas()->imageRect().toAlignedRect().adjusted(2, 2, -2, -2);
        const QRect legend = legendRect(view->firstCanvas()->rect()).adjusted(-8, -20, 80, 20);
        const QColor zero = falseColourRamp(0);
        int checked = 0;
        for (int y = r.top(); y <= r.bottom(); y += 3)
            for (int x = r.left(); x <= r.right(); x += 3) {
                if (legend.contains(x, y) || y < 30) continue;  // the legend, the caption
                QCOMPARE(shot.pixelColor(x, y), zero);
                ++checked;
            }
        QVERIFY(checked > 1000);
    }
    grabbed(view.get()).save("compare_difference_equal.png");
}

void TestCompareView::differenceLegendReadsTheDifference() {
    // The preview is the converged image plus 0.3 in every channel of the left half: the absolute
    // difference there is 0.3, which is also the 99th percentile the legend tops out at.
    auto view = shownView();
    QVERIFY(view);
    const Image converged = gradient(40, 30);
    Image preview = converged;
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 20; ++x) preview.at(x, y) = preview.at(x, y) + Rgb(0.3f, 0.3f, 0.3f);
    view->setPreview(preview);
    view->setConverged(converged);
    view->setMode(CompareView::Mode::AbsoluteDifference);
    const auto legend = view->firstCanvas()->legend();
    QVERIFY(legend);
    QCOMPARE(legend->lo, 0.0);
    QVERIFY(std::abs(legend->hi - 0.3) < 1e-5);
    const QImage shot = grabbed(view->firstCanvas());
    const QPointF left = centreOfPixel(view->firstCanvas(), 5, 15, 40, 30);
    const QPointF right = centreOfPixel(view->firstCanvas(), 30, 15, 40, 30);
    QVERIFY_NEAR_COLOUR(shot.pixelColor(left.toPoint()), legendColour(*legend, 0.3), 2);
    QCOMPARE(shot.pixelColor(right.toPoint()), legendColour(*legend, 0.0));
    grabbed(view.get()).save("compare_difference.png");
}

void TestCompareView::splitShowsEachImageOnItsSide() {
    auto view = shownView();
    QVERIFY(view);
    view->setPreview(uniform(40, 30, Rgb(1, 0, 0)));     // red
    view->setConverged(uniform(80, 60, Rgb(0, 0, 1)));   // blue, another size
    view->setMode(CompareView::Mode::Split);
    QCoreApplication::processEvents();  // the first pane takes the room the second left
    CompareCanvas* canvas = view->firstCanvas();
    QVERIFY(canvas->isSplit());
    QVERIFY(!view->secondCanvas()->isVisible());
    const int y = int(canvas->imageRect().center().y()) + 20;  // below the divider's handle
    const auto check = [&](int expectLeftOfDivider) {
        const QImage shot = grabbed(canvas);
        const QRectF r = canvas->imageRect();
        const int d = canvas->dividerX();
        QVERIFY(r.left() < d - 10 && d + 10 < r.right());
        for (int x = int(r.left()) + 2; x < d - 2; x += 4) QCOMPARE(shot.pixelColor(x, y), QColor(255, 0, 0));
        for (int x = d + 2; x < int(r.right()) - 2; x += 4) QCOMPARE(shot.pixelColor(x, y), QColor(0, 0, 255));
        QCOMPARE(d, expectLeftOfDivider);
    };
    check(int(std::lround(0.5 * canvas->width())));
    grabbed(view.get()).save("compare_split.png");
    // Drag the divider to a third of the width; a drag elsewhere pans instead and leaves it.
    const int third = canvas->width() / 3;
    drag(canvas, QPointF(canvas->dividerX(), y), QPointF(third, y));
    check(third);
    const QPointF centreBefore = view->transform()->centre();
    drag(canvas, QPointF(third + 60, y), QPointF(third + 90, y));
    QCOMPARE(canvas->dividerX(), third);
    QVERIFY(view->transform()->centre().x() < centreBefore.x());
}

void TestCompareView::sideBySideSharesZoomAndPan() {
    auto view = shownView();
    QVERIFY(view);
    view->setPreview(gradient(40, 30));
    view->setConverged(gradient(80, 60));
    view->setMode(CompareView::Mode::SideBySide);
    CompareCanvas *a = view->firstCanvas(), *b = view->secondCanvas();
    QVERIFY(a->isVisible() && b->isVisible());
    QCOMPARE(a->size(), b->size());
    // Zoom in on a with the wheel about a point off-centre: the point stays under the cursor...
    const QPointF anchor = a->imageRect().topLeft() + QPointF(a->imageRect().width() * 0.3, a->imageRect().height() * 0.6);
    const QPointF before = a->toImage(anchor);
    QWheelEvent wheel(anchor, a->mapToGlobal(anchor), {}, QPoint(0, 480), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(a, &wheel);
    QVERIFY(std::abs(view->transform()->zoom() - 2.0) < 1e-9);
    QVERIFY(std::abs(a->toImage(anchor).x() - before.x()) < 1e-9);
    QVERIFY(std::abs(a->toImage(anchor).y() - before.y()) < 1e-9);
    // ...and b shows the same image point at the same place.
    QCOMPARE(b->imageRect(), a->imageRect());
    // Pan in b: a follows.
    const QPointF grabbedPoint = b->toImage(QPointF(200, 200));
    drag(b, QPointF(200, 200), QPointF(150, 180));
    QCOMPARE(a->imageRect(), b->imageRect());
    for (CompareCanvas* c : {a, b}) {
        QVERIFY(std::abs(c->toImage(QPointF(150, 180)).x() - grabbedPoint.x()) < 1e-9);
        QVERIFY(std::abs(c->toImage(QPointF(150, 180)).y() - grabbedPoint.y()) < 1e-9);
    }
    // The pictures follow too: the same image point shows the same colour in both panes.
    const QImage sa = grabbed(a), sb = grabbed(b);
    const QPoint p(a->width() / 3, a->height() / 2);
    QVERIFY_NEAR_COLOUR(sa.pixelColor(p), sb.pixelColor(p), 8);  // 40 vs 80 pixels across
    grabbed(view.get()).save("compare_side_by_side.png");
}

void TestCompareView::falseColourPutsALuminanceOnTheLegendsColour() {
    auto view = shownView();
    QVERIFY(view);
    // Grey radiance of luminance 10 / 683, that is 10 cd/m^2: the middle of the 0.1..1000 log
    // range.
    const float v = float(10.0 / kLumensPerWatt);
    view->setPreview(uniform(40, 30, Rgb(v, v, v)));
    view->setConverged(uniform(40, 30, Rgb(v, v, v)));
    auto* mode = view->displayControls()->findChild<QComboBox*>("toneMapping");
    QVERIFY(mode);
    mode->setCurrentIndex(2);  // as a user picks it
    QVERIFY(view->displaySettings().falseColour);
    QCOMPARE(view->displaySettings().falseMin, 0.1);
    QCOMPARE(view->displaySettings().falseMax, 1000.0);
    CompareCanvas* canvas = view->secondCanvas();
    const auto legend = canvas->legend();
    QVERIFY(legend && legend->logScale && legend->unit == QString("cd/m\u00b2"));
    QCOMPARE(legendPosition(*legend, 10.0), 0.5);
    const QColor expected = legendColour(*legend, 10.0);
    const QImage shot = grabbed(canvas);
    // The picture, away from the legend...
    const QRectF r = canvas->imageRect();
    QVERIFY_NEAR_COLOUR(shot.pixelColor(QPointF(r.left() + 10, r.center().y()).toPoint()), expected, 1);
    // ...and the legend's ramp where it stands for 10 cd/m^2 (halfway up).
    const QRect ramp = legendRect(canvas->rect());
    // (One row of the ramp is about 5 levels: a tolerance of 4 pins the row.)
    QVERIFY_NEAR_COLOUR(shot.pixelColor(ramp.center().x(), ramp.bottom() - ramp.height() / 2), expected, 4);
    grabbed(view.get()).save("compare_false_colour.png");
    // The range is the user's: 1..10000 puts 10 cd/m^2 at a quarter.
    view->displayControls()->findChild<QDoubleSpinBox*>("falseMin")->setValue(1);
    view->displayControls()->findChild<QDoubleSpinBox*>("falseMax")->setValue(10000);
    QCOMPARE(legendPosition(*canvas->legend(), 10.0), 0.25);
    QVERIFY_NEAR_COLOUR(grabbed(canvas).pixelColor(QPointF(r.left() + 10, r.center().y()).toPoint()), falseColourRamp(0.25), 1);
}

void TestCompareView::exposureAndToneCurve() {
    // One stop more shows 0.1 as 0.2 is shown without it.
    DisplaySettings s;
    s.exposureStops = 1;
    QCOMPARE(toDisplayImage(uniform(2, 2, Rgb(0.1f, 0.1f, 0.1f)), s).pixelColor(0, 0),
             toDisplayImage(uniform(2, 2, Rgb(0.2f, 0.2f, 0.2f))).pixelColor(0, 0));
    // Linear sRGB clips at 1; the filmic curve keeps 1 below white, rises monotonically and
    // still separates 4 from 8.
    DisplaySettings filmic;
    filmic.curve = ToneCurve::Filmic;
    const auto shown = [](float v, const DisplaySettings& d) { return toDisplayImage(uniform(1, 1, Rgb(v, v, v)), d).pixelColor(0, 0).red(); };
    QCOMPARE(shown(1.0f, DisplaySettings{}), 255);
    QVERIFY(shown(1.0f, filmic) < 240);
    int last = -1;
    for (float v : {0.01f, 0.1f, 0.5f, 1.0f, 2.0f, 4.0f}) {
        QVERIFY(shown(v, filmic) > last);
        last = shown(v, filmic);
    }
    // Through the controls: the spin box sets the view's exposure.
    auto view = shownView();
    QVERIFY(view);
    auto* exposure = view->displayControls()->findChild<QDoubleSpinBox*>("exposure");
    exposure->setValue(2);
    QCOMPARE(view->displaySettings().exposureStops, 2.0f);
    view->setPreview(uniform(10, 10, Rgb(0.05f, 0.05f, 0.05f)));
    view->setConverged(uniform(10, 10, Rgb(0.05f, 0.05f, 0.05f)));
    const QImage shot = grabbed(view->firstCanvas());
    QCOMPARE(shot.pixelColor(view->firstCanvas()->imageRect().center().toPoint() + QPoint(0, 30)),
             toDisplayImage(uniform(1, 1, Rgb(0.2f, 0.2f, 0.2f))).pixelColor(0, 0));

    // White balance through the controls: a grey lit at 3000 K shows neutral with "White 3000 K"
    // and with "the lights" when the scene's lights are 3000 K; amber with D65.
    const Rgbd lamp = blackbodyColour(3000);
    const Image warm = uniform(10, 10, Rgb(float(0.05 * lamp.x), float(0.05 * lamp.y), float(0.05 * lamp.z)));
    view->setPreview(warm);
    view->setConverged(warm);
    const QPoint centre = view->firstCanvas()->imageRect().center().toPoint() + QPoint(0, 30);
    const QColor amber = grabbed(view->firstCanvas()).pixelColor(centre);
    QCOMPARE_GT(amber.red() - amber.blue(), 40);
    auto* white = view->displayControls()->findChild<QComboBox*>("whiteBalance");
    QVERIFY(white && white->isVisible());
    white->setCurrentIndex(white->findText("White 3000 K"));
    QCOMPARE(view->displaySettings().white.reference, WhiteReference::Temperature);
    const QColor balanced = grabbed(view->firstCanvas()).pixelColor(centre);
    QVERIFY_NEAR_COLOUR(balanced, QColor(balanced.green(), balanced.green(), balanced.green()), 1);
    view->setLightsWhite(lamp);
    white->setCurrentIndex(white->findText("White: the lights"));
    QVERIFY_NEAR_COLOUR(grabbed(view->firstCanvas()).pixelColor(centre), balanced, 1);
    white->setCurrentIndex(white->findText("White D65"));
    QCOMPARE(grabbed(view->firstCanvas()).pixelColor(centre), amber);
}

void TestCompareView::probeReadsThePixelUnderTheCursor() {
    auto view = shownView();
    QVERIFY(view);
    Image converged = gradient(8, 6);
    converged.at(3, 2) = Rgb(0.5f, 0.25f, 0.125f);
    Image preview = gradient(4, 3);
    preview.at(1, 1) = Rgb(2.0f, 1.0f, 0.0f);  // the preview pixel over converged (3, 2)
    view->setPreview(preview);
    view->setConverged(converged);
    for (CompareCanvas* canvas : {view->firstCanvas(), view->secondCanvas()}) {
        view->probeLabel()->clear();
        sendMouse(canvas, QEvent::MouseMove, centreOfPixel(canvas, 3, 2, 8, 6), Qt::NoButton, Qt::NoButton);
        const QString text = view->probeLabel()->text();
        QVERIFY2(text.startsWith("(3, 2)"), qPrintable(text));
        // Radiance as stored, luminance 683 * Y in cd/m^2.
        const double cd = kLumensPerWatt * (0.2126 * 0.5 + 0.7152 * 0.25 + 0.0722 * 0.125);
        QVERIFY2(text.contains(QString("converged RGB 0.5 0.25 0.125  L %1 cd/m\u00b2").arg(cd, 0, 'g', 4)), qPrintable(text));
        QVERIFY2(text.contains(QString("preview RGB 2 1 0  L %1 cd/m\u00b2").arg(kLumensPerWatt * (0.2126 * 2 + 0.7152), 0, 'g', 4)),
                 qPrintable(text));
    }
    // Off the image, nothing.
    sendMouse(view->firstCanvas(), QEvent::MouseMove, QPointF(1, 1), Qt::NoButton, Qt::NoButton);
    QVERIFY(view->probeLabel()->text().isEmpty());
}

void TestCompareView::relmseIsCompareImages() {
    auto view = shownView();
    QVERIFY(view);
    QVERIFY(!view->relmse());
    QCOMPARE(view->relmseLabel()->text(), QString("relmse \u2014"));
    Image preview = gradient(20, 15, 1.3f);
    preview.at(4, 4) = Rgb(NAN, 0, 0);  // excluded, as SPEC.md says
    const Image converged = gradient(40, 30);
    view->setPreview(preview);
    view->setConverged(converged);
    const double expected = compareImages(resampledNearest(preview, 40, 30), converged).relmse;
    QVERIFY(expected > 0.01);
    QCOMPARE(*view->relmse(), expected);
    QCOMPARE(view->relmseLabel()->text(), QString("relmse %1").arg(QString::number(expected, 'g', 6)));
}

// Lux from radiance and albedo: a white-lit matt surface of albedo (0.8, 0.4, 0.2) under 100 lx
// has L = albedo E / pi per channel; the lux view puts 100 lx on the legend's colour for it, the
// probe reads it, an illuminance layer takes precedence, and a black surface shows the bottom.
void TestCompareView::falseColourLuxFromTheAlbedoLayer() {
    const double E = 100.0 / kLumensPerWatt;  // W/m^2 of white light: 100 lx
    const Rgb albedo(0.8f, 0.4f, 0.2f);
    Image image = uniform(40, 30, albedo * float(E / std::numbers::pi));
    for (int c = 0; c < 3; ++c) image.channels[std::string("albedo.") + "RGB"[c]].assign(image.pixelCount(), albedo[c]);
    image.channels["albedo.R"][0] = image.channels["albedo.G"][0] = image.channels["albedo.B"][0] = 0.0f;
    QVERIFY(std::abs(*pixelIlluminance(image, 5) - 100.0) < 1e-3);
    QVERIFY(!pixelIlluminance(image, 0));  // nothing to divide by
    QVERIFY(probeText(image, QPoint(5, 0)).contains("E 100 lx"));
    QVERIFY(!pixelIlluminance(uniform(4, 4, Rgb(1, 1, 1)), 0));  // no layer at all

    auto view = shownView();
    view->setPreview(image);
    view->setConverged(image);
    auto* mode = view->displayControls()->findChild<QComboBox*>("toneMapping");
    mode->setCurrentIndex(3);  // False colour lx
    QVERIFY(view->displaySettings().falseColour);
    QVERIFY(view->displaySettings().quantity == FalseColourQuantity::Illuminance);
    view->displayControls()->findChild<QDoubleSpinBox*>("falseMin")->setValue(1);
    view->displayControls()->findChild<QDoubleSpinBox*>("falseMax")->setValue(10000);
    CompareCanvas* canvas = view->secondCanvas();
    const auto legend = canvas->legend();
    QVERIFY(legend && legend->unit == QString("lx"));
    const QImage shot = grabbed(canvas);
    const QRectF r = canvas->imageRect();
    QVERIFY_NEAR_COLOUR(shot.pixelColor(QPointF(r.left() + 10, r.center().y()).toPoint()), legendColour(*legend, 100.0), 1);
    grabbed(view.get()).save("compare_false_colour_lux.png");

    // An illuminance layer is what the view shows where there is one.
    image.channels["illuminance.Y"].assign(image.pixelCount(), 1000.0f);
    QCOMPARE(*pixelIlluminance(image, 0), 1000.0);
}

// The lux view's range: from the image on entering it (2nd to 98th percentile, widened to round
// numbers), then as typed: each field takes its value when the typing ends and leaves the other
// alone; a maximum not above the minimum is refused with a message and the range kept; a later
// image no longer moves a range the user set.
void TestCompareView::luxRangeFromTheImageAndAsTyped() {
    // Illuminance 130 .. 870 lx across the image (a ramp along x, 100 columns).
    Image image = uniform(100, 10, Rgb(0.1f, 0.1f, 0.1f));
    auto& lux = image.channels["illuminance.Y"];
    lux.resize(image.pixelCount());
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 100; ++x) lux[size_t(y) * 100 + x] = float(130 + 740 * x / 99.0);
    const auto range = illuminanceRange(image);
    QVERIFY(range);
    QCOMPARE(range->lo, 100.0);  // the 2nd percentile, 144.8 lx, down to a round number
    QCOMPARE(range->hi, 1000.0); // the 98th, 855.2 lx, up
    QVERIFY(!illuminanceRange(uniform(4, 4, Rgb(1, 1, 1))));  // no lux at all

    auto view = shownView();
    view->setConverged(image);
    auto* controls = view->displayControls();
    auto* mode = controls->findChild<QComboBox*>("toneMapping");
    auto* minField = controls->findChild<QDoubleSpinBox*>("falseMin");
    auto* maxField = controls->findChild<QDoubleSpinBox*>("falseMax");
    mode->setCurrentIndex(3);  // False colour lx
    QCOMPARE(view->displaySettings().falseMin, 100.0);
    QCOMPARE(view->displaySettings().falseMax, 1000.0);
    QCOMPARE(minField->value(), 100.0);
    QCOMPARE(maxField->value(), 1000.0);
    grabbed(view.get()).save("compare_lux_range_default.png");

    QSignalSpy messages(controls, &DisplayControls::message);
    const auto type = [](QDoubleSpinBox* field, const QString& text) {
        field->setFocus();
        field->selectAll();
        QTest::keyClicks(field, text);
        // Nothing is taken while typing: the prefix "5" of "50" never reaches the range.
        QTest::keyClick(field, Qt::Key_Return);
    };
    type(minField, "50");
    QCOMPARE(view->displaySettings().falseMin, 50.0);
    QCOMPARE(view->displaySettings().falseMax, 1000.0);  // not moved by the minimum
    QCOMPARE(maxField->value(), 1000.0);
    type(maxField, "300");
    QCOMPARE(view->displaySettings().falseMax, 300.0);
    QCOMPARE(view->displaySettings().falseMin, 50.0);
    QCOMPARE(messages.count(), 0);
    type(maxField, "20");  // below the minimum: refused, the range kept
    QCOMPARE(messages.count(), 1);
    QVERIFY2(messages.at(0).at(0).toString().contains("must be above the minimum"), qPrintable(messages.at(0).at(0).toString()));
    QCOMPARE(view->displaySettings().falseMax, 300.0);
    QCOMPARE(maxField->value(), 300.0);
    QCOMPARE(minField->value(), 50.0);
    type(minField, "300");  // equal to the maximum: refused too
    QCOMPARE(messages.count(), 2);
    QCOMPARE(view->displaySettings().falseMin, 50.0);
    QCOMPARE(minField->value(), 50.0);

    grabbed(view.get()).save("compare_lux_range_typed.png");

    // A new image keeps the range the user set.
    for (float& v : lux) v *= 10;
    view->setConverged(image);
    QCOMPARE(view->displaySettings().falseMin, 50.0);
    QCOMPARE(view->displaySettings().falseMax, 300.0);
}

QTEST_MAIN(TestCompareView)
#include "test_compare_view.moc"
