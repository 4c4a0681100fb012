#include "ui/document/document.h"

namespace lucerna {

Document::Document(Scene scene, std::string path, QObject* parent)
    : QObject(parent), scene_(std::make_shared<const Scene>(std::move(scene))), path_(std::move(path)) {}

void Document::setPath(std::string path) {
    path_ = std::move(path);
    emit pathChanged();
}

void Document::publish(std::shared_ptr<Scene> copy) {
    scene_ = std::move(copy);
    emit changed(++version_);
}

void Document::modify(const std::function<void(Scene&)>& edit) {
    auto copy = std::make_shared<Scene>(*scene_);
    edit(*copy);
    publish(std::move(copy));
}

void Document::reset(Scene scene) {
    undo_.clear();
    scene_ = std::make_shared<const Scene>(std::move(scene));
    undo_.setClean();
    emit replaced();
    emit changed(++version_);
    emit structureChanged();
    emit cameraChanged();
    emit daylightChanged();
}

void Document::setLight(int index, Light light) {
    const Light& old = scene_->lights.at(size_t(index));
    const bool renamed = old.name != light.name || old.group != light.group;
    auto copy = std::make_shared<Scene>(*scene_);
    copy->lights[size_t(index)] = std::move(light);
    publish(std::move(copy));
    emit lightChanged(index);
    if (renamed) emit structureChanged();
}

void Document::setLights(const std::vector<int>& indices, const std::vector<Light>& lights) {
    bool renamed = false;
    auto copy = std::make_shared<Scene>(*scene_);
    for (size_t k = 0; k < indices.size() && k < lights.size(); ++k) {
        Light& l = copy->lights.at(size_t(indices[k]));
        renamed = renamed || l.name != lights[k].name || l.group != lights[k].group;
        l = lights[k];
    }
    publish(std::move(copy));
    for (int i : indices) emit lightChanged(i);
    if (renamed) emit structureChanged();
}

void Document::replaceLights(std::vector<Light> lights) {
    auto copy = std::make_shared<Scene>(*scene_);
    copy->lights = std::move(lights);
    publish(std::move(copy));
    emit structureChanged();
}

void Document::insertLight(int index, Light light) {
    auto copy = std::make_shared<Scene>(*scene_);
    copy->lights.insert(copy->lights.begin() + index, std::move(light));
    publish(std::move(copy));
    emit structureChanged();
}

void Document::removeLight(int index) {
    auto copy = std::make_shared<Scene>(*scene_);
    copy->lights.erase(copy->lights.begin() + index);
    publish(std::move(copy));
    emit structureChanged();
}

void Document::setMaterial(int index, Material material) {
    // The outliner shows each material's type.
    const Material& old = scene_->materials.at(size_t(index));
    const bool renamed = old.name != material.name || old.type != material.type;
    auto copy = std::make_shared<Scene>(*scene_);
    copy->materials[size_t(index)] = std::move(material);
    publish(std::move(copy));
    if (renamed) emit structureChanged();
}

void Document::insertMaterial(int index, Material material) {
    auto copy = std::make_shared<Scene>(*scene_);
    copy->materials.insert(copy->materials.begin() + index, std::move(material));
    publish(std::move(copy));
    emit structureChanged();
}

void Document::removeMaterial(int index) {
    auto copy = std::make_shared<Scene>(*scene_);
    copy->materials.erase(copy->materials.begin() + index);
    publish(std::move(copy));
    emit structureChanged();
}

void Document::setObject(int index, Object object) {
    // The outliner shows each object's material.
    const Object& old = scene_->objects.at(size_t(index));
    const bool renamed = old.name != object.name || old.material != object.material;
    auto copy = std::make_shared<Scene>(*scene_);
    copy->objects[size_t(index)] = std::move(object);
    publish(std::move(copy));
    if (renamed) emit structureChanged();
}

void Document::insertObject(int index, Object object) {
    auto copy = std::make_shared<Scene>(*scene_);
    copy->objects.insert(copy->objects.begin() + index, std::move(object));
    publish(std::move(copy));
    emit structureChanged();
}

void Document::removeObject(int index) {
    auto copy = std::make_shared<Scene>(*scene_);
    copy->objects.erase(copy->objects.begin() + index);
    publish(std::move(copy));
    emit structureChanged();
}

void Document::setCamera(const Camera& camera) {
    auto copy = std::make_shared<Scene>(*scene_);
    copy->camera = camera;
    publish(std::move(copy));
    emit cameraChanged();
}

void Document::setSite(std::optional<Site> site) {
    auto copy = std::make_shared<Scene>(*scene_);
    copy->site = std::move(site);
    publish(std::move(copy));
    emit daylightChanged();
}

void Document::setSky(std::optional<Sky> sky) {
    auto copy = std::make_shared<Scene>(*scene_);
    copy->sky = std::move(sky);
    publish(std::move(copy));
    emit daylightChanged();
}

bool Document::nameInUse(const std::string& name) const {
    for (const Object& o : scene_->objects)
        if (o.name == name) return true;
    for (const Light& l : scene_->lights)
        if (l.name == name) return true;
    return false;
}

std::string Document::uniqueName(const std::string& base) const {
    if (!nameInUse(base)) return base;
    for (int i = 2;; ++i) {
        std::string candidate = base + "-" + std::to_string(i);
        if (!nameInUse(candidate)) return candidate;
    }
}

}  // namespace lucerna
