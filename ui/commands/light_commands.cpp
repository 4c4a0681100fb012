#include "ui/commands/light_commands.h"

#include "core/photometry/light_output.h"
#include "core/scene/scene_geometry.h"

namespace lucerna {

AddLightCommand::AddLightCommand(Document* doc, int index, Light light, const QString& text)
    : QUndoCommand(text), doc_(doc), index_(index), light_(std::move(light)) {}

void AddLightCommand::redo() { doc_->insertLight(index_, light_); }
void AddLightCommand::undo() { doc_->removeLight(index_); }

DeleteLightCommand::DeleteLightCommand(Document* doc, int index)
    : QUndoCommand(QObject::tr("Delete %1").arg(QString::fromStdString(doc->scene().lights.at(size_t(index)).name))),
      doc_(doc), index_(index), light_(doc->scene().lights.at(size_t(index))) {}

void DeleteLightCommand::redo() { doc_->removeLight(index_); }
void DeleteLightCommand::undo() { doc_->insertLight(index_, light_); }

EditLightCommand::EditLightCommand(Document* doc, int index, Light after, int mergeKey, const QString& text)
    : QUndoCommand(text), doc_(doc), index_(index), before_(doc->scene().lights.at(size_t(index))),
      after_(std::move(after)), mergeKey_(mergeKey) {}

void EditLightCommand::redo() { doc_->setLight(index_, after_); }
void EditLightCommand::undo() { doc_->setLight(index_, before_); }

bool EditLightCommand::mergeWith(const QUndoCommand* other) {
    const auto* o = static_cast<const EditLightCommand*>(other);
    if (mergeKey_ == 0 || o->mergeKey_ != mergeKey_ || o->index_ != index_) return false;
    after_ = o->after_;
    return true;
}

QString lightTypeName(LightType type) {
    switch (type) {
    case LightType::Point: return QObject::tr("Point light");
    case LightType::Spot: return QObject::tr("Spot light");
    case LightType::Directional: return QObject::tr("Directional light");
    case LightType::Luminaire: return QObject::tr("Luminaire");
    case LightType::Sun: return QObject::tr("Sun");
    }
    return {};
}

Light defaultLight(const Scene& scene, LightType type, const std::string& name) {
    const SceneBounds b = sceneBounds(scene);
    Light l;
    l.name = name;
    l.type = type;
    // Above the middle of the scene, a fifth of its size below the top.
    l.position = V3d(b.center.x, b.hi.y - 0.2 * (b.hi.y - b.lo.y), b.center.z);
    l.direction = V3d(0, -1, 0);
    // A plausible lamp: 1000 lm at 3000 K (a spot's flux spread over its cone), given in those
    // keys so that the file says so.
    PhotometricSpec lamp;
    lamp.quantity = PhotometricSpec::Quantity::Lumens;
    lamp.value = 1000;
    lamp.temperatureK = 3000;
    switch (type) {
    case LightType::Point: l = withPhotometric(l, lamp); break;
    case LightType::Spot:
        l.coneAngleDeg = 30;
        l.falloffStartDeg = 25;
        l = withPhotometric(l, lamp);
        break;
    case LightType::Directional:
        l.direction = V3d(-0.3, -1, 0.2);
        l.irradiance = Rgbd(2, 2, 2);
        break;
    case LightType::Luminaire:  // needs a file: not made from the Edit menu
    case LightType::Sun: break;   // made by the daylight panel (daylight_commands.h)
    }
    return l;
}

}  // namespace lucerna
