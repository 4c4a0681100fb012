#pragma once
// The editable scene (DESIGN.md, "The flow of data"), in the house style of Tiled: the document
// wraps the scene, owns the undo stack and emits a signal from each setter. Every setter replaces
// the scene by an edited copy, bumps the version and emits changed(); backends only ever hold the
// immutable snapshots it hands out. Mesh data is shared between copies, so a copy per edit costs
// little. The setters are what the undo commands (ui/commands/) call; nothing else in the UI
// edits the scene, so every edit is undoable.

#include "core/scene/scene.h"

#include <QObject>
#include <QUndoStack>

#include <functional>

namespace lucerna {

// What File > Project Settings edits, as one value so that its OK is one undo step: the project's
// details for the report (README, "Reports"), the scene's maintenance factor (README,
// "Maintained values"), the EN 12464-1 edition its task areas are checked against (README,
// "Task areas") and the lighting energy's settings (README, "Energy (LENI; an addition)");
// absent: none (the edition: the default, and no key written; the energy: LENI not computed).
struct ProjectSettings {
    std::optional<ProjectInfo> project;
    std::optional<MaintenanceFactor> maintenance;
    std::optional<StandardEdition> lightingStandard;
    std::optional<EnergySettings> energy;
    bool operator==(const ProjectSettings&) const = default;
};

class Document : public QObject {
    Q_OBJECT
public:
    explicit Document(Scene scene, std::string path = {}, QObject* parent = nullptr);

    SceneSnapshot snapshot() const { return scene_; }
    const Scene& scene() const { return *scene_; }
    uint64_t version() const { return version_; }
    const std::string& path() const { return path_; }
    void setPath(std::string path);

    QUndoStack* undoStack() { return &undo_; }
    // Unsaved changes: the undo stack is away from the state last saved or opened.
    bool isModified() const { return !undo_.isClean(); }
    // After a save: the current state is the saved one.
    void markSaved() { undo_.setClean(); }

    // Applies edit to a copy of the scene and publishes the copy. The edit must leave the scene
    // valid (meshes resolved). Not undoable by itself: commands call it or the setters below.
    void modify(const std::function<void(Scene&)>& edit);
    // Replaces the whole scene (open, revert, recovery) and clears the undo history.
    void reset(Scene scene);

    // Typed getters and setters for the undo commands, which pair them (ui/commands/change_value.h,
    // ui/commands/add_or_delete.h). Indices must be valid (insert: at most the size).
    const Light& light(int index) const { return scene_->lights.at(size_t(index)); }
    const Material& material(int index) const { return scene_->materials.at(size_t(index)); }
    const Object& object(int index) const { return scene_->objects.at(size_t(index)); }
    const TaskArea& taskArea(int index) const { return scene_->taskAreas.at(size_t(index)); }
    const std::vector<Light>& lights() const { return scene_->lights; }
    std::vector<Light> lightsAt(const std::vector<int>& indices) const;
    const Camera& camera() const { return scene_->camera; }
    const std::optional<Site>& site() const { return scene_->site; }
    const std::optional<Sky>& sky() const { return scene_->sky; }
    ProjectSettings projectSettings() const {
        return {scene_->project, scene_->maintenance, scene_->lightingStandard, scene_->energy};
    }
    const std::optional<EnergySettings>& energy() const { return scene_->energy; }

    void setLight(int index, Light light);
    void insertLight(int index, Light light);
    void removeLight(int index);
    // Several lights at once, in one published copy (a group edit, a multi-selection): one undo
    // step of any size costs one copy of the scene. Indices distinct and valid, one light each.
    void setLights(const std::vector<int>& indices, const std::vector<Light>& lights);
    // The whole list of lights (a field of luminaires added, a group deleted).
    void replaceLights(std::vector<Light> lights);
    void setMaterial(int index, Material material);
    void insertMaterial(int index, Material material);
    void removeMaterial(int index);
    // The object must carry its resolved worldMesh (the commands resolve it once, not per redo).
    void setObject(int index, Object object);
    void insertObject(int index, Object object);
    void removeObject(int index);
    // Task areas (README, "Task areas"); names unique among them (taskAreaNameInUse).
    void setTaskArea(int index, TaskArea area);
    void insertTaskArea(int index, TaskArea area);
    void removeTaskArea(int index);
    void setCamera(const Camera& camera);
    // SPEC.md section 5; absent: none. The sun is a light (setLight).
    void setSite(std::optional<Site> site);
    void setSky(std::optional<Sky> sky);
    void setProjectSettings(ProjectSettings settings);
    // The lighting energy's settings (README, "Energy (LENI)"); absent: LENI not computed.
    void setEnergy(std::optional<EnergySettings> energy);

    // A name not used by any object or light (SPEC.md: names are unique across both): base,
    // or base-2, base-3, ...
    std::string uniqueName(const std::string& base) const;
    bool nameInUse(const std::string& name) const;
    // A task area other than `except` (an index, -1: none) is named `name`.
    bool taskAreaNameInUse(const std::string& name, int except = -1) const;

signals:
    void changed(uint64_t version);
    // The whole scene was replaced by reset() (a file opened, a recovery): emitted before
    // changed(), so that views drop what they show of the old scene before the new one arrives.
    void replaced();
    // Finer signals so that views redo only what changed (the preview re-lights one light).
    void lightChanged(int index);
    void cameraChanged();
    // The site or the sky (a sun placed by time moves with its site).
    void daylightChanged();
    // Objects, lights or materials were added or removed, renamed, or lights regrouped: lists
    // must be rebuilt.
    void structureChanged();
    void pathChanged();
    // The project settings (the project's details, the scene's maintenance factor, the EN 12464-1 edition).
    void projectChanged();
    // The energy settings (setEnergy, or setProjectSettings when they changed).
    void energyChanged();

private:
    void publish(std::shared_ptr<Scene> copy);
    // An item inserted into or removed from one of the scene's lists; the structure changed.
    template <class T> void insertInto(std::vector<T> Scene::*list, int index, T item);
    template <class T> void removeFrom(std::vector<T> Scene::*list, int index);
    // An item of one of the scene's lists replaced; `listed`: what the outliner shows of it changed.
    template <class T> void replaceIn(std::vector<T> Scene::*list, int index, T item, bool listed);

    SceneSnapshot scene_;
    uint64_t version_ = 1;
    std::string path_;
    QUndoStack undo_;
};

}  // namespace lucerna
