#pragma once
// The property panel of several lights at once (issue 19): a group selected in the outliner, or
// lights selected together. It edits what the lights share, each edit one undo step for all of
// them: the group they belong to (renaming a group, gathering lights into one, or none), switched
// on or off, the luminous flux (lm) of each, the colour temperature (K), and the luminaire file
// (every light with a position becomes a luminaire of that file at its own place and aim). A field
// whose value differs between the lights says "mixed" until a value is typed.

#include "ui/document/document.h"
#include "ui/properties/property_rows.h"

#include <QWidget>

#include <functional>
#include <string>
#include <vector>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace lucerna {

class LightSetProperties : public QWidget {
    Q_OBJECT
public:
    explicit LightSetProperties(Document* doc, QWidget* parent = nullptr);
    ~LightSetProperties() override;  // disconnects its children first (ui/disconnect_children.h)

    // A scene group (its lights follow the group as the scene changes) or a fixed set of lights.
    void setGroup(const std::string& group);
    void setLights(std::vector<int> lights);
    const std::vector<int>& lights() const { return lights_; }

    // The file dialog the Replace button asks (the window's; tests answer it).
    void setFileQuestion(std::function<QString()> ask) { askFile_ = std::move(ask); }
    // Every light with a position becomes a luminaire of `path` (IES or EULUMDAT) at its own
    // place, nadir along its aim (straight down for a point light), at the file's own flux, its
    // colour and rotation kept: one undo step. False, with a one-line reason, when the file
    // cannot be read (nothing changes).
    bool replaceLuminaireFile(const QString& path, QString* error = nullptr);

    QLabel* titleLabel() const { return title_; }
    QLineEdit* groupField() const { return group_; }
    QCheckBox* onField() const { return on_; }
    QDoubleSpinBox* fluxField() const { return flux_; }
    QDoubleSpinBox* temperatureField() const { return temperature_; }
    QLabel* fileLabel() const { return file_; }

signals:
    void message(const QString& text);

private:
    enum class Field { Group, On, Flux, Temperature };
    void refresh();
    void apply(Field field, const void* sender);
    void push(std::vector<int> indices, std::vector<Light> after, const void* sender, const QString& text);

    Document* doc_;
    std::string groupName_;     // a group's panel: its name (empty for a multi-selection)
    std::vector<int> lights_;
    QLabel *title_, *summary_, *file_;
    QLineEdit* group_;
    QCheckBox* on_;
    QDoubleSpinBox *flux_, *temperature_;
    QPushButton* replace_;
    QWidget *fluxRow_, *temperatureRow_;
    std::function<QString()> askFile_;
    MergeTracker merge_;
};

}  // namespace lucerna
