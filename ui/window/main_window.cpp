#include "ui/window/main_window.h"

#include "core/image/exr_io.h"
#include "core/resources.h"
#include "core/scene/scene_io.h"
#include "render/display/display.h"
#include "render/display/false_colour.h"
#include "ui/scene_panels/arrangement_dialog.h"
#include "ui/document/autosave.h"
#include "ui/scene_panels/camera_panel.h"
#include "ui/commands/light_commands.h"
#include "ui/commands/light_group_commands.h"
#include "ui/commands/object_commands.h"
#include "ui/commands/scene_commands.h"
#include "ui/compare/compare_view.h"
#include "ui/scene_panels/daylight_panel.h"
#include "ui/rendering/display_controls.h"
#include "ui/rendering/converging_render.h"
#include "ui/io/file_dialogs.h"
#include "ui/calculation/grid_panel.h"
#include "ui/io/image_export.h"
#include "ui/calculation/report_export.h"
#include "ui/window/layout_state.h"
#include "ui/properties/light_properties.h"
#include "ui/properties/light_set_properties.h"
#include "ui/rendering/live_preview.h"
#include "ui/io/luminaire_import.h"
#include "ui/io/mesh_import.h"
#include "ui/io/model_import_action.h"
#include "ui/document/new_scene.h"
#include "ui/scene_panels/outliner.h"
#include "ui/plan/plan_view.h"
#include "ui/properties/properties_panel.h"
#include "ui/window/recent_files.h"
#include "ui/rendering/render_panel.h"
#include "ui/window/view_area.h"
#include "ui/viewport/viewport.h"

#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QPushButton>
#include <QScrollArea>
#include <QScreen>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>

#include <filesystem>

namespace lucerna {

MainWindow::MainWindow(const QString& scenePath, QWidget* parent)
    : QMainWindow(parent), doc_(std::make_unique<Document>(Scene{})),
      render_(std::make_unique<ConvergingRender>(tasks_, gate_)),
      preview_(std::make_unique<LivePreview>(gate_, LivePreview::engineFromEnvironment())) {
    setObjectName("MainWindow");
    viewport_ = new Viewport(doc_.get(), gate_, this);
    viewport_->setObjectName("viewport");
    dialogs_ = std::make_unique<FileDialogs>(this, [this] {
        const QString folder =
            doc_->path().empty() ? QString() : QFileInfo(QString::fromStdString(doc_->path())).absolutePath();
        // The bundled scenes' folder belongs to the installation, not to the user's files.
        const QString bundled = QDir(QString::fromStdString(resourceDirectory())).absolutePath();
        return folder == bundled || folder.startsWith(bundled + '/') ? QString() : folder;
    });
    plan_ = new PlanView(doc_.get(), gate_, this);
    plan_->setObjectName("planView");
    viewArea_ = new ViewArea(viewport_, plan_, this);
    viewArea_->setObjectName("viewArea");
    setCentralWidget(viewArea_);
    createDocks();
    report_ = std::make_unique<ReportExport>(tasks_, gate_, this);
    connect(report_.get(), &ReportExport::finished, this, [this](bool, const QString& message) {
        statusBar()->showMessage(message, 8000);
    });
    createMenus();
    previewInfo_ = new QLabel(this);
    statusBar()->addPermanentWidget(previewInfo_);

    // Every edit reaches both images: the preview draws the newest snapshot, the converging
    // render restarts on it. A new scene never shows the old one's frame meanwhile.
    connect(doc_.get(), &Document::replaced, preview_.get(), &LivePreview::dropFrame);
    connect(doc_.get(), &Document::changed, this, [this] {
        preview_->setScene(doc_->snapshot());
        render_->setScene(doc_->snapshot());
        const MaintenanceRange mf = maintenanceRange(*doc_->snapshot());
        compare_->setIlluminanceNote(!mf.electric       ? QString()
                                     : !mf.maintained() ? tr("new")
                                     : mf.lowest == mf.highest
                                         ? tr("MF %1").arg(mf.lowest, 0, 'f', 2)
                                         : tr("MF %1-%2").arg(mf.lowest, 0, 'f', 2).arg(mf.highest, 0, 'f', 2));
    });
    connect(doc_->undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    connect(doc_.get(), &Document::pathChanged, this, &MainWindow::updateTitle);
    connect(preview_.get(), &LivePreview::frameReady, this, &MainWindow::showPreviewFrame);

    // 1500 x 900, or the screen's free area where that is smaller (a 1400 px screen cut off the
    // render dock's controls).
    QSize size(1500, 900);
    if (const QScreen* s = screen()) size = size.boundedTo(s->availableGeometry().size());
    resize(size);
    layout_ = new LayoutState(this, viewport_, [this] { defaultDockSizes(); });
    layout_->restore();
    updateTitle();
    if (!scenePath.isEmpty()) openFile(scenePath);
}

MainWindow::~MainWindow() {
    // The jobs first, while everything they report to is still there.
    report_.reset();
    render_.reset();
    preview_.reset();
}

void MainWindow::createDocks() {
    renderPanel_ = new RenderPanel(render_.get(), this);
    outliner_ = new Outliner(doc_.get(), this);
    outliner_->setObjectName("outliner");
    properties_ = new LightProperties(doc_.get(), this);
    properties_->setObjectName("lightProperties");
    const auto dock = [this](QWidget* w, const QString& title, const QString& name, Qt::DockWidgetArea area,
                             bool scrolls = false) {
        auto* d = new QDockWidget(title, this);
        d->setObjectName(name);  // saveState() needs names
        if (scrolls) {
            // A panel with a wide row of controls would make its dock as wide as that row and
            // the viewport narrower: it scrolls instead, and the dock keeps the size given it.
            auto* scroll = new QScrollArea(d);
            scroll->setWidget(w);
            scroll->setWidgetResizable(true);
            scroll->setFrameShape(QFrame::NoFrame);
            d->setWidget(scroll);
        } else {
            d->setWidget(w);
        }
        // A click anywhere in a dock takes the focus from the viewport, so that keys typed
        // afterwards do not fly the camera (Qt gives the focus to the nearest ancestor of the
        // clicked widget that takes it on a click).
        d->setFocusPolicy(Qt::ClickFocus);
        addDockWidget(area, d);
        return d;
    };
    QDockWidget* renderDock = dock(renderPanel_, tr("Converging render"), "renderDock", Qt::RightDockWidgetArea, true);
    QDockWidget* outlinerDock = dock(outliner_, tr("Outliner"), "outlinerDock", Qt::LeftDockWidgetArea);
    propertiesPanel_ = new PropertiesPanel(doc_.get(), properties_, this);
    QDockWidget* propertiesDock = dock(propertiesPanel_, tr("Properties"), "propertiesDock", Qt::LeftDockWidgetArea, true);
    cameraPanel_ = new CameraPanel(doc_.get(), this);
    cameraPanel_->setObjectName("cameraPanel");
    tabifyDockWidget(propertiesDock, dock(cameraPanel_, tr("Camera"), "cameraDock", Qt::LeftDockWidgetArea, true));
    daylightPanel_ = new DaylightPanel(doc_.get(), this);
    daylightPanel_->setObjectName("daylightPanel");
    tabifyDockWidget(propertiesDock, dock(daylightPanel_, tr("Daylight"), "daylightDock", Qt::LeftDockWidgetArea, true));
    propertiesDock->raise();
    // The comparison shares the render's side, a tab behind it.
    compare_ = new CompareView(this);
    compare_->setObjectName("compareView");
    QDockWidget* compareDock = dock(compare_, tr("Comparison"), "compareDock", Qt::RightDockWidgetArea, true);
    tabifyDockWidget(renderDock, compareDock);
    gridPanel_ = new GridPanel(doc_.get(), gate_, this);
    gridPanel_->setObjectName("gridPanel");
    tabifyDockWidget(renderDock, dock(gridPanel_, tr("Calculation grid"), "gridDock", Qt::RightDockWidgetArea, true));
    renderDock->raise();
    renderDock_ = renderDock;
    outlinerDock_ = outlinerDock;

    connect(outliner_, &Outliner::selectionChangedTo, this, [this](Outliner::Selection s) {
        const int light = s.kind == Outliner::Kind::Light ? s.index : -1;
        propertiesPanel_->showSelection(s);
        viewport_->setSelectedLight(light);
        plan_->setSelectedLight(light);
        plan_->setSelectedLights(s.lights);
        viewport_->setSelectedObject(s.kind == Outliner::Kind::Object ? s.index : -1);
    });
    connect(render_.get(), &ConvergingRender::frameReady, this, [this] {
        if (const auto frame = render_->frame()) compare_->setConverged(frame->image);
    });
    connect(compare_, &CompareView::displaySettingsChanged, this, [this](const DisplaySettings& s) {
        renderPanel_->setDisplaySettings(s);
        viewport_->setLegend(luminanceLegend(s));
        preview_->setAlbedoLayer(s.falseColour && s.quantity == FalseColourQuantity::Illuminance);
        showPreviewFrame();
    });
    connect(viewport_, &Viewport::lightClicked, this, [this](int i) { outliner_->select(Outliner::Kind::Light, i); });
    connect(viewport_, &Viewport::lightPlaced, this, [this](int i) { outliner_->select(Outliner::Kind::Light, i); });
    connect(viewport_, &Viewport::objectClicked, this, [this](int i) { outliner_->select(Outliner::Kind::Object, i); });
    connect(viewport_, &Viewport::message, this, [this](const QString& text) { statusBar()->showMessage(text, 5000); });
    connect(compare_->displayControls(), &DisplayControls::message, this,
            [this](const QString& text) { statusBar()->showMessage(text, 8000); });
    connect(plan_, &PlanView::lightClicked, this, [this](int i) { outliner_->select(Outliner::Kind::Light, i); });
    connect(plan_, &PlanView::message, this, [this](const QString& text) { statusBar()->showMessage(text, 5000); });
    connect(plan_, &PlanView::fieldDrawn, this,
            [this](double x0, double z0, double x1, double z1) { arrangeLights(std::array<double, 4>{x0, z0, x1, z1}); });
    LightSetProperties* sets = propertiesPanel_->lightSetProperties();
    sets->setFileQuestion([this] {
        return dialogs_->open(tr("Luminaire file for the lights"), tr("Photometric files (*.ies *.IES *.ldt *.LDT);;All files (*)"));
    });
    connect(sets, &LightSetProperties::message, this, [this](const QString& text) { statusBar()->showMessage(text, 8000); });
    connect(cameraPanel_, &CameraPanel::message, this, [this](const QString& text) { statusBar()->showMessage(text, 5000); });
    connect(daylightPanel_, &DaylightPanel::message, this, [this](const QString& text) { statusBar()->showMessage(text, 5000); });
    // The plan shows the newest calculation grid on its plane.
    connect(gridPanel_, &GridPanel::resultChanged, this,
            [this] { plan_->setGridResult(gridPanel_->grid(), gridPanel_->layout(), gridPanel_->result()); });
    // Calculation grids drawn in the viewport.
    connect(gridPanel_, &GridPanel::drawRequested, this, [this] { viewport_->setTool(Viewport::Tool::GridRectangle); });
    connect(viewport_, &Viewport::gridRectangleDrawn, this, [this](const V3d& a, const V3d& n, const V3d& b) {
        gridPanel_->setDrawnRectangle(a, n, b);
        findChild<QDockWidget*>("gridDock")->raise();
    });
}

void MainWindow::defaultDockSizes() {
    // The viewport keeps more than half the width (LayoutState); the converged image beside it.
    // Every dock with rows of fields scrolls, so none widens past what is given here.
    const int side = std::max(150, width() / 6);
    const int render = std::max(150, int(width() * (1 - LayoutState::kMinViewportShare)) - side - 20);
    resizeDocks({outlinerDock_, renderDock_}, {side, render}, Qt::Horizontal);
}

MainWindow::ImportTarget MainWindow::askImportTarget() {
    if (askImport_) return askImport_();
    QMessageBox box(QMessageBox::Question, tr("Import model"), tr("Import the model into a new scene or into this one?"),
                    QMessageBox::Cancel, this);
    QPushButton* fresh = box.addButton(tr("New Scene"), QMessageBox::AcceptRole);
    QPushButton* here = box.addButton(tr("This Scene"), QMessageBox::AcceptRole);
    box.setDefaultButton(here);
    box.exec();
    return box.clickedButton() == fresh ? ImportTarget::NewScene
           : box.clickedButton() == here ? ImportTarget::OpenScene
                                         : ImportTarget::Cancel;
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    const auto add = [this](QMenu* menu, const QString& text, const QString& name, const QKeySequence& key,
                            auto slot) {
        QAction* a = menu->addAction(text, this, slot);
        a->setObjectName(name);
        a->setShortcut(key);
        return a;
    };
    add(file, tr("&New"), "actionNew", QKeySequence(tr("Ctrl+N")), [this] {
        if (maybeSave()) newScene();
    });
    add(file, tr("&Open..."), "actionOpen", QKeySequence(tr("Ctrl+O")), [this] {
        if (!maybeSave()) return;
        const QString path = dialogs_->open(tr("Open scene"), tr("Lucerna scenes (*.json)"));
        if (!path.isEmpty() && !openFile(path)) QMessageBox::warning(this, tr("Open scene"), lastError_);
    });
    recent_ = new RecentFilesMenu(
        [this](const QString& path) {
            if (maybeSave() && !openFile(path)) QMessageBox::warning(this, tr("Open scene"), lastError_);
        },
        this);
    file->addMenu(recent_);
    add(file, tr("&Save"), "actionSave", QKeySequence(tr("Ctrl+S")), [this] {
        if (!save() && !lastError_.isEmpty()) QMessageBox::warning(this, tr("Save scene"), lastError_);
    });
    add(file, tr("Save &As..."), "actionSaveAs", QKeySequence(tr("Ctrl+Shift+S")), [this] {
        const QString path = dialogs_->save(tr("Save scene"), tr("Lucerna scenes (*.json)"));
        if (!path.isEmpty() && !saveFileAs(path)) QMessageBox::warning(this, tr("Save scene"), lastError_);
    });
    file->addSeparator();
    add(file, tr("&Export EXR..."), "actionExportExr", QKeySequence(tr("Ctrl+E")), [this] {
        const QString path = dialogs_->save(tr("Export the converged image"), tr("OpenEXR (*.exr)"));
        if (!path.isEmpty() && !exportExr(path)) QMessageBox::warning(this, tr("Export EXR"), lastError_);
    });
    add(file, tr("Export &Preview EXR..."), "actionExportPreviewExr", QKeySequence(tr("Ctrl+Alt+E")), [this] {
        const QString path = dialogs_->save(tr("Export the preview"), tr("OpenEXR (*.exr)"));
        if (!path.isEmpty() && !exportPreviewExr(path)) QMessageBox::warning(this, tr("Export EXR"), lastError_);
    });
    add(file, tr("Export &Both EXR..."), "actionExportBothExr", {}, [this] {
        const QString path = dialogs_->save(tr("Export preview and converged image (NAME-preview.exr, NAME-converged.exr)"), tr("OpenEXR (*.exr)"));
        if (!path.isEmpty() && !exportBothExr(path)) QMessageBox::warning(this, tr("Export EXR"), lastError_);
    });
    add(file, tr("Export P&NG..."), "actionExportPng", QKeySequence(tr("Ctrl+Shift+E")), [this] {
        const QString path = dialogs_->save(tr("Export the converged image as a picture"), tr("PNG (*.png)"));
        if (!path.isEmpty() && !exportPng(path)) QMessageBox::warning(this, tr("Export PNG"), lastError_);
    });
    add(file, tr("Export &Report..."), "actionExportReport", QKeySequence(tr("Ctrl+Shift+R")), [this] {
        QString path = dialogs_->save(tr("Export the lighting design report"), tr("PDF (*.pdf)"));
        if (path.isEmpty()) return;
        if (!path.endsWith(QStringLiteral(".pdf"), Qt::CaseInsensitive)) path += QStringLiteral(".pdf");
        if (!report_->start(doc_->snapshot(), QString::fromStdString(doc_->path()), path))
            statusBar()->showMessage(tr("A report is being computed already"), 5000);
    });
    add(file, tr("&Import Mesh..."), "actionImportMesh", QKeySequence(tr("Ctrl+I")), [this] {
        const QString path = dialogs_->open(tr("Import a mesh"), tr("Meshes (*.obj *.ply *.off *.stl)"));
        if (!path.isEmpty() && !importMeshFile(path)) QMessageBox::warning(this, tr("Import mesh"), lastError_);
    });
    add(file, tr("Import &Model..."), "actionImportModel", QKeySequence(tr("Ctrl+Shift+I")), [this] {
        const QString path = dialogs_->open(
            tr("Import a model"), tr("Models (*.obj *.gltf *.glb *.fbx *.dae *.3ds *.ply *.stl *.blend);;All files (*)"));
        if (path.isEmpty()) return;
        const ImportTarget target = askImportTarget();
        if (target == ImportTarget::Cancel || (target == ImportTarget::NewScene && !maybeSave())) return;
        if (!importModelFile(path, target)) QMessageBox::warning(this, tr("Import model"), lastError_);
    });
    file->addSeparator();
    add(file, tr("&Quit"), "actionQuit", QKeySequence(tr("Ctrl+Q")), [this] { close(); });

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = doc_->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setObjectName("actionUndo");
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = doc_->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setObjectName("actionRedo");
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    add(edit, tr("Add &Point Light"), "actionAddPointLight", QKeySequence(tr("Ctrl+Alt+P")),
        [this] { addLight(LightType::Point); });
    add(edit, tr("Add S&pot Light"), "actionAddSpotLight", QKeySequence(tr("Ctrl+Alt+S")),
        [this] { addLight(LightType::Spot); });
    add(edit, tr("Add &Directional Light"), "actionAddDirectionalLight", QKeySequence(tr("Ctrl+Alt+D")),
        [this] { addLight(LightType::Directional); });
    add(edit, tr("Add &Luminaire..."), "actionAddLuminaire", QKeySequence(tr("Ctrl+Alt+L")), [this] {
        const QString path = dialogs_->open(tr("Add a luminaire"), tr("Photometric files (*.ies *.IES *.ldt *.LDT);;All files (*)"));
        if (!path.isEmpty() && !addLuminaireFile(path)) QMessageBox::warning(this, tr("Add luminaire"), lastError_);
    });
    add(edit, tr("Arrange Li&ghts..."), "actionArrangeLights", QKeySequence(tr("Ctrl+Alt+F")), [this] { arrangeLights(); });
    add(edit, tr("D&uplicate"), "actionDuplicate", QKeySequence(tr("Ctrl+D")), [this] { duplicateSelection(); });
    add(edit, tr("&Delete"), "actionDelete", QKeySequence::Delete, [this] { deleteSelection(); });
    // Placing and aiming by clicking a surface: the viewport's tools, also on a tool bar.
    edit->addSeparator();
    edit->addActions(viewport_->toolActions());
    QToolBar* tools = addToolBar(tr("Tools"));
    tools->setObjectName("toolsToolBar");
    tools->addActions(viewport_->toolActions());

    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->addActions(viewArea_->modeActions());
    view->addSeparator();
    add(view, tr("View &All"), "actionViewAll", QKeySequence(Qt::Key_Home), [this] {
        cameraPanel_->viewAll();
        plan_->fitToScene();
    });
    add(view, tr("&Reset Camera"), "actionResetCamera", QKeySequence(Qt::SHIFT | Qt::Key_Home),
        [this] { cameraPanel_->resetCamera(); });
    view->addSeparator();
    for (QDockWidget* d : findChildren<QDockWidget*>()) view->addAction(d->toggleViewAction());
    view->addSeparator();
    add(view, tr("&Reset Layout"), "actionResetLayout", {}, [this] { layout_->reset(); });

    // The menus' shortcuts work whatever has the focus, a dock (floating ones too) included; a
    // text field still takes the keys it edits with (Qt asks it first).
    for (QAction* menuAction : menuBar()->actions())
        if (QMenu* menu = menuAction->menu())
            for (QAction* a : menu->actions())
                if (!a->shortcut().isEmpty()) a->setShortcutContext(Qt::ApplicationShortcut);
}

void MainWindow::fail(const QString& message) {
    lastError_ = message;
    statusBar()->showMessage(message);
}

bool MainWindow::openFile(const QString& path) {
    Scene scene;
    try {
        scene = loadScene(path.toStdString());
    } catch (const std::exception& e) {
        fail(QString::fromStdString(e.what()));
        return false;
    }
    doc_->reset(std::move(scene));
    doc_->setPath(QFileInfo(path).absoluteFilePath().toStdString());
    render_->start();
    // The recovery file was the previous scene's, whose changes were saved or let go.
    if (autosave_) autosave_->discard();
    if (recent_) recent_->add(path);
    statusBar()->showMessage(tr("Opened %1").arg(QFileInfo(path).fileName()), 5000);
    return true;
}

void MainWindow::newScene() {
    doc_->reset(newSceneWithFloor(dialogs_->folder().toStdString()));
    doc_->setPath({});
    render_->start();
    if (autosave_) autosave_->discard();
    statusBar()->showMessage(tr("New scene"), 5000);
}

bool MainWindow::save() {
    if (doc_->path().empty()) {
        const QString path = dialogs_->save(tr("Save scene"), tr("Lucerna scenes (*.json)"));
        return !path.isEmpty() && saveFileAs(path);
    }
    return saveFileAs(QString::fromStdString(doc_->path()));
}

bool MainWindow::saveFileAs(const QString& path) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    // Mesh files are named relative to the scene's folder: rebase them on the new folder, so that
    // the saved file finds the same meshes.
    Scene scene = doc_->scene();
    const QDir newDir = QFileInfo(absolute).absoluteDir();
    for (Object& o : scene.objects)
        if (o.mesh.kind == MeshSource::Kind::File && !std::filesystem::path(o.mesh.file).is_absolute()) {
            const QString meshPath = QDir(QString::fromStdString(scene.baseDir)).absoluteFilePath(QString::fromStdString(o.mesh.file));
            o.mesh.file = newDir.relativeFilePath(meshPath).toStdString();
        }
    try {
        saveScene(scene, absolute.toStdString());
    } catch (const std::exception& e) {
        fail(tr("Could not save %1: %2").arg(path, QString::fromStdString(e.what())));
        return false;
    }
    if (newDir.absolutePath() != QDir(QString::fromStdString(doc_->scene().baseDir)).absolutePath()) {
        // Reload so that the document's folder and mesh paths are the saved file's. Not undoable
        // across the save, as in any editor after Save As to another folder.
        if (!openFile(absolute)) return false;
    } else {
        doc_->setPath(absolute.toStdString());
        doc_->markSaved();
    }
    if (autosave_) autosave_->discard();
    recent_->add(absolute);
    statusBar()->showMessage(tr("Saved %1").arg(QFileInfo(path).fileName()), 5000);
    return true;
}

bool MainWindow::exportExr(const QString& path) {
    const auto frame = render_->frame();
    if (!frame) {
        fail(tr("Nothing to export yet: the converging render has no frame."));
        return false;
    }
    try {
        writeExr(path.toStdString(), convergedExportImage(*frame, render_->scene()));
    } catch (const std::exception& e) {
        fail(QString::fromStdString(e.what()));
        return false;
    }
    statusBar()->showMessage(tr("Exported %1 (%2 spp)").arg(path).arg(frame->samplesPerPixel), 5000);
    return true;
}

bool MainWindow::exportPreviewExr(const QString& path) {
    const auto frame = preview_->frame();
    if (!frame) {
        fail(tr("Nothing to export yet: the preview has no frame."));
        return false;
    }
    try {
        writeExr(path.toStdString(), previewExportImage(*frame, preview_->engineDescription()));
    } catch (const std::exception& e) {
        fail(QString::fromStdString(e.what()));
        return false;
    }
    statusBar()->showMessage(tr("Exported %1").arg(path), 5000);
    return true;
}

bool MainWindow::exportBothExr(const QString& path) {
    // Two files: the two images differ in size (the preview draws at a reduced resolution).
    return exportPreviewExr(exportSibling(path, "-preview")) && exportExr(exportSibling(path, "-converged"));
}

bool MainWindow::exportPng(const QString& path) {
    const auto frame = render_->frame();
    if (!frame) {
        fail(tr("Nothing to export yet: the converging render has no frame."));
        return false;
    }
    try {
        writePng(toDisplayImage(frame->image, compare_->displaySettings()), path);
    } catch (const std::exception& e) {
        fail(QString::fromStdString(e.what()));
        return false;
    }
    statusBar()->showMessage(tr("Exported %1").arg(path), 5000);
    return true;
}

bool MainWindow::importMeshFile(const QString& path) {
    MeshImport imported;
    try {
        imported = importMesh(*doc_, path);
    } catch (const std::exception& e) {
        fail(tr("Could not import %1: %2").arg(path, QString::fromStdString(e.what())));
        return false;
    }
    const QString text = tr("Import %1").arg(QString::fromStdString(imported.object.name));
    doc_->undoStack()->push(new AddObjectCommand(doc_.get(), std::move(imported.object), std::move(imported.material), text));
    outliner_->select(Outliner::Kind::Object, int(doc_->scene().objects.size()) - 1);
    statusBar()->showMessage(tr("Imported %1").arg(path), 5000);
    return true;
}

bool MainWindow::importModelFile(const QString& path, ImportTarget target) {
    if (target == ImportTarget::Cancel) return false;
    QStringList report;
    try {
        const Camera before = doc_->scene().camera;
        if (target == ImportTarget::NewScene) {
            // A new document, not an undo step of the old one.
            doc_->reset(newSceneWithModel(path, &report));
            doc_->setPath({});
            doc_->undoStack()->resetClean();  // an untitled scene with content is unsaved work
            render_->start();
            if (autosave_) autosave_->discard();
        } else {
            report = importModelInto(doc_.get(), path);
        }
        // A camera the import placed (in the largest room) is the one Reset Camera returns to.
        if (doc_->scene().camera != before) cameraPanel_->setHomeCamera(doc_->scene().camera);
    } catch (const std::exception& e) {
        fail(tr("Could not import %1: %2").arg(path, QString::fromStdString(e.what())));
        return false;
    }
    statusBar()->showMessage(report.value(0), 8000);
    ImportReportDialog::present(this, path, report);
    return true;
}

bool MainWindow::startAutosave(const QString& directory, int intervalMs) {
    QString error;
    std::optional<Autosave::Recovery> recovery = Autosave::pending(directory, &error);
    if (!error.isEmpty()) fail(tr("A recovery file could not be read: %1").arg(error));
    bool recovered = false;
    if (recovery) {
        const QString name = recovery->documentPath.empty() ? tr("an untitled scene")
                                                            : QString::fromStdString(recovery->documentPath);
        const QMessageBox::StandardButton answer =
            askRecovery_ ? askRecovery_()
                         : QMessageBox::question(this, tr("Recover unsaved changes"),
                                                 tr("Lucerna did not close cleanly. Recover the unsaved changes to %1?")
                                                     .arg(name),
                                                 QMessageBox::Yes | QMessageBox::No);
        if (answer == QMessageBox::Yes) {
            doc_->reset(std::move(recovery->scene));
            doc_->setPath(recovery->documentPath);
            doc_->undoStack()->resetClean();  // recovered work is unsaved work
            render_->start();
            statusBar()->showMessage(tr("Recovered the unsaved changes to %1").arg(name), 5000);
            recovered = true;
        }
        Autosave::discard(directory);
    }
    autosave_ = std::make_unique<Autosave>(*doc_, directory, intervalMs);
    return recovered;
}

bool MainWindow::maybeSave() {
    if (!doc_->isModified()) return true;
    const QMessageBox::StandardButton answer =
        ask_ ? ask_()
             : QMessageBox::warning(this, tr("Unsaved changes"), tr("The scene has unsaved changes. Save them?"),
                                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

int MainWindow::selectedLight() const {
    const Outliner::Selection s = outliner_->selection();
    return s.kind == Outliner::Kind::Light ? s.index : -1;
}

void MainWindow::addLight(LightType type) {
    const char* base = type == LightType::Point ? "point" : type == LightType::Spot ? "spot" : "sun";
    const int index = int(doc_->scene().lights.size());
    Light light = defaultLight(doc_->scene(), type, doc_->uniqueName(base));
    doc_->undoStack()->push(new AddLightCommand(doc_.get(), index, light,
                                                tr("Add %1").arg(QString::fromStdString(light.name))));
    outliner_->select(Outliner::Kind::Light, index);
}

bool MainWindow::addLuminaireFile(const QString& path) {
    Light light;
    try {
        light = luminaireFromFile(*doc_, path);
    } catch (const std::exception& e) {
        fail(tr("Could not add %1: %2").arg(path, QString::fromStdString(e.what())));
        return false;
    }
    const int index = int(doc_->scene().lights.size());
    const QString text = tr("Add %1").arg(QString::fromStdString(light.name));
    doc_->undoStack()->push(new AddLightCommand(doc_.get(), index, std::move(light), text));
    outliner_->select(Outliner::Kind::Light, index);
    return true;
}

void MainWindow::duplicateSelection() {
    const int index = selectedLight();
    if (index < 0) return;
    Light light = doc_->scene().lights[size_t(index)];
    if (light.type == LightType::Sun) {
        fail(tr("A scene has one sun at most: it is not duplicated."));
        return;
    }
    light.name = doc_->uniqueName(light.name);
    doc_->undoStack()->push(new AddLightCommand(doc_.get(), index + 1, light,
                                                tr("Duplicate %1").arg(QString::fromStdString(light.name))));
    outliner_->select(Outliner::Kind::Light, index + 1);
}

void MainWindow::arrangeLights(const std::optional<std::array<double, 4>>& rectangle) {
    ArrangementDialog dialog(*doc_, selectedLight(), this);
    dialog.setFileQuestion([this] {
        return dialogs_->open(tr("Luminaire of the field"), tr("Photometric files (*.ies *.IES *.ldt *.LDT);;All files (*)"));
    });
    if (rectangle) dialog.setRectangle((*rectangle)[0], (*rectangle)[1], (*rectangle)[2], (*rectangle)[3]);
    if (dialog.exec() != QDialog::Accepted) return;
    try {
        arrangeField(dialog.arrangement(), dialog.prototype(), QString::fromStdString(dialog.group()));
    } catch (const std::exception& e) {
        fail(QString::fromStdString(e.what()));  // the dialog checked the file a moment ago
    }
}

bool MainWindow::arrangeField(const FieldArrangement& field, const Light& prototype, const QString& group) {
    QElapsedTimer clock;
    clock.start();
    int count = 0;
    try {
        count = lucerna::arrangeField(*doc_, field, prototype, group.toStdString());
    } catch (const std::exception& e) {
        fail(tr("No field arranged: %1").arg(QString::fromStdString(e.what())));
        return false;
    }
    outliner_->selectGroup(group.toStdString());
    statusBar()->showMessage(tr("Arranged %1 lights in group %2 (%3 ms)").arg(count).arg(group).arg(clock.elapsed()), 8000);
    return true;
}

void MainWindow::deleteSelection() {
    const Outliner::Selection s = outliner_->selection();
    if (s.kind == Outliner::Kind::Group || s.kind == Outliner::Kind::Lights) {
        std::vector<char> gone(doc_->scene().lights.size(), 0);
        for (int i : s.lights) gone[size_t(i)] = 1;
        std::vector<Light> kept;
        for (size_t i = 0; i < gone.size(); ++i)
            if (!gone[i]) kept.push_back(doc_->scene().lights[i]);
        const QString text = s.kind == Outliner::Kind::Group ? tr("Delete group %1").arg(QString::fromStdString(s.group))
                                                             : tr("Delete %1 lights").arg(s.lights.size());
        doc_->undoStack()->push(new ReplaceLightsCommand(doc_.get(), std::move(kept), text));
    } else if (s.kind == Outliner::Kind::Light)
        doc_->undoStack()->push(new DeleteLightCommand(doc_.get(), s.index));
    else if (s.kind == Outliner::Kind::Object)
        doc_->undoStack()->push(new DeleteObjectCommand(doc_.get(), s.index));
}

void MainWindow::showPreviewFrame() {
    const auto frame = preview_->frame();
    if (!frame) {
        viewport_->showNoFrame(preview_->error());
        compare_->setPreview({});
        previewInfo_->setText(preview_->error().isEmpty() ? QString() : tr("Preview: failed"));
        return;
    }
    viewport_->setImage(toDisplayImage(frame->image, compare_->displaySettings()));
    compare_->setPreview(frame->image);
    previewInfo_->setText(previewStatusText(preview_->engineDescription(), *frame));
}

void MainWindow::updateTitle() {
    const QString name = doc_->path().empty() ? tr("untitled") : QFileInfo(QString::fromStdString(doc_->path())).fileName();
    setWindowTitle(tr("%1[*] - Lucerna").arg(name));
    setWindowModified(doc_->isModified());
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    if (autosave_) autosave_->closedCleanly();  // saved, or the changes discarded
    layout_->save();
    event->accept();
}

}  // namespace lucerna
