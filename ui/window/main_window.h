#pragma once
// The application window, in the shape of Tiled's: the document and its undo stack, the viewport
// with the live preview in the middle, and docks for the converging render, the outliner and the
// selected light's properties. The window only wires these together: each part is its own widget,
// the menus' actions are their own objects (FileActions, ExportActions, ImportActions,
// EditActions), and every edit is an undo command (ui/commands/).

// oneTBB before any Qt header: Qt's `emit` macro breaks TBB's headers.
#include "core/task_system.h"
#include "ui/document/document.h"
#include "ui/io/export_actions.h"
#include "ui/io/import_actions.h"
#include "ui/rendering/yield_gate.h"
#include "ui/window/edit_actions.h"
#include "ui/window/file_actions.h"
#include "ui/window/window_messages.h"

#include <QMainWindow>
#include <QMessageBox>

#include <array>
#include <functional>
#include <memory>
#include <optional>

class QDockWidget;
class QLabel;

namespace lucerna {

class Autosave;
class CameraPanel;
class CompareView;
class DaylightPanel;
class FileDialogs;
class LayoutState;
class ConvergingRender;
class GridPanel;
class AnnualPanel;
class LightProperties;
class LivePreview;
class Outliner;
class PlanView;
class PropertiesPanel;
class RecentFilesMenu;
class RenderPanel;
class TaskAreaActions;
class RoomActions;
class ReportExport;
class ViewArea;
class Viewport;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    // Opens scenePath when given (a failure is reported in the status bar; the window stays).
    explicit MainWindow(const QString& scenePath = {}, QWidget* parent = nullptr);
    explicit MainWindow(const std::string& scenePath, QWidget* parent = nullptr)
        : MainWindow(QString::fromStdString(scenePath), parent) {}
    ~MainWindow() override;

    // The menus' operations without their dialogs, and the questions tests answer in their
    // place: FileActions, ExportActions, ImportActions and EditActions say what each promises. A
    // failure is said in the status bar and kept as lastError().
    bool openFile(const QString& path) { return files_->openFile(path); }
    bool save() { return files_->save(); }
    bool saveFileAs(const QString& path) { return files_->saveFileAs(path); }
    void newScene() { files_->newScene(); }
    bool maybeSave() { return files_->maybeSave(); }
    void setSaveQuestion(std::function<QMessageBox::StandardButton()> ask) { files_->setSaveQuestion(std::move(ask)); }
    bool startAutosave(const QString& directory, int intervalMs = 60000) {
        return files_->startAutosave(directory, intervalMs);
    }
    void setRecoveryQuestion(std::function<QMessageBox::StandardButton()> ask) {
        files_->setRecoveryQuestion(std::move(ask));
    }
    Autosave* autosave() const { return files_->autosave(); }
    bool exportExr(const QString& path) { return exports_->exportExr(path); }
    bool exportPreviewExr(const QString& path) { return exports_->exportPreviewExr(path); }
    bool exportBothExr(const QString& path) { return exports_->exportBothExr(path); }
    bool exportPng(const QString& path) { return exports_->exportPng(path); }
    using ImportTarget = lucerna::ImportTarget;
    bool importMeshFile(const QString& path) { return imports_->importMeshFile(path); }
    bool importModelFile(const QString& path, ImportTarget target = ImportTarget::OpenScene) {
        return imports_->importModelFile(path, target);
    }
    void setImportQuestion(std::function<ImportTarget()> ask) { imports_->setImportQuestion(std::move(ask)); }
    void addLight(LightType type) { edits_->addLight(type); }
    bool addLuminaireFile(const QString& path) { return edits_->addLuminaireFile(path); }
    void arrangeLights(const std::optional<std::array<double, 4>>& rectangle = std::nullopt) {
        edits_->arrangeLights(rectangle);
    }
    bool arrangeField(const FieldArrangement& field, const Light& prototype, const QString& group) {
        return edits_->arrangeField(field, prototype, group);
    }
    void duplicateSelection() { edits_->duplicateSelection(); }
    void deleteSelection() { edits_->deleteSelection(); }
    int selectedLight() const { return edits_->selectedLight(); }
    QString lastError() const { return messages_.lastError(); }
    // The menus' file dialogs (they open in the scene's folder; tests replace the question).
    FileDialogs* fileDialogs() const { return dialogs_.get(); }

    Document* document() const { return doc_.get(); }
    ConvergingRender* convergingRender() const { return render_.get(); }
    LivePreview* livePreview() const { return preview_.get(); }
    Viewport* viewport() const { return viewport_; }
    RenderPanel* renderPanel() const { return renderPanel_; }
    Outliner* outliner() const { return outliner_; }
    LightProperties* lightProperties() const { return properties_; }
    PropertiesPanel* propertiesPanel() const { return propertiesPanel_; }
    CompareView* compareView() const { return compare_; }
    GridPanel* gridPanel() const { return gridPanel_; }
    RecentFilesMenu* recentFiles() const { return files_->recentFiles(); }
    PlanView* planView() const { return plan_; }
    ViewArea* viewArea() const { return viewArea_; }
    CameraPanel* cameraPanel() const { return cameraPanel_; }
    DaylightPanel* daylightPanel() const { return daylightPanel_; }
    AnnualPanel* annualPanel() const { return annualPanel_; }
    ReportExport* reportExport() const { return report_.get(); }
    TaskAreaActions* taskAreaActions() const { return taskAreas_.get(); }
    RoomActions* roomActions() const { return rooms_.get(); }

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void createDocks();
    void createMenus();
    void defaultDockSizes();
    void showPreviewFrame();
    void updateTitle();

    std::unique_ptr<Document> doc_;
    WindowMessages messages_;
    TaskSystem tasks_;
    YieldGate gate_;
    // After tasks_: their jobs run in its arena and end before it goes.
    std::unique_ptr<ConvergingRender> render_;
    std::unique_ptr<LivePreview> preview_;
    std::unique_ptr<ReportExport> report_;  // File > Export Report
    std::unique_ptr<FileDialogs> dialogs_;
    // After the document and the renders they act on.
    std::unique_ptr<FileActions> files_;
    std::unique_ptr<ExportActions> exports_;
    std::unique_ptr<ImportActions> imports_;
    std::unique_ptr<EditActions> edits_;
    std::unique_ptr<TaskAreaActions> taskAreas_;  // Add Task Area, the plan's drawn ones
    std::unique_ptr<RoomActions> rooms_;          // Add Room, openings, Mark as Room, the plan's drawn rooms
    Viewport* viewport_ = nullptr;
    PlanView* plan_ = nullptr;
    ViewArea* viewArea_ = nullptr;  // the viewport or the plan view
    CameraPanel* cameraPanel_ = nullptr;
    DaylightPanel* daylightPanel_ = nullptr;
    AnnualPanel* annualPanel_ = nullptr;
    RenderPanel* renderPanel_ = nullptr;
    Outliner* outliner_ = nullptr;
    LightProperties* properties_ = nullptr;
    PropertiesPanel* propertiesPanel_ = nullptr;  // light, object and material panels
    CompareView* compare_ = nullptr;  // also holds the display settings of every view
    GridPanel* gridPanel_ = nullptr;
    QLabel* previewInfo_ = nullptr;
    QDockWidget *renderDock_ = nullptr, *outlinerDock_ = nullptr;
    LayoutState* layout_ = nullptr;
};

}  // namespace lucerna
