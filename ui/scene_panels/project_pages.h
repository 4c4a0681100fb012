#pragma once
// The tabs of File > Project Settings (ui/scene_panels/project_dialog.h): the project's name,
// client, designer and notes (the `project` key, the report's cover), the scene's maintenance
// factor (the top-level `maintenance_factor` key) and the EN 12464-1 edition its task areas are
// checked against (the top-level `lighting_standard` key).

#include "ui/scene_panels/project_dialog.h"

#include "core/photometry/maintenance_assistant.h"

class QComboBox;
class QLineEdit;
class QPlainTextEdit;

namespace lucerna {

class MaintenanceFactorEdit;

class ProjectInfoPage : public ProjectSettingsPage {
    Q_OBJECT
public:
    explicit ProjectInfoPage(QWidget* parent = nullptr);
    void load(const ProjectSettings& settings) override;
    // A field counts only when it was edited (an untouched one keeps the file's text exactly). All
    // four empty: no `project` key (one the file had empty stays).
    void store(ProjectSettings& settings) const override;

private:
    QLineEdit *name_, *client_, *designer_;
    QPlainTextEdit* notes_;
    ProjectInfo loaded_;
    QString shownNotes_;  // the notes as the field shows what was loaded
};

class MaintenancePage : public ProjectSettingsPage {
    Q_OBJECT
public:
    // `choices`: what the assistant opens on (the scene's room).
    explicit MaintenancePage(const MaintenanceChoices& choices, QWidget* parent = nullptr);
    void load(const ProjectSettings& settings) override;
    void store(ProjectSettings& settings) const override;
    MaintenanceFactorEdit* factorEdit() const { return edit_; }

private:
    MaintenanceFactorEdit* edit_;
};

class StandardEditionPage : public ProjectSettingsPage {
    Q_OBJECT
public:
    explicit StandardEditionPage(QWidget* parent = nullptr);
    void load(const ProjectSettings& settings) override;
    // The edition left as loaded keeps the scene's key as it was (absent stays absent); another
    // one is written.
    void store(ProjectSettings& settings) const override;
    QComboBox* editionField() const { return edition_; }

private:
    QComboBox* edition_;
    std::optional<StandardEdition> loaded_;
};

}  // namespace lucerna
