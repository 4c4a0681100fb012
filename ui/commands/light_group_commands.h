#pragma once
// Undo commands on many lights at once (issue 19): an edit of a group or of a multi-selection of
// lights, and a change of the list of lights (a field of luminaires added, a group deleted). Each
// is one undo step however many lights it touches, and applies as one copy of the scene.

#include "ui/document/document.h"

#include <QUndoCommand>

#include <vector>

namespace lucerna {

class EditLightsCommand : public QUndoCommand {
public:
    // The lights at `indices` become `after` (one light per index). mergeKey 0: never merges;
    // otherwise merges into the previous edit of the same lights with the same key (a field's
    // arrow steps).
    EditLightsCommand(Document* doc, std::vector<int> indices, std::vector<Light> after, int mergeKey, const QString& text);
    void redo() override;
    void undo() override;
    int id() const override { return 1005; }
    bool mergeWith(const QUndoCommand* other) override;

private:
    Document* doc_;
    std::vector<int> indices_;
    std::vector<Light> before_, after_;
    int mergeKey_;
};

// The scene's list of lights replaced by `after` (kept whole before and after: a field of 10,000
// luminaires is a few megabytes).
class ReplaceLightsCommand : public QUndoCommand {
public:
    ReplaceLightsCommand(Document* doc, std::vector<Light> after, const QString& text);
    void redo() override;
    void undo() override;

private:
    Document* doc_;
    std::vector<Light> before_, after_;
};

// The indices of the lights in `group`, in file order.
std::vector<int> groupMembers(const Scene& scene, const std::string& group);

}  // namespace lucerna
