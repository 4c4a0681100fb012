#include "core/document.h"

namespace lucerna {

Document::Document(Scene scene, std::string path, QObject* parent)
    : QObject(parent), scene_(std::make_shared<const Scene>(std::move(scene))), path_(std::move(path)) {}

void Document::setPath(std::string path) {
    path_ = std::move(path);
    emit pathChanged();
}

void Document::modify(const std::function<void(Scene&)>& edit) {
    auto copy = std::make_shared<Scene>(*scene_);
    edit(*copy);
    scene_ = std::move(copy);
    emit changed(++version_);
}

void Document::reset(Scene scene) {
    scene_ = std::make_shared<const Scene>(std::move(scene));
    emit changed(++version_);
}

}  // namespace lucerna
