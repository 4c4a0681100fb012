#pragma once
// Undo commands on the scene's lights: add (also duplicate and place-by-click), delete, and edit
// (move, aim, rename, colour, power, cone). Consecutive edits of one light with the same merge
// key fold into one command, so a gizmo drag or a slider drag is a single undo step.

#include "ui/document/document.h"

#include <QUndoCommand>

namespace lucerna {

class AddLightCommand : public QUndoCommand {
public:
    AddLightCommand(Document* doc, int index, Light light, const QString& text);
    void redo() override;
    void undo() override;

private:
    Document* doc_;
    int index_;
    Light light_;
};

class DeleteLightCommand : public QUndoCommand {
public:
    DeleteLightCommand(Document* doc, int index);
    void redo() override;
    void undo() override;

private:
    Document* doc_;
    int index_;
    Light light_;
};

class EditLightCommand : public QUndoCommand {
public:
    // mergeKey 0: never merges. Otherwise merges into the previous edit of the same light with
    // the same key (one key per drag or per field).
    EditLightCommand(Document* doc, int index, Light after, int mergeKey, const QString& text);
    void redo() override;
    void undo() override;
    int id() const override { return 1001; }
    bool mergeWith(const QUndoCommand* other) override;

private:
    Document* doc_;
    int index_;
    Light before_, after_;
    int mergeKey_;
};

// A new light of a type (SPEC.md types) above the middle of the scene: a point or spot light of
// 1000 lm at 3000 K, a sun of 2 W/m² (about 1370 lx).
Light defaultLight(const Scene& scene, LightType type, const std::string& name);
QString lightTypeName(LightType type);

}  // namespace lucerna
