#include "ui/window/edit_actions.h"

#include "core/read_crash_hook.h"
#include "ui/commands/light_commands.h"
#include "ui/commands/light_group_commands.h"
#include "ui/commands/object_commands.h"
#include "ui/commands/task_area_commands.h"
#include "ui/io/file_dialogs.h"
#include "ui/io/luminaire_import.h"
#include "ui/scene_panels/arrangement_dialog.h"
#include "ui/scene_panels/project_dialog.h"
#include "ui/scene_panels/outliner.h"
#include "ui/window/file_actions.h"
#include "ui/window/room_actions.h"
#include "ui/window/menu_entry.h"
#include "ui/window/window_messages.h"

#include <QDialog>
#include <QElapsedTimer>
#include <QMainWindow>
#include <QMenu>

namespace lucerna {

EditActions::EditActions(Document& doc, FileActions& files, Outliner& outliner, FileDialogs& dialogs,
                         WindowMessages& messages)
    : doc_(doc), files_(files), outliner_(outliner), dialogs_(dialogs), messages_(messages) {}

void EditActions::addTo(QMenu* menu) {
    QAction* undo = doc_.undoStack()->createUndoAction(messages_.window(), tr("&Undo"));
    undo->setObjectName("actionUndo");
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = doc_.undoStack()->createRedoAction(messages_.window(), tr("&Redo"));
    redo->setObjectName("actionRedo");
    // The platform's keys (Ctrl+Shift+Z on Linux) and Ctrl+Y, which designers bring from other
    // programs.
    QList<QKeySequence> redoKeys = QKeySequence::keyBindings(QKeySequence::Redo);
    if (const QKeySequence ctrlY(Qt::CTRL | Qt::Key_Y); !redoKeys.contains(ctrlY)) redoKeys.append(ctrlY);
    redo->setShortcuts(redoKeys);
    menu->addAction(undo);
    menu->addAction(redo);
    menu->addSeparator();
    if (rooms_) rooms_->addTo(menu);
    addMenuEntry(menu, tr("Add &Point Light"), "actionAddPointLight", QKeySequence(tr("Ctrl+Alt+P")), this,
                 [this] { addLight(LightType::Point); });
    addMenuEntry(menu, tr("Add S&pot Light"), "actionAddSpotLight", QKeySequence(tr("Ctrl+Alt+S")), this,
                 [this] { addLight(LightType::Spot); });
    addMenuEntry(menu, tr("Add &Directional Light"), "actionAddDirectionalLight", QKeySequence(tr("Ctrl+Alt+D")), this,
                 [this] { addLight(LightType::Directional); });
    addMenuEntry(menu, tr("Add &Luminaire..."), "actionAddLuminaire", QKeySequence(tr("Ctrl+Alt+L")), this, [this] {
        const QString path =
            dialogs_.open(tr("Add a luminaire"), tr("Photometric files (*.ies *.IES *.ldt *.LDT);;All files (*)"));
        if (!path.isEmpty()) messages_.warnUnless(addLuminaireFile(path), tr("Add luminaire"));
    });
    addMenuEntry(menu, tr("Arrange Li&ghts..."), "actionArrangeLights", QKeySequence(tr("Ctrl+Alt+F")), this,
                 [this] { arrangeLights(); });
    addMenuEntry(menu, tr("&Energy..."), "actionEnergy", QKeySequence(), this, [this] { showEnergy(); });
    addMenuEntry(menu, tr("D&uplicate"), "actionDuplicate", QKeySequence(tr("Ctrl+D")), this,
                 [this] { duplicateSelection(); });
    addMenuEntry(menu, tr("&Delete"), "actionDelete", QKeySequence::Delete, this, [this] { deleteSelection(); });
}

int EditActions::selectedLight() const {
    const Outliner::Selection s = outliner_.selection();
    return s.kind == Outliner::Kind::Light ? s.index : -1;
}

void EditActions::addLight(LightType type) {
    const char* base = type == LightType::Point ? "point" : type == LightType::Spot ? "spot" : "sun";
    append(defaultLight(doc_.scene(), type, doc_.uniqueName(base)));
}

bool EditActions::addLuminaireFile(const QString& path) {
    files_.secureUnsavedWork();
    Light light;
    const auto read = [&] {
        crashHereWhenTesting("luminaire");
        light = luminaireFromFile(doc_, path);
    };
    if (!messages_.attempt(read, tr("Could not add %1").arg(path))) return false;
    append(std::move(light));
    return true;
}

void EditActions::append(Light light) {
    const int index = int(doc_.scene().lights.size());
    const QString text = tr("Add %1").arg(QString::fromStdString(light.name));
    doc_.undoStack()->push(new AddLightCommand(&doc_, index, std::move(light), text));
    outliner_.select(Outliner::Kind::Light, index);
}

void EditActions::duplicateSelection() {
    const int index = selectedLight();
    if (index < 0) return;
    Light light = doc_.scene().lights[size_t(index)];
    if (light.type == LightType::Sun) {
        messages_.fail(tr("A scene has one sun at most: it is not duplicated."));
        return;
    }
    light.name = doc_.uniqueName(light.name);
    const QString text = tr("Duplicate %1").arg(QString::fromStdString(light.name));
    doc_.undoStack()->push(new AddLightCommand(&doc_, index + 1, std::move(light), text));
    outliner_.select(Outliner::Kind::Light, index + 1);
}

void EditActions::arrangeLights(const std::optional<std::array<double, 4>>& rectangle) {
    ArrangementDialog dialog(doc_, selectedLight(), messages_.window());
    dialog.setFileQuestion([this] {
        return dialogs_.open(tr("Luminaire of the field"), tr("Photometric files (*.ies *.IES *.ldt *.LDT);;All files (*)"));
    });
    if (rectangle) dialog.setRectangle((*rectangle)[0], (*rectangle)[1], (*rectangle)[2], (*rectangle)[3]);
    if (dialog.exec() != QDialog::Accepted) return;
    // prototype() reads the luminaire file, which the dialog checked a moment ago.
    messages_.attempt(
        [&] { arrangeField(dialog.arrangement(), dialog.prototype(), QString::fromStdString(dialog.group())); });
}

bool EditActions::arrangeField(const FieldArrangement& field, const Light& prototype, const QString& group) {
    QElapsedTimer clock;
    clock.start();
    int count = 0;
    if (!messages_.attempt([&] { count = lucerna::arrangeField(doc_, field, prototype, group.toStdString()); },
                           tr("No field arranged")))
        return false;
    outliner_.selectGroup(group.toStdString());
    messages_.show(tr("Arranged %1 lights in group %2 (%3 ms)").arg(count).arg(group).arg(clock.elapsed()), 8000);
    return true;
}

void EditActions::showEnergy() {
    ProjectDialog dialog(&doc_, messages_.window(), ProjectDialog::Tab::Energy);
    dialog.exec();
}

void EditActions::deleteSelection() {
    if (rooms_ && rooms_->deleteSelection()) return;  // a room or an opening
    const Outliner::Selection s = outliner_.selection();
    if (s.kind == Outliner::Kind::Group || s.kind == Outliner::Kind::Lights) {
        std::vector<char> gone(doc_.scene().lights.size(), 0);
        for (int i : s.lights) gone[size_t(i)] = 1;
        std::vector<Light> kept;
        for (size_t i = 0; i < gone.size(); ++i)
            if (!gone[i]) kept.push_back(doc_.scene().lights[i]);
        const QString text = s.kind == Outliner::Kind::Group ? tr("Delete group %1").arg(QString::fromStdString(s.group))
                                                             : tr("Delete %1 lights").arg(s.lights.size());
        doc_.undoStack()->push(new ReplaceLightsCommand(&doc_, std::move(kept), text));
    } else if (s.kind == Outliner::Kind::Light)
        doc_.undoStack()->push(new DeleteLightCommand(&doc_, s.index));
    else if (s.kind == Outliner::Kind::Object)
        doc_.undoStack()->push(new DeleteObjectCommand(&doc_, s.index));
    else if (s.kind == Outliner::Kind::TaskArea)
        doc_.undoStack()->push(TaskAreaListCommand::remove(&doc_, s.index));
}

}  // namespace lucerna
