#pragma once
// The Edit menu: Undo and Redo, the rooms' entries (ui/window/room_actions.h), adding a point, spot or
// directional light or a luminaire (an IES or EULUMDAT file), arranging a field of lights (ui/scene_panels/arrangement_dialog.h), and
// duplicating and deleting what the outliner selects. Every edit is one undo step.

#include "ui/scene_panels/light_arrangement.h"

#include <QObject>
#include <QString>

#include <array>
#include <optional>

class QMenu;

namespace lucerna {

class Document;
class FileDialogs;
class FileActions;
class Outliner;
class RoomActions;
class WindowMessages;

class EditActions : public QObject {
    Q_OBJECT
public:
    // `outliner` holds the selection the actions work on, and selects what they add; `files`
    // autosaves unsaved changes before a luminaire file is read.
    EditActions(Document& doc, FileActions& files, Outliner& outliner, FileDialogs& dialogs, WindowMessages& messages);

    // Adds Undo, Redo and the actions below to `menu`.
    void addTo(QMenu* menu);

    // The operations behind the menu, without dialogs.
    // The rooms' actions: their menu entries after Undo and Redo, Delete on a room or opening.
    void setRoomActions(RoomActions* rooms) { rooms_ = rooms; }
    // A light of `type` (point, spot or directional) above the middle of the scene, selected.
    void addLight(LightType type);
    // Adds the IES or EULUMDAT file's luminaire and selects it; false (and a status message)
    // when the file cannot be read. Unsaved changes are autosaved before the file is read.
    bool addLuminaireFile(const QString& path);
    // The dialog, over the rectangle drawn in the plan when given (x0, z0, x1, z1), else the
    // scene's plan.
    void arrangeLights(const std::optional<std::array<double, 4>>& rectangle = std::nullopt);
    // The field added and its group selected; false with a one-line reason in the status bar
    // (and WindowMessages::lastError) when it makes no field.
    bool arrangeField(const FieldArrangement& field, const Light& prototype, const QString& group);
    // The selected light, after it (not a sun: a scene has one at most).
    void duplicateSelection();
    // The selected light, object, group, lights or task area.
    void deleteSelection();
    // The selected light's index, or -1.
    int selectedLight() const;
    // Edit > Energy...: File > Project Settings (ui/scene_panels/project_dialog.h) opened on its
    // Energy tab, where a designer looking in the Edit menu finds it too.
    void showEnergy();

private:
    // Adds `light` after the others, one undo step, and selects it.
    void append(Light light);

    Document& doc_;
    FileActions& files_;
    Outliner& outliner_;
    FileDialogs& dialogs_;
    WindowMessages& messages_;
    RoomActions* rooms_ = nullptr;
};

}  // namespace lucerna
