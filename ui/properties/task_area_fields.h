#pragma once
// The fields of a task area (README, "Task areas"), shared by Edit > Add Task Area's dialog
// (ui/scene_panels/task_area_dialog.h) and the task area's properties page
// (ui/properties/task_area_properties.h): its name; its rectangle in the plan (the corner of
// least x and z in the scene's unit, width along x and depth along z in metres) and the work
// plane's height above the floor (the scene's lowest geometry) in metres; the activity, chosen by
// area and activity from EN 12464-1's bundled table of the scene's edition (2021: the 2021 entries
// and the 2011 ones it falls back to, marked "(2011)"), with its requirements; the posture
// (seated or standing: where EN 12464-1:2021's Ez is computed, 1.2 m or 1.6 m); the grid spacing
// (EN 12464-1's rule unless set, the rule's spacing shown); the surrounding zone and the
// background area (core/photometry/surrounding_zones.h), each a check box with its width and the
// requirement that follows; and the glare observers, a list of eye positions (scene units) and
// view directions (none: the report's four). A field the user leaves alone keeps the area's
// exact value, though a spin box shows it rounded. An area not lying flat with its sides along x
// and z (on a wall, turned in the plan) keeps its rectangle: those fields are shown disabled.

#include "core/scene/scene.h"

#include <QString>
#include <QWidget>

#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;

namespace lucerna {

// The floor a task area's height is measured from: the scene's lowest point (as the work plane's).
double taskAreaFloor(const Scene& scene);

class TaskAreaFields : public QWidget {
    Q_OBJECT
public:
    explicit TaskAreaFields(QWidget* parent = nullptr);
    ~TaskAreaFields() override;  // disconnects its children first (ui/disconnect_children.h)

    // Shows `area`, placed in `scene` (its unit, its floor and its EN 12464-1 edition).
    void setArea(const TaskArea& area, const Scene& scene);
    // The area as the fields give it now (observer rows that do not parse left out: problem()).
    TaskArea area() const;
    // Why the fields give no valid area, in one line (an empty name, an observer's value that is
    // not a number, a view of zero); nothing when they give one. Whether the name is taken is the
    // caller's to check.
    std::optional<QString> problem() const;
    // The floor and unit the fields were last shown with.
    double floorY() const { return floorY_; }
    double metersPerUnit() const { return metersPerUnit_; }
    // The edition whose activities the fields list.
    StandardEdition edition() const { return edition_; }

    QLineEdit* nameField() const { return name_; }
    QDoubleSpinBox* xField() const { return x_; }
    QDoubleSpinBox* zField() const { return z_; }
    QDoubleSpinBox* widthField() const { return width_; }
    QDoubleSpinBox* depthField() const { return depth_; }
    QDoubleSpinBox* heightField() const { return height_; }
    QComboBox* activityAreaField() const { return activityArea_; }
    QComboBox* activityField() const { return activity_; }
    QComboBox* postureField() const { return posture_; }  // 0 seated, 1 standing
    QDoubleSpinBox* spacingField() const { return spacing_; }
    QCheckBox* surroundingBox() const { return surrounding_; }
    QDoubleSpinBox* surroundingWidthField() const { return surroundingWidth_; }
    QCheckBox* backgroundBox() const { return background_; }
    QDoubleSpinBox* backgroundWidthField() const { return backgroundWidth_; }
    QTableWidget* observersTable() const { return observers_; }
    QPushButton* addObserverButton() const { return addObserver_; }
    QPushButton* removeObserverButton() const { return removeObserver_; }

signals:
    // The user changed a field (the field, for undo merging: a spin box's arrow steps are one
    // field's run).
    void edited(const QObject* field);
    // A field's editing finished (Enter, focus left, a discrete choice made): the next change is
    // a new undo step.
    void finished();

private:
    QDoubleSpinBox* makeSpin(const char* name, double lo, double hi, int decimals, const QString& suffix);
    void listAreas();
    void listActivities(const QString& area);
    void showActivity(const std::string& reference);
    void addObserverRow(const GlareObserver& o);
    std::optional<std::vector<GlareObserver>> observers(QString* why) const;
    void updateNotes();
    // A discrete change (a choice, a check box, a row): one step of its own.
    void discreteEdit(const QObject* field);

    QLineEdit* name_;
    QDoubleSpinBox *x_, *z_, *width_, *depth_, *height_, *spacing_, *surroundingWidth_, *backgroundWidth_;
    QComboBox *activityArea_, *activity_;
    QComboBox* posture_;
    QCheckBox *surrounding_, *background_;
    QLabel *rectangleNote_, *requirement_, *surroundingNote_, *backgroundNote_, *observersNote_;
    QTableWidget* observers_;
    QPushButton *addObserver_, *removeObserver_;

    TaskArea base_;  // the area shown: what the untouched fields keep
    double metersPerUnit_ = 1, floorY_ = 0;
    StandardEdition edition_ = kDefaultStandardEdition;
    int requirementReserve_ = 0;  // px: the requirement note's height for the longest line
    bool rectangleEditable_ = true;
    // The spin boxes' values as shown (rounded), to tell a field left alone from one edited.
    struct Shown {
        double x = 0, z = 0, width = 0, depth = 0, height = 0, spacing = 0, surrounding = 0, background = 0;
    } shown_;
    QString shownName_;
    bool filling_ = false;  // setArea is filling the fields: no edits announced
};

}  // namespace lucerna
