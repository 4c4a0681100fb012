#include "ui/commands/import_commands.h"

namespace lucerna {

ImportModelCommand::ImportModelCommand(Document* doc, std::vector<Material> materials, std::vector<Object> objects,
                                       std::vector<Light> lights, const QString& text)
    : QUndoCommand(text), doc_(doc), materials_(std::move(materials)), objects_(std::move(objects)),
      lights_(std::move(lights)), materialsBefore_(doc->scene().materials.size()),
      objectsBefore_(doc->scene().objects.size()), lightsBefore_(doc->scene().lights.size()) {}

// One published scene per step rather than one per item: a model may bring hundreds of objects,
// and each publication makes the preview and the converging render start over. The document has
// no setter for a batch, so the structure signal the per-item setters send is sent here.
void ImportModelCommand::redo() {
    doc_->modify([this](Scene& s) {
        s.materials.insert(s.materials.end(), materials_.begin(), materials_.end());
        s.objects.insert(s.objects.end(), objects_.begin(), objects_.end());
        s.lights.insert(s.lights.end(), lights_.begin(), lights_.end());
    });
    emit doc_->structureChanged();
}

void ImportModelCommand::undo() {
    doc_->modify([this](Scene& s) {
        s.lights.erase(s.lights.begin() + std::ptrdiff_t(lightsBefore_), s.lights.end());
        s.objects.erase(s.objects.begin() + std::ptrdiff_t(objectsBefore_), s.objects.end());
        s.materials.erase(s.materials.begin() + std::ptrdiff_t(materialsBefore_), s.materials.end());
    });
    emit doc_->structureChanged();
}

}  // namespace lucerna
