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

template <class T> void Document::insertInto(std::vector<T> Scene::*list, int index, T item) {
    modify([&](Scene& s) { (s.*list).insert((s.*list).begin() + index, std::move(item)); });
    emit structureChanged();
}

template <class T> void Document::removeFrom(std::vector<T> Scene::*list, int index) {
    modify([&](Scene& s) { (s.*list).erase((s.*list).begin() + index); });
    emit structureChanged();
}

template <class T> void Document::replaceIn(std::vector<T> Scene::*list, int index, T item, bool listed) {
    modify([&](Scene& s) { (s.*list)[size_t(index)] = std::move(item); });
    if (listed) emit structureChanged();
}

std::vector<Light> Document::lightsAt(const std::vector<int>& indices) const {
    std::vector<Light> lights;
    lights.reserve(indices.size());
    for (int i : indices) lights.push_back(light(i));
    return lights;
}

void Document::setLight(int index, Light light) {
    const Light& old = this->light(index);
    const bool renamed = old.name != light.name || old.group != light.group;
    modify([&](Scene& s) { s.lights[size_t(index)] = std::move(light); });
    emit lightChanged(index);
    if (renamed) emit structureChanged();
}

void Document::setLights(const std::vector<int>& indices, const std::vector<Light>& lights) {
    bool renamed = false;
    modify([&](Scene& s) {
        for (size_t k = 0; k < indices.size() && k < lights.size(); ++k) {
            Light& l = s.lights.at(size_t(indices[k]));
            renamed = renamed || l.name != lights[k].name || l.group != lights[k].group;
            l = lights[k];
        }
    });
    for (int i : indices) emit lightChanged(i);
    if (renamed) emit structureChanged();
}

void Document::replaceLights(std::vector<Light> lights) {
    modify([&](Scene& s) { s.lights = std::move(lights); });
    emit structureChanged();
}

void Document::insertLight(int index, Light light) { insertInto(&Scene::lights, index, std::move(light)); }
void Document::removeLight(int index) { removeFrom(&Scene::lights, index); }

void Document::setMaterial(int index, Material material) {
    // The outliner shows each material's type.
    const bool listed = material.name != this->material(index).name || material.type != this->material(index).type;
    replaceIn(&Scene::materials, index, std::move(material), listed);
}

void Document::insertMaterial(int index, Material material) {
    insertInto(&Scene::materials, index, std::move(material));
}
void Document::removeMaterial(int index) { removeFrom(&Scene::materials, index); }

void Document::setObject(int index, Object object) {
    // The outliner shows each object's material.
    const bool listed = object.name != this->object(index).name || object.material != this->object(index).material;
    replaceIn(&Scene::objects, index, std::move(object), listed);
}

void Document::insertObject(int index, Object object) { insertInto(&Scene::objects, index, std::move(object)); }
void Document::removeObject(int index) { removeFrom(&Scene::objects, index); }

void Document::setTaskArea(int index, TaskArea area) {
    // The outliner shows each task area's name and activity.
    const bool listed = area.grid.name != taskArea(index).grid.name || area.activity != taskArea(index).activity;
    replaceIn(&Scene::taskAreas, index, std::move(area), listed);
}

void Document::insertTaskArea(int index, TaskArea area) { insertInto(&Scene::taskAreas, index, std::move(area)); }
void Document::removeTaskArea(int index) { removeFrom(&Scene::taskAreas, index); }

bool Document::taskAreaNameInUse(const std::string& name, int except) const {
    for (size_t i = 0; i < scene_->taskAreas.size(); ++i)
        if (int(i) != except && scene_->taskAreas[i].grid.name == name) return true;
    return false;
}

void Document::setCamera(const Camera& camera) {
    modify([&](Scene& s) { s.camera = camera; });
    emit cameraChanged();
}

void Document::setSite(std::optional<Site> site) {
    modify([&](Scene& s) { s.site = std::move(site); });
    emit daylightChanged();
}

void Document::setSky(std::optional<Sky> sky) {
    modify([&](Scene& s) { s.sky = std::move(sky); });
    emit daylightChanged();
}

void Document::setProjectSettings(ProjectSettings settings) {
    const bool energy = settings.energy != scene_->energy;
    modify([&](Scene& s) {
        s.project = std::move(settings.project);
        s.maintenance = std::move(settings.maintenance);
        s.lightingStandard = settings.lightingStandard;
        s.energy = std::move(settings.energy);
    });
    emit projectChanged();
    if (energy) emit energyChanged();
}

void Document::setEnergy(std::optional<EnergySettings> energy) {
    modify([&](Scene& s) { s.energy = std::move(energy); });
    emit energyChanged();
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
