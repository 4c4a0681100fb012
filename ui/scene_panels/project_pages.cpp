#include "ui/scene_panels/project_pages.h"

#include "core/photometry/lighting_standards.h"
#include "ui/properties/property_rows.h"
#include "ui/scene_panels/maintenance_factor_edit.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QVBoxLayout>

namespace lucerna {

namespace {
QLineEdit* line(QWidget* parent, const char* name, const QString& placeholder) {
    auto* edit = new QLineEdit(parent);
    edit->setObjectName(name);
    edit->setPlaceholderText(placeholder);
    return edit;
}
}  // namespace

ProjectInfoPage::ProjectInfoPage(QWidget* parent) : ProjectSettingsPage(parent) {
    setObjectName("projectInfoPage");
    name_ = line(this, "projectName", tr("the scene file's name"));
    client_ = line(this, "projectClient", {});
    designer_ = line(this, "projectDesigner", {});
    notes_ = new QPlainTextEdit(this);
    notes_->setObjectName("projectNotes");
    notes_->setTabChangesFocus(true);
    auto* form = new QFormLayout(this);
    form->addRow(tr("Name"), name_);
    form->addRow(tr("Client"), client_);
    form->addRow(tr("Designer"), designer_);
    form->addRow(tr("Notes"), notes_);
    form->addRow(makeWrappingLabel(this, "projectHelp",
                                   tr("On the report's cover and in every page's header (the name; without one, "
                                      "the scene file's name).")));
}

void ProjectInfoPage::load(const ProjectSettings& settings) {
    loaded_ = settings.project.value_or(ProjectInfo{});
    name_->setText(QString::fromStdString(loaded_.name));
    client_->setText(QString::fromStdString(loaded_.client));
    designer_->setText(QString::fromStdString(loaded_.designer));
    notes_->setPlainText(QString::fromStdString(loaded_.notes));
    shownNotes_ = notes_->toPlainText();
}

void ProjectInfoPage::store(ProjectSettings& settings) const {
    ProjectInfo p = loaded_;
    const auto take = [](const QLineEdit* field, std::string& out) {
        if (field->text() != QString::fromStdString(out)) out = field->text().toStdString();
    };
    take(name_, p.name);
    take(client_, p.client);
    take(designer_, p.designer);
    if (notes_->toPlainText() != shownNotes_) p.notes = notes_->toPlainText().toStdString();
    if (!(p == ProjectInfo{})) settings.project = p;
    else if (!(settings.project && *settings.project == ProjectInfo{})) settings.project.reset();
}

MaintenancePage::MaintenancePage(const MaintenanceChoices& choices, QWidget* parent) : ProjectSettingsPage(parent) {
    setObjectName("maintenancePage");
    edit_ = new MaintenanceFactorEdit(MaintenanceFactorEdit::Absent::None, this);
    edit_->setObjectName("sceneMaintenance");
    edit_->setAssistantChoices(choices);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(makeWrappingLabel(
        this, "maintenanceHelp",
        tr("The maintenance factor (CIE 97:2005) scales every electric light and emitting surface to what the "
           "installation gives at the end of its maintenance cycle, so that the grids, the lux view and the report "
           "show maintained values. A light's own factor (its Properties) replaces it for that light.\n"
           "None: the figures are the new installation's, and a task area's maintained illuminance Em "
           "(EN 12464-1) is left \"not checked\".")));
    layout->addWidget(edit_, 1);  // the room below is the assistant's lines
}

void MaintenancePage::load(const ProjectSettings& settings) { edit_->setValue(settings.maintenance); }

void MaintenancePage::store(ProjectSettings& settings) const { settings.maintenance = edit_->value(); }

StandardEditionPage::StandardEditionPage(QWidget* parent) : ProjectSettingsPage(parent) {
    setObjectName("standardPage");
    edition_ = new QComboBox(this);
    edition_->setObjectName("lightingStandard");
    for (StandardEdition e : {StandardEdition::En12464_2021, StandardEdition::En12464_2011})
        edition_->addItem(QString::fromUtf8(standardEditionName(e)), int(e));
    // Which 2021 figures are bundled, from the table itself, so that the note cannot go stale.
    QStringList bundled;
    for (const ActivityRequirement& a : en12464Activities(StandardEdition::En12464_2021))
        bundled << QStringLiteral("%1 %2").arg(QString::fromUtf8(a.reference), QString::fromUtf8(a.activity));
    auto* form = new QFormLayout(this);
    form->addRow(tr("Task areas are checked against"), edition_);
    form->addRow(makeWrappingLabel(
        this, "standardHelp",
        tr("EN 12464-1 gives each activity its maintained illuminance Em, uniformity U0, glare limit UGR_L and "
           "colour rendering Ra; the 2021 edition adds a modified Em,u for demanding contexts and the cylindrical "
           "illuminance Ez and the walls' and ceiling's illuminance, each with U0 0.10.\n"
           "Bundled 2021 figures: %1. Every other activity is checked against its 2011 figures under 2021, "
           "and its requirement line says so. Without a choice in the scene file: 2021.")
            .arg(bundled.join(tr("; ")))));
}

void StandardEditionPage::load(const ProjectSettings& settings) {
    loaded_ = settings.lightingStandard;
    edition_->setCurrentIndex(edition_->findData(int(settings.lightingStandard.value_or(kDefaultStandardEdition))));
}

void StandardEditionPage::store(ProjectSettings& settings) const {
    const auto shown = StandardEdition(edition_->currentData().toInt());
    settings.lightingStandard = shown == loaded_.value_or(kDefaultStandardEdition) ? loaded_ : std::optional(shown);
}

}  // namespace lucerna
