// The light panel on a luminaire (issue 7): the bundled luminaire scene opens, the panel shows the
// file, the rotation and the flux in place of the intensity, and edits of the rotation and the
// flux are undoable document edits that the scene file keeps.

#include "core/photometry/luminaire.h"
#include "core/scene/aim_angles.h"
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
    void aimAsTiltAndAzimuth();
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

// The aim as a tilt from straight down and a bearing from north (core/scene/aim_angles.h), each
// edit one undo step "Aim NAME" as the direction's fields made.
void TestLuminairePanel::aimAsTiltAndAzimuth() {
    const std::string path = std::string(LUCERNA_RESOURCE_DIR) + "/scenes/luminaire.json";
    Document doc(loadScene(path), path);
    LightProperties panel(&doc);
    panel.show();
    const int washer = 2;
    QCOMPARE(doc.scene().lights[washer].name, std::string("washer"));
    panel.setLight(washer);
    QVERIFY(panel.tiltField()->isVisibleTo(&panel));
    QVERIFY(panel.azimuthField()->isVisibleTo(&panel));
    QCOMPARE(panel.tiltField()->value(), 0.0);  // straight down
    QUndoStack* undo = doc.undoStack();
    const auto direction = [&] { return doc.scene().lights[washer].direction; };
    const auto near = [](const V3d& a, const V3d& b) { return (a - b).length() < 1e-12; };

    // Straight down has no bearing to turn: no edit, and the field keeps the bearing for the tilt.
    panel.azimuthField()->setValue(90);
    QCOMPARE(undo->count(), 0);
    QCOMPARE(panel.azimuthField()->value(), 90.0);
    // Tilted 30 degrees that way: toward the east, +x (no site: north is -z).
    panel.tiltField()->setValue(30);
    QCOMPARE(undo->count(), 1);
    QCOMPARE(undo->text(0), QString("Aim washer"));
    const V3d east(0.5, -std::sqrt(3.0) / 2, 0);
    QVERIFY2(near(direction(), east), qPrintable(QString("%1 %2 %3").arg(direction().x).arg(direction().y).arg(direction().z)));
    // The arrows' steps of one field merge into that step until its editing finishes.
    panel.tiltField()->setValue(31);
    QCOMPARE(undo->count(), 1);
    panel.tiltField()->setValue(30);
    emit panel.tiltField()->editingFinished();
    QVERIFY(near(direction(), east));
    // Turned to the south (+z): the tilt stays exactly 30 degrees.
    panel.azimuthField()->setValue(180);
    QCOMPARE(undo->count(), 2);
    QVERIFY(near(direction(), V3d(0, -std::sqrt(3.0) / 2, 0.5)));
    QVERIFY(std::abs(aimAngles(direction(), V3d(0, 0, -1)).tiltDeg - 30) < 1e-12);
    const std::string saved = saveSceneToString(doc.scene());
    QVERIFY(saved.find(R"("name": "washer")") != std::string::npos);
    // Undone step by step; the fields follow.
    undo->undo();
    QVERIFY(near(direction(), east));
    QCOMPARE(panel.azimuthField()->value(), 90.0);
    QCOMPARE(panel.tiltField()->value(), 30.0);
    undo->undo();
    QCOMPARE(direction(), V3d(0, -1, 0));
    QCOMPARE(panel.tiltField()->value(), 0.0);
}

QTEST_MAIN(TestLuminairePanel)
#include "test_luminaire_panel.moc"
