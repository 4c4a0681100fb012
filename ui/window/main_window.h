#pragma once
// The application window, in the shape of Tiled's: the document and its undo stack, the viewport
// with the live preview in the middle, and docks for the converging render, the outliner and the
// selected light's properties. The window only wires these together and runs the file menu;
// each part is its own widget, and every edit is an undo command (ui/commands/).

// oneTBB before any Qt header: Qt's `emit` macro breaks TBB's headers.
#include "core/task_system.h"
#include "ui/document/document.h"
#include "ui/scene_panels/light_arrangement.h"
#include "ui/rendering/yield_gate.h"

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
class LightProperties;
class LivePreview;
class Outliner;
class PlanView;
class PropertiesPanel;
class RecentFilesMenu;
class RenderPanel;
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

    // The file operations behind the menu, without dialogs. Each returns false and says why in
    // the status bar (and lastError()) when it fails.
    bool openFile(const QString& path);
    bool save();                           // to the document's path; Save As when it has none
    bool saveFileAs(const QString& path);
    bool exportExr(const QString& path);   // the converging render's newest frame, SPEC.md section 3
    // The live preview's newest frame, SPEC.md section 3; both: PATH-preview.exr and
    // PATH-converged.exr. Every EXR export carries albedo, normal and depth layers (README).
    bool exportPreviewExr(const QString& path);
    bool exportBothExr(const QString& path);
    // The converging render's newest frame at full resolution, as the display settings show it
    // (exposure, tone curve or false colour).
    bool exportPng(const QString& path);
    // File > New without its question: an untitled scene with a floor (ui/document/new_scene.h).
    void newScene();
    // Adds the mesh file as a new object with a material of its own: one undo step.
    bool importMeshFile(const QString& path);
    // Adds a model (OBJ+MTL, glTF, FBX, COLLADA, ...: objects, materials, lights) in one undo
    // step and shows the import report (ui/io/model_import_action.h) in a non-modal window.
    // Into a new scene (untitled, the model on a floor, the camera framing it) or the open one.
    enum class ImportTarget { OpenScene, NewScene, Cancel };
    bool importModelFile(const QString& path, ImportTarget target = ImportTarget::OpenScene);
    // Replaces the question File > Import Model asks (new scene or this one).
    void setImportQuestion(std::function<ImportTarget()> ask) { askImport_ = std::move(ask); }
    // The menus' file dialogs (they open in the scene's folder; tests replace the question).
    FileDialogs* fileDialogs() const { return dialogs_.get(); }
    // Edit > Add Luminaire without its file dialog: adds the IES or EULUMDAT file's luminaire as
    // one undo step and selects it; false (and a status message) when the file cannot be read.
    bool addLuminaireFile(const QString& path);
    // Before unsaved changes are lost: asks (Save, Discard, Cancel); true when it may go on.
    bool maybeSave();
    // Replaces the question maybeSave() asks (tests answer without a modal dialog).
    void setSaveQuestion(std::function<QMessageBox::StandardButton()> ask) { ask_ = std::move(ask); }
    QString lastError() const { return lastError_; }

    // Crash recovery (ui/document/autosave.h): autosaves go to `directory` from now on; a recovery file a
    // previous session left there is offered back (the question is replaceable for tests, like
    // the save question). Returns true when the scene was recovered.
    bool startAutosave(const QString& directory, int intervalMs = 60000);
    void setRecoveryQuestion(std::function<QMessageBox::StandardButton()> ask) { askRecovery_ = std::move(ask); }
    Autosave* autosave() const { return autosave_.get(); }

    // Edit > Arrange Lights: the dialog (ui/scene_panels/arrangement_dialog.h), over the rectangle drawn in the
    // plan when given (x0, z0, x1, z1), else the scene's plan.
    void arrangeLights(const std::optional<std::array<double, 4>>& rectangle = std::nullopt);
    // The field added as one undo step and its group selected; false with a one-line reason in
    // the status bar (and lastError()) when it makes no field.
    bool arrangeField(const FieldArrangement& field, const Light& prototype, const QString& group);

    // Edit menu operations on the selection.
    void addLight(LightType type);
    void duplicateSelection();
    void deleteSelection();
    int selectedLight() const;

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
    RecentFilesMenu* recentFiles() const { return recent_; }
    PlanView* planView() const { return plan_; }
    ViewArea* viewArea() const { return viewArea_; }
    CameraPanel* cameraPanel() const { return cameraPanel_; }
    DaylightPanel* daylightPanel() const { return daylightPanel_; }
    ReportExport* reportExport() const { return report_.get(); }

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void createDocks();
    void createMenus();
    void defaultDockSizes();
    ImportTarget askImportTarget();
    void showPreviewFrame();
    void updateTitle();
    void fail(const QString& message);

    std::unique_ptr<Document> doc_;
    TaskSystem tasks_;
    YieldGate gate_;
    // After tasks_: their jobs run in its arena and end before it goes.
    std::unique_ptr<ConvergingRender> render_;
    std::unique_ptr<LivePreview> preview_;
    std::unique_ptr<ReportExport> report_;  // File > Export Report
    Viewport* viewport_ = nullptr;
    PlanView* plan_ = nullptr;
    ViewArea* viewArea_ = nullptr;  // the viewport or the plan view
    CameraPanel* cameraPanel_ = nullptr;
    DaylightPanel* daylightPanel_ = nullptr;
    RenderPanel* renderPanel_ = nullptr;
    Outliner* outliner_ = nullptr;
    LightProperties* properties_ = nullptr;
    PropertiesPanel* propertiesPanel_ = nullptr;  // light, object and material panels
    CompareView* compare_ = nullptr;  // also holds the display settings of every view
    GridPanel* gridPanel_ = nullptr;
    RecentFilesMenu* recent_ = nullptr;
    QLabel* previewInfo_ = nullptr;
    QDockWidget *renderDock_ = nullptr, *outlinerDock_ = nullptr;
    std::function<QMessageBox::StandardButton()> ask_, askRecovery_;
    std::function<ImportTarget()> askImport_;
    std::unique_ptr<FileDialogs> dialogs_;
    LayoutState* layout_ = nullptr;
    std::unique_ptr<Autosave> autosave_;
    QString lastError_;
};

}  // namespace lucerna
