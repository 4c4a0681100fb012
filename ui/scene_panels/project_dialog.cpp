#include "ui/scene_panels/project_dialog.h"

#include "ui/commands/project_commands.h"
#include "ui/scene_panels/energy_settings_page.h"
#include "ui/scene_panels/maintenance_assistant_dialog.h"
#include "ui/scene_panels/project_pages.h"

#include <QDialogButtonBox>
#include <QTabWidget>
#include <QVBoxLayout>

namespace lucerna {

ProjectDialog::ProjectDialog(Document* doc, QWidget* parent, Tab tab) : QDialog(parent), doc_(doc) {
    setObjectName("projectDialog");
    setWindowTitle(tr("Project settings"));
    tabs_ = new QTabWidget(this);
    tabs_->setObjectName("projectTabs");
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(tabs_);
    layout->addWidget(buttons);
    addPage(new ProjectInfoPage(this), tr("Project"));
    addPage(new MaintenancePage(choicesForScene(doc->scene()), this), tr("Maintenance"));
    addPage(new StandardEditionPage(this), tr("Standard"));
    addPage(new EnergySettingsPage(doc->snapshot(), this), tr("Energy"));
    tabs_->setCurrentIndex(int(tab));
    resize(680, 600);  // room for the assistant's lines under the factors
}

void ProjectDialog::addPage(ProjectSettingsPage* page, const QString& title) {
    page->setParent(tabs_);
    page->load(doc_->projectSettings());
    tabs_->addTab(page, title);
    pages_.push_back(page);
}

ProjectSettings ProjectDialog::settings() const {
    ProjectSettings s = doc_->projectSettings();
    for (const ProjectSettingsPage* page : pages_) page->store(s);
    return s;
}

void ProjectDialog::accept() {
    for (ProjectSettingsPage* page : pages_) {
        if (!page->check().isEmpty()) {
            tabs_->setCurrentWidget(page);
            return;
        }
    }
    const ProjectSettings after = settings();
    if (!(after == doc_->projectSettings()))
        doc_->undoStack()->push(new EditProjectSettingsCommand(doc_, after, 0, tr("Change project settings")));
    QDialog::accept();
}

}  // namespace lucerna
