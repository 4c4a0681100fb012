#pragma once
// The editable scene (DESIGN.md, "The flow of data"). Every change goes through a setter that
// replaces the scene by an edited copy, bumps the version and emits changed(); backends only ever
// hold the immutable snapshots it hands out. Mesh data is shared between copies, so a copy per
// edit costs little.

#include "core/scene.h"

#include <QObject>

#include <functional>

namespace lucerna {

class Document : public QObject {
    Q_OBJECT
public:
    explicit Document(Scene scene, std::string path = {}, QObject* parent = nullptr);

    SceneSnapshot snapshot() const { return scene_; }
    const Scene& scene() const { return *scene_; }
    uint64_t version() const { return version_; }
    const std::string& path() const { return path_; }
    void setPath(std::string path);

    // Applies edit to a copy of the scene and publishes the copy. The edit must leave the scene
    // valid (meshes resolved); the undo commands of the UI are built on this.
    void modify(const std::function<void(Scene&)>& edit);
    // Replaces the whole scene (open, revert).
    void reset(Scene scene);

signals:
    void changed(uint64_t version);
    void pathChanged();

private:
    SceneSnapshot scene_;
    uint64_t version_ = 1;
    std::string path_;
};

}  // namespace lucerna
