#pragma once
// The properties dock: the panel of what the outliner selects. A light shows the light panel; a
// group or several lights the panel of a set of lights; an object shows the object panel above
// its material's panel; a material shows the material panel; a task area its page.

#include "ui/document/document.h"
#include "ui/scene_panels/outliner.h"

#include <QStackedWidget>

class QFrame;

namespace lucerna {

class LightProperties;
class LightSetProperties;
class MaterialProperties;
class ObjectProperties;
class TaskAreaProperties;

class PropertiesPanel : public QStackedWidget {
    Q_OBJECT
public:
    // Takes `lights` as its first page.
    PropertiesPanel(Document* doc, LightProperties* lights, QWidget* parent = nullptr);

    void showSelection(const Outliner::Selection& selection);

    MaterialProperties* materialProperties() const { return materials_; }
    ObjectProperties* objectProperties() const { return objects_; }
    LightSetProperties* lightSetProperties() const { return sets_; }
    TaskAreaProperties* taskAreaProperties() const { return taskAreas_; }

private:
    void followObjectMaterial();

    Document* doc_;
    LightProperties* lights_;
    QWidget* surfacePage_;
    QFrame* separator_;
    ObjectProperties* objects_;
    MaterialProperties* materials_;
    LightSetProperties* sets_;
    TaskAreaProperties* taskAreas_;
};

}  // namespace lucerna
