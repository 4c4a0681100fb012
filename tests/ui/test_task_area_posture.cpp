// A task area's posture in the window (README, "Task areas"): chosen Standing in Edit > Add Task
// Area's dialog (the new area one undo step, standing), shown on its properties page, changed
// back to Seated there (one step), undone and redone with the page following, and written to the
// file only when standing. Screenshot of the page.

#include "core/scene/scene_io.h"
#include "ui/document/document.h"
#include "ui/properties/properties_panel.h"
#include "ui/properties/task_area_fields.h"
#include "ui/properties/task_area_properties.h"
#include "ui/scene_panels/task_area_dialog.h"
#include "ui/window/main_window.h"
#include "window_test_helpers.h"

#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QMessageBox>
#include <QPushButton>
#include <QTimer>
#include <QUndoStack>
#include <QtTest>

using namespace lucerna;
using namespace lucerna::test;

namespace {
// Chosen as a user chooses: the item, then the combo's activated signal (as a click sends it).
void choose(QComboBox* box, int index) {
    box->setCurrentIndex(index);
    emit box->activated(index);
}
}  // namespace

class TestTaskAreaPosture : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { useTestSettings("test_task_area_posture"); }

    void chosenInTheDialogAndOnThePage() {
        MainWindow w(cornellPath());
        w.resize(1400, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        trigger(w, "actionNew");
        Document* doc = w.document();
        QUndoStack* undo = doc->undoStack();
        const int start = undo->count();

        bool filled = false;
        QTimer::singleShot(0, [&] {
            auto* dialog = qobject_cast<TaskAreaDialog*>(QApplication::activeModalWidget());
            QVERIFY(dialog);
            QComboBox* posture = dialog->fields()->postureField();
            QCOMPARE(posture->currentIndex(), 0);  // seated unless chosen
            QCOMPARE(posture->currentText(), QString("Seated"));
            choose(posture, posture->findText("Standing"));
            filled = true;
            QTest::mouseClick(dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok), Qt::LeftButton);
        });
        trigger(w, "actionAddTaskArea");
        QVERIFY(filled);
        QCOMPARE(doc->scene().taskAreas.size(), size_t(1));
        QVERIFY(doc->scene().taskAreas[0].standing);
        QCOMPARE(undo->count(), start + 1);
        QVERIFY(saveSceneToString(doc->scene()).find(R"("posture": "standing")") != std::string::npos);

        // The page of the new (selected) area shows it; Seated chosen there is one step.
        TaskAreaProperties* page = w.propertiesPanel()->taskAreaProperties();
        QCOMPARE(w.propertiesPanel()->currentWidget(), static_cast<QWidget*>(page));
        QComboBox* posture = page->fields()->postureField();
        QCOMPARE(posture->currentIndex(), 1);
        QTest::qWait(200);  // the dock laid out
        page->grab().save("task_area_page_posture.png");
        choose(posture, 0);
        QVERIFY(!doc->scene().taskAreas[0].standing);
        QCOMPARE(undo->count(), start + 2);
        QVERIFY(saveSceneToString(doc->scene()).find("posture") == std::string::npos);
        choose(posture, 0);  // the same again: no step
        QCOMPARE(undo->count(), start + 2);

        undo->undo();
        QVERIFY(doc->scene().taskAreas[0].standing);
        QCOMPARE(posture->currentIndex(), 1);
        undo->redo();
        QVERIFY(!doc->scene().taskAreas[0].standing);
        QCOMPARE(posture->currentIndex(), 0);
        w.setSaveQuestion([] { return QMessageBox::Discard; });
    }
};

QTEST_MAIN(TestTaskAreaPosture)
#include "test_task_area_posture.moc"
