// The light panel on a luminaire (issue 7): the bundled luminaire scene opens, the panel shows the
// file, the rotation and the flux in place of the intensity, and edits of the rotation and the
// flux are undoable document edits that the scene file keeps.

#include "core/photometry/luminaire.h"
#include "core/scene/scene_io.h"
#include "ui/document/document.h"
#include "ui/properties/light_properties.h"

#include <QDoubleSpinBox>
#include <QLabel>
#include <QtTest>

using namespace lucerna;

class TestLuminairePanel : public QObject {
    Q_OBJECT
private slots:
    void showsAndEditsALuminaire();
};

void TestLuminairePanel::showsAndEditsALuminaire() {
    const std::string path = std::string(LUCERNA_RESOURCE_DIR) + "/scenes/luminaire.json";
    Document doc(loadScene(path), path);
    LightProperties panel(&doc);
    panel.show();
    int washer = -1;
    for (size_t i = 0; i < doc.scene().lights.size(); ++i)
        if (doc.scene().lights[i].name == "washer") washer = int(i);
    QVERIFY(washer >= 0);
    panel.setLight(washer);
    QVERIFY(!panel.powerFields()[0]->isVisibleTo(&panel));  // no intensity for a luminaire
    QVERIFY(panel.rotationField()->isVisibleTo(&panel));
    QVERIFY(!panel.coneField()->isVisibleTo(&panel));
    const auto* file = panel.findChild<QLabel*>("luminaireFile");
    QVERIFY(file && file->text().startsWith("luminaires/wallwasher.ldt (wall washer"));
    QCOMPARE(panel.lumensField()->value(), 1000.0);
    QCOMPARE(panel.rotationField()->value(), 0.0);

    panel.rotationField()->setValue(45);
    QCOMPARE(*doc.scene().lights[size_t(washer)].luminaire->rotationDeg, 45.0);
    panel.lumensField()->setValue(1500);
    const Light& l = doc.scene().lights[size_t(washer)];
    QCOMPARE(*l.luminaire->lumens, 1500.0);
    QVERIFY(std::abs(luminaireFlux(l) - 1500) < 1e-6);
    QVERIFY(l.luminaire->distribution);  // the edit keeps the loaded table
    const std::string saved = saveSceneToString(doc.scene());
    QVERIFY(saved.find(R"("rotation": 45, "lumens": 1500)") != std::string::npos);

    doc.undoStack()->undo();
    doc.undoStack()->undo();
    QCOMPARE(*doc.scene().lights[size_t(washer)].luminaire->rotationDeg, 0.0);
    QCOMPARE(*doc.scene().lights[size_t(washer)].luminaire->lumens, 1000.0);
    QCOMPARE(panel.rotationField()->value(), 0.0);
    QCOMPARE(panel.lumensField()->value(), 1000.0);
}

QTEST_MAIN(TestLuminairePanel)
#include "test_luminaire_panel.moc"
