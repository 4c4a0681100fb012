#include "ui/properties/properties_panel.h"

#include "ui/properties/light_properties.h"
#include "ui/properties/light_set_properties.h"
#include "ui/properties/material_properties.h"
#include "ui/properties/object_properties.h"
#include "ui/properties/task_area_properties.h"

#include <QFrame>
#include <QVBoxLayout>

namespace lucerna {

PropertiesPanel::PropertiesPanel(Document* doc, LightProperties* lights, QWidget* parent)
    : QStackedWidget(parent), doc_(doc), lights_(lights) {
    surfacePage_ = new QWidget(this);
    objects_ = new ObjectProperties(doc, surfacePage_);
    objects_->setObjectName("objectProperties");
    materials_ = new MaterialProperties(doc, surfacePage_);
    materials_->setObjectName("materialProperties");
    separator_ = new QFrame(surfacePage_);
    separator_->setFrameShape(QFrame::HLine);
    separator_->setFrameShadow(QFrame::Sunken);
    auto* v = new QVBoxLayout(surfacePage_);
    v->addWidget(objects_);
    v->addWidget(separator_);
    v->addWidget(materials_);
    v->addStretch(1);
    sets_ = new LightSetProperties(doc, this);
    sets_->setObjectName("lightSetProperties");
    addWidget(lights_);
    addWidget(surfacePage_);
    addWidget(sets_);
    taskAreas_ = new TaskAreaProperties(doc, this);
    taskAreas_->setObjectName("taskAreaProperties");
    addWidget(taskAreas_);
    connect(objects_, &ObjectProperties::materialAssigned, materials_, &MaterialProperties::setMaterial);
    // Undo of an assignment, or a rename of the object's material: the panel follows the object.
    connect(doc_, &Document::changed, this, &PropertiesPanel::followObjectMaterial);
    // The dock as wide and tall as the page shown needs, not as the widest of all pages (a
    // stacked widget's own rule), so that a narrow dock does not scroll sideways to a page that
    // is not there.
    connect(this, &QStackedWidget::currentChanged, this, [this](int shown) {
        for (int i = 0; i < count(); ++i) {
            const QSizePolicy::Policy p = i == shown ? QSizePolicy::Preferred : QSizePolicy::Ignored;
            widget(i)->setSizePolicy(p, p);
        }
        updateGeometry();
    });
    showSelection({});
}

void PropertiesPanel::showSelection(const Outliner::Selection& s) {
    lights_->setLight(s.kind == Outliner::Kind::Light ? s.index : -1);
    objects_->setObject(s.kind == Outliner::Kind::Object ? s.index : -1);
    if (s.kind == Outliner::Kind::Material) materials_->setMaterial(s.index);
    else if (s.kind == Outliner::Kind::Object) followObjectMaterial();
    else materials_->setMaterial(-1);
    separator_->setVisible(s.kind == Outliner::Kind::Object);  // only between two panels
    if (s.kind == Outliner::Kind::Group) sets_->setGroup(s.group);
    else if (s.kind == Outliner::Kind::Lights) sets_->setLights(s.lights);
    else sets_->setLights({});
    taskAreas_->setTaskArea(s.kind == Outliner::Kind::TaskArea ? s.index : -1);
    if (s.kind == Outliner::Kind::TaskArea) {
        setCurrentWidget(taskAreas_);
        return;
    }
    const bool set = s.kind == Outliner::Kind::Group || s.kind == Outliner::Kind::Lights;
    setCurrentWidget(set ? static_cast<QWidget*>(sets_) : s.kind == Outliner::Kind::Light ? static_cast<QWidget*>(lights_) : surfacePage_);
}

void PropertiesPanel::followObjectMaterial() {
    const int i = objects_->object();
    const Scene& scene = doc_->scene();
    if (i < 0 || i >= int(scene.objects.size())) return;
    materials_->setMaterial(scene.materialIndex(scene.objects[size_t(i)].material));
}

}  // namespace lucerna
