#pragma once
// File > Project Settings: the project's details for the report's cover, the scene's
// maintenance factor, the EN 12464-1 edition (ui/scene_panels/project_pages.h) and the lighting
// energy's settings (ui/scene_panels/energy_settings_page.h), one tab each. OK is one undo step
// for everything the tabs changed (EditProjectSettingsCommand); Cancel changes nothing.
//
// A tab is a ProjectSettingsPage: it shows the settings and writes its part back. Another tab is
// added with addPage; a part of the scene a new tab edits is a member of ProjectSettings, so that
// it joins the same undo step.

#include "ui/document/document.h"

#include <QDialog>
#include <QWidget>

#include <vector>

class QTabWidget;

namespace lucerna {

class ProjectSettingsPage : public QWidget {
    Q_OBJECT
public:
    using QWidget::QWidget;
    // Shows `settings` (the document's, when the dialog opens).
    virtual void load(const ProjectSettings& settings) = 0;
    // Writes what the page shows into `settings`, leaving the rest of it as it is.
    virtual void store(ProjectSettings& settings) const = 0;
    // Before OK stores: empty, or one line saying why what the page shows cannot be stored (a
    // value out of range), which the page shows too. OK then stays open on this page.
    virtual QString check() { return {}; }
};

class ProjectDialog : public QDialog {
    Q_OBJECT
public:
    // The tabs, in their order.
    enum class Tab { Project, Maintenance, Standard, Energy };

    // Opens with the tabs "Project", "Maintenance", "Standard" and "Energy", showing `doc`'s
    // settings, on `tab`.
    explicit ProjectDialog(Document* doc, QWidget* parent = nullptr, Tab tab = Tab::Project);

    // Adds a tab after the others; the dialog owns it, loads it now and stores it on OK.
    void addPage(ProjectSettingsPage* page, const QString& title);
    QTabWidget* tabs() const { return tabs_; }
    // The settings the tabs show now (what OK would set).
    ProjectSettings settings() const;

    // OK: when a tab's check() finds a problem, shows that tab and stays open; otherwise pushes
    // one command when the settings changed, then closes.
    void accept() override;

private:
    Document* doc_;
    QTabWidget* tabs_;
    std::vector<ProjectSettingsPage*> pages_;
};

}  // namespace lucerna
