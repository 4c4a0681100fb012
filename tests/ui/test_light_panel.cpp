// The light panel in photometric units (issue 25), driven through the real window: a new point
// light is 1000 lm at 3000 K; typing lumens gives the light that flux (683 x Y(intensity) x 4 pi)
// in one undo step, and undo restores the light exactly; a colour temperature, a picked colour
// and a switch to candela are one step each and keep the flux; a spot keeps its lumens over a new
// cone; a sun is edited in lux; the bundled luminaire scene's washer shows its distribution as a
// polar plot (curves in the lower half, the peak label the distribution's maximum) and takes a
// colour temperature. Screenshots of the panel go to the working directory.

#include "core/photometry/goniometric_distribution.h"
#include "core/photometry/light_output.h"
#include "core/photometry/luminaire.h"
#include "core/scene/scene_io.h"
#include "ui/properties/colour_edit.h"
#include "ui/properties/light_colour_edit.h"
#include "ui/properties/light_properties.h"
#include "ui/properties/luminaire_polar_plot.h"
#include "ui/window/main_window.h"
#include "ui/scene_panels/outliner.h"
#include "ui/properties/properties_panel.h"
#include "window_test_helpers.h"

#include <QComboBox>
#include <QLabel>
#include <QToolButton>
#include <QtTest>

#include <numbers>

using namespace lucerna;
using namespace lucerna::test;

namespace {

// The flux of a point light by the scene format's conversion, straight from the radiant intensity.
double pointFlux(const Light& l) { return kLumensPerWatt * luminance(l.intensity) * 4.0 * std::numbers::pi; }

bool near(double a, double b, double relative) { return std::abs(a - b) <= relative * std::abs(b); }

struct Window {
    explicit Window(const QString& path) : w(path) {
        w.show();
        exposed = QTest::qWaitForWindowExposed(&w);
    }
    MainWindow w;
    bool exposed = false;
};

// Selects a colour mode in the list as a user would (activated, not just the index).
void chooseMode(QComboBox* combo, int index) {
    combo->setCurrentIndex(index);
    emit combo->activated(index);
}

}  // namespace

class TestLightPanel : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { useTestSettings("test_light_panel"); }
    void pointLightInLumensAndKelvin();
    void spotKeepsItsLumensOverItsCone();
    void sunInLux();
    void luminaireShowsItsDistribution();
};

void TestLightPanel::pointLightInLumensAndKelvin() {
    Window win(cornellPath());
    QVERIFY(win.exposed);
    MainWindow& w = win.w;
    Document* doc = w.document();
    QUndoStack* undo = doc->undoStack();
    LightProperties* props = w.lightProperties();

    // A new point light: 1000 lm at 3000 K, written with those keys.
    trigger(w, "actionAddPointLight");
    QCOMPARE(doc->scene().lights.size(), size_t(1));
    const Light added = doc->scene().lights[0];
    QVERIFY(added.photometric);
    QCOMPARE(added.photometric->quantity, PhotometricSpec::Quantity::Lumens);
    QCOMPARE(added.photometric->value, 1000.0);
    QCOMPARE(added.photometric->temperatureK, std::optional<double>(3000.0));
    QVERIFY2(near(pointFlux(added), 1000, 1e-9), qPrintable(QString::number(pointFlux(added))));
    QVERIFY(added.intensity.x > added.intensity.z);  // 3000 K is warm
    QCOMPARE(props->outputField()->value(), 1000.0);
    QCOMPARE(props->outputUnitField()->currentText(), QString("lm"));
    QVERIFY(props->outputField()->isVisibleTo(props));
    QVERIFY(props->colourField()->usesTemperature());
    QCOMPARE(props->colourField()->temperatureField()->value(), 3000.0);
    QVERIFY(!props->powerFields()[0]->isVisibleTo(props));  // W/sr only in the advanced view
    QVERIFY(saveSceneToString(doc->scene()).find(R"("lumens": 1000, "temperature": 3000)") != std::string::npos);
    screenshot(*w.propertiesPanel(), "light_panel_point.png");

    // Dimming: one typed value, one undo step, the flux as typed; undo gives the light back exactly.
    const int steps = undo->index();
    typeInto(props->outputField(), 350);
    QCOMPARE(undo->index(), steps + 1);
    const Light dimmed = doc->scene().lights[0];
    QVERIFY2(near(pointFlux(dimmed), 350, 1e-6), qPrintable(QString::number(pointFlux(dimmed))));
    QCOMPARE(dimmed.photometric->temperatureK, std::optional<double>(3000.0));
    // The colour did not move: the channels scale together.
    QVERIFY(near(dimmed.intensity.z / dimmed.intensity.x, added.intensity.z / added.intensity.x, 1e-12));
    QVERIFY(saveSceneToString(doc->scene()).find(R"("lumens": 350, "temperature": 3000)") != std::string::npos);
    trigger(w, "actionUndo");
    QCOMPARE(doc->scene().lights[0], added);
    QCOMPARE(props->outputField()->value(), 1000.0);
    trigger(w, "actionRedo");
    QCOMPARE(doc->scene().lights[0], dimmed);

    // Arrow steps of one field are one step until its editing finishes.
    props->outputField()->setFocus();
    for (int i = 0; i < 3; ++i) QTest::keyClick(props->outputField(), Qt::Key_Up);
    QCOMPARE(undo->index(), steps + 2);
    QVERIFY(near(doc->scene().lights[0].photometric->value, 353, 1e-12));
    QTest::keyClick(props->outputField(), Qt::Key_Return);
    trigger(w, "actionUndo");
    QCOMPARE(doc->scene().lights[0], dimmed);

    // A colour temperature: one step, the flux kept, the light bluer.
    const int beforeKelvin = undo->index();
    typeInto(props->colourField()->temperatureField(), 5000);
    QCOMPARE(undo->index(), beforeKelvin + 1);
    const Light cooler = doc->scene().lights[0];
    QCOMPARE(cooler.photometric->temperatureK, std::optional<double>(5000.0));
    QVERIFY(near(pointFlux(cooler), 350, 1e-9));
    QVERIFY(cooler.intensity.z / cooler.intensity.x > 1.5 * dimmed.intensity.z / dimmed.intensity.x);
    trigger(w, "actionUndo");
    QCOMPARE(doc->scene().lights[0], dimmed);

    // A colour instead: the mode is one step, a picked colour another; the flux stays.
    chooseMode(props->colourField()->modeField(), 1);
    QCOMPARE(undo->index(), beforeKelvin + 1);
    QVERIFY(!doc->scene().lights[0].photometric->temperatureK);
    QVERIFY(near(pointFlux(doc->scene().lights[0]), 350, 1e-9));
    const Light warmColour = doc->scene().lights[0];
    props->colourField()->colourField()->pick(QColor(40, 90, 255));
    QCOMPARE(undo->index(), beforeKelvin + 2);
    const Light blue = doc->scene().lights[0];
    QVERIFY(blue.intensity.z > 5 * blue.intensity.x);
    screenshot(*w.propertiesPanel(), "light_panel_colour.png");
    QVERIFY(near(pointFlux(blue), 350, 1e-9));
    QVERIFY(saveSceneToString(doc->scene()).find(R"("lumens": 350, "color": [)") != std::string::npos);
    {
        // The file reads back as the same light.
        const Scene reread = parseScene(saveSceneToString(doc->scene()), cornellPath().toStdString());
        QCOMPARE(reread.lights.size(), size_t(1));
        QCOMPARE(reread.lights[0].photometric, blue.photometric);
        QVERIFY(near(reread.lights[0].intensity.z, blue.intensity.z, 1e-12));
    }
    // The blue light bug: one undo gives back the whole previous light, not part of its colour.
    trigger(w, "actionUndo");
    QCOMPARE(doc->scene().lights[0], warmColour);
    trigger(w, "actionUndo");
    QCOMPARE(doc->scene().lights[0], dimmed);
    QVERIFY(props->colourField()->usesTemperature());

    // Candela: one step; the light is the same, only its keys change.
    props->outputUnitField()->setCurrentIndex(1);
    emit props->outputUnitField()->activated(1);
    QCOMPARE(undo->index(), beforeKelvin + 1);
    const Light inCandela = doc->scene().lights[0];
    QCOMPARE(inCandela.photometric->quantity, PhotometricSpec::Quantity::Candela);
    QVERIFY(near(inCandela.photometric->value, 350 / (4 * std::numbers::pi), 1e-12));
    QVERIFY(near(inCandela.intensity.x, dimmed.intensity.x, 1e-12));
    QVERIFY(std::abs(props->outputField()->value() - 350 / (4 * std::numbers::pi)) <= 0.05);  // one decimal
    typeInto(props->outputField(), 100);
    QVERIFY(near(kLumensPerWatt * luminance(doc->scene().lights[0].intensity), 100, 1e-9));

    // The advanced view: W/sr per channel, and a typed channel is the intensity as typed.
    QVERIFY(props->advancedToggle()->isVisibleTo(props));
    props->advancedToggle()->setChecked(true);
    QVERIFY(props->powerFields()[0]->isVisibleTo(props));
    screenshot(*w.propertiesPanel(), "light_panel_radiometric.png");
    const int beforePower = undo->index();
    typeInto(props->powerFields()[1], 0.5);
    QCOMPARE(undo->index(), beforePower + 1);
    QCOMPARE(doc->scene().lights[0].intensity.y, 0.5);
    // Still in candela, as the designer chose; the keys now give a colour instead of 3000 K.
    QCOMPARE(doc->scene().lights[0].photometric->quantity, PhotometricSpec::Quantity::Candela);
    QVERIFY(!doc->scene().lights[0].photometric->temperatureK);
    QVERIFY(near(photometricIntensity(*doc->scene().lights[0].photometric, pointSolidAngle()).y, 0.5, 1e-12));
    QVERIFY(saveSceneToString(doc->scene()).find(R"("candela": )") != std::string::npos);
    QVERIFY(std::abs(props->outputField()->value() - luminousIntensityCd(doc->scene().lights[0])) <= 0.05);
}

void TestLightPanel::spotKeepsItsLumensOverItsCone() {
    Window win(cornellPath());
    QVERIFY(win.exposed);
    MainWindow& w = win.w;
    Document* doc = w.document();
    LightProperties* props = w.lightProperties();
    trigger(w, "actionAddSpotLight");
    const Light spot = doc->scene().lights[0];
    QCOMPARE(spot.type, LightType::Spot);
    const auto spotFlux = [](const Light& l) {
        return kLumensPerWatt * luminance(l.intensity) * spotSolidAngle(l.coneAngleDeg, l.falloffStartDeg);
    };
    QVERIFY(near(spotFlux(spot), 1000, 1e-9));
    QCOMPARE(spot.photometric->temperatureK, std::optional<double>(3000.0));
    QVERIFY(props->coneField()->isVisibleTo(props));
    QVERIFY(props->falloffField()->isVisibleTo(props));
    screenshot(*w.propertiesPanel(), "light_panel_spot.png");

    // A wider cone spreads the same lumens: one step, the on-axis intensity lower.
    const int steps = doc->undoStack()->index();
    typeInto(props->coneField(), 45);
    QCOMPARE(doc->undoStack()->index(), steps + 1);
    const Light wide = doc->scene().lights[0];
    QCOMPARE(wide.coneAngleDeg, 45.0);
    QVERIFY(near(spotFlux(wide), 1000, 1e-9));
    QVERIFY(wide.intensity.x < 0.8 * spot.intensity.x);
    trigger(w, "actionUndo");
    QCOMPARE(doc->scene().lights[0], spot);
}

void TestLightPanel::sunInLux() {
    Window win(cornellPath());
    QVERIFY(win.exposed);
    MainWindow& w = win.w;
    Document* doc = w.document();
    LightProperties* props = w.lightProperties();
    trigger(w, "actionAddDirectionalLight");
    QCOMPARE(doc->scene().lights[0].type, LightType::Directional);
    QVERIFY(props->illuminanceField()->isVisibleTo(props));
    QVERIFY(!props->outputField()->isVisibleTo(props));
    QVERIFY(!props->colourField()->modeField()->isVisibleTo(props));  // no temperature key for a sun
    QVERIFY(near(props->illuminanceField()->value(), 2 * kLumensPerWatt, 1e-3));
    screenshot(*w.propertiesPanel(), "light_panel_sun.png");
    const int steps = doc->undoStack()->index();
    typeInto(props->illuminanceField(), 20000);
    QCOMPARE(doc->undoStack()->index(), steps + 1);
    QVERIFY(near(kLumensPerWatt * luminance(doc->scene().lights[0].irradiance), 20000, 1e-9));
}

void TestLightPanel::luminaireShowsItsDistribution() {
    Window win(QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/luminaire.json"));
    QVERIFY(win.exposed);
    MainWindow& w = win.w;
    Document* doc = w.document();
    LightProperties* props = w.lightProperties();
    int washer = -1;
    for (size_t i = 0; i < doc->scene().lights.size(); ++i)
        if (doc->scene().lights[i].name == "washer") washer = int(i);
    QVERIFY(washer >= 0);
    w.outliner()->select(Outliner::Kind::Light, washer);
    QCOMPARE(props->light(), washer);
    LuminairePolarPlot* plot = props->polarPlot();
    QVERIFY(plot->isVisibleTo(props));
    QVERIFY(!props->outputField()->isVisibleTo(props));
    QVERIFY(!props->advancedToggle()->isVisibleTo(props));
    screenshot(*w.propertiesPanel(), "light_panel_luminaire.png");

    // The peak label is the distribution's largest candela as the scene uses it (scaled to the
    // luminaire's 1000 lm), and the same per 1000 lm.
    const Light& l = doc->scene().lights[size_t(washer)];
    const GoniometricDistribution& d = *l.luminaire->distribution;
    const double peak = d.maxIntensity() * 1000.0 / d.integratedFlux();
    QVERIFY(near(plot->peakCandela(), peak, 1e-9));
    QCOMPARE(plot->peakLabel()->text(),
             QString("Peak %1 cd (%2 cd/klm)").arg(peak, 0, 'f', 0).arg(peak * 1000 / luminaireFlux(l), 0, 'f', 0));
    QVERIFY(plot->peakLabel()->isVisibleTo(props));

    // Drawn: the C0-C180 curve (blue) and the C90-C270 curve (red) of a light that shines down,
    // so their pixels lie in the lower half, below the luminaire at the centre.
    const QImage image = plot->canvas()->grab().toImage();
    QVERIFY(image.width() >= 150 && image.height() >= 150);
    int blueLow = 0, blueHigh = 0, redLow = 0, redHigh = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            // Inside the rings only: the legend's samples of the two pens sit in a corner.
            const double cx = x - image.width() / 2.0, cy = y - image.height() / 2.0;
            if (std::hypot(cx, cy) > 0.4 * std::min(image.width(), image.height())) continue;
            const QColor c = image.pixelColor(x, y);
            const bool lower = y > image.height() / 2;
            if (c.blue() > c.red() + 80 && c.blue() > c.green() + 40) (lower ? blueLow : blueHigh)++;
            if (c.red() > c.blue() + 80 && c.red() > c.green() + 80) (lower ? redLow : redHigh)++;
        }
    QVERIFY2(blueLow > 100 && blueLow > 4 * blueHigh && redLow > 50 && redLow > 4 * redHigh,
             qPrintable(QString("blue %1 low %2 high, red %3 low %4 high").arg(blueLow).arg(blueHigh).arg(redLow).arg(redHigh)));

    // A colour temperature: one step, kept in the file, the flux and the plot unchanged.
    QVERIFY(props->colourField()->usesTemperature());
    QCOMPARE(props->colourField()->temperatureField()->value(), 4000.0);
    const Light before = l;
    const int steps = doc->undoStack()->index();
    typeInto(props->colourField()->temperatureField(), 2700);
    QCOMPARE(doc->undoStack()->index(), steps + 1);
    QCOMPARE(doc->scene().lights[size_t(washer)].luminaire->temperatureK, std::optional<double>(2700.0));
    QVERIFY(near(luminaireFlux(doc->scene().lights[size_t(washer)]), 1000, 1e-9));
    QVERIFY(saveSceneToString(doc->scene()).find(R"("lumens": 1000, "temperature": 2700)") != std::string::npos);
    QVERIFY(near(plot->peakCandela(), peak, 1e-9));
    trigger(w, "actionUndo");
    QCOMPARE(doc->scene().lights[size_t(washer)], before);
}

QTEST_MAIN(TestLightPanel)
#include "test_light_panel.moc"
