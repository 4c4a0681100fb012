#include "ui/commands/light_group_commands.h"

namespace lucerna {

EditLightsCommand::EditLightsCommand(Document* doc, std::vector<int> indices, std::vector<Light> after, int mergeKey,
                                     const QString& text)
    : QUndoCommand(text), doc_(doc), indices_(std::move(indices)), after_(std::move(after)), mergeKey_(mergeKey) {
    before_.reserve(indices_.size());
    for (int i : indices_) before_.push_back(doc->scene().lights.at(size_t(i)));
}

void EditLightsCommand::redo() { doc_->setLights(indices_, after_); }
void EditLightsCommand::undo() { doc_->setLights(indices_, before_); }

bool EditLightsCommand::mergeWith(const QUndoCommand* other) {
    const auto* o = static_cast<const EditLightsCommand*>(other);
    if (mergeKey_ == 0 || o->mergeKey_ != mergeKey_ || o->indices_ != indices_) return false;
    after_ = o->after_;
    return true;
}

ReplaceLightsCommand::ReplaceLightsCommand(Document* doc, std::vector<Light> after, const QString& text)
    : QUndoCommand(text), doc_(doc), before_(doc->scene().lights), after_(std::move(after)) {}

void ReplaceLightsCommand::redo() { doc_->replaceLights(after_); }
void ReplaceLightsCommand::undo() { doc_->replaceLights(before_); }

std::vector<int> groupMembers(const Scene& scene, const std::string& group) {
    std::vector<int> members;
    if (group.empty()) return members;
    for (size_t i = 0; i < scene.lights.size(); ++i)
        if (scene.lights[i].group == group) members.push_back(int(i));
    return members;
}

}  // namespace lucerna
