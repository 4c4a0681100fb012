#include "ui/window/main_window.h"

#include "core/resources.h"
#include "render/display/display.h"
#include "render/display/false_colour.h"
#include "render/display/white_balance.h"
#include "ui/calculation/annual_panel.h"
#include "ui/calculation/grid_panel.h"
#include "ui/calculation/report_export.h"
#include "ui/compare/compare_view.h"
#include "ui/io/file_dialogs.h"
#include "ui/plan/plan_view.h"
#include "ui/plan/room_drawing.h"
#include "ui/properties/light_properties.h"
#include "ui/properties/light_set_properties.h"
#include "ui/properties/properties_panel.h"
#include "ui/rendering/converging_render.h"
#include "ui/rendering/display_controls.h"
#include "ui/rendering/live_preview.h"
#include "ui/rendering/render_panel.h"
#include "ui/scene_panels/camera_panel.h"
#include "ui/scene_panels/daylight_panel.h"
#include "ui/scene_panels/outliner.h"
#include "ui/scene_panels/project_dialog.h"
#include "ui/viewport/viewport.h"
#include "ui/window/help_actions.h"
#include "ui/window/layout_state.h"
#include "ui/window/menu_entry.h"
#include "ui/window/room_actions.h"
#include "ui/window/task_area_actions.h"
#include "ui/window/view_area.h"
#include "ui/window/wheel_guard.h"

#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QScreen>
#include <QScrollArea>
#include <QStatusBar>
#include <QToolBar>

namespace lucerna {

MainWindow::MainWindow(const QString& scenePath, QWidget* parent)
    : QMainWindow(parent), doc_(std::make_unique<Document>(Scene{})), messages_(this),
      render_(std::make_unique<ConvergingRender>(tasks_, gate_)),
      preview_(std::make_unique<LivePreview>(gate_, LivePreview::engineFromEnvironment())) {
    setObjectName("MainWindow");
    new WheelGuard(this);  // the docks' wheels scroll them, never edit an unfocused field
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
    createMenus();
    previewInfo_ = new QLabel(this);
    statusBar()->addPermanentWidget(previewInfo_);

    // Every edit reaches both images: the preview draws the newest snapshot, the converging
    // render restarts on it. A new scene never shows the old one's frame meanwhile.
    connect(doc_.get(), &Document::replaced, preview_.get(), &LivePreview::dropFrame);
    connect(doc_.get(), &Document::changed, this, [this] {
        preview_->setScene(doc_->snapshot());
        render_->setScene(doc_->snapshot());
        compare_->setLightsWhite(lightsWhite(*doc_->snapshot()));
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
    annualPanel_ = new AnnualPanel(doc_.get(), gate_, this);
    annualPanel_->setObjectName("annualPanel");
    tabifyDockWidget(renderDock, dock(annualPanel_, tr("Annual daylight"), "annualDock", Qt::RightDockWidgetArea, true));
    renderDock->raise();
    renderDock_ = renderDock;
    outlinerDock_ = outlinerDock;

    connect(outliner_, &Outliner::selectionChangedTo, this, [this](Outliner::Selection s) {
        const int light = s.kind == Outliner::Kind::Light ? s.index : -1;
        propertiesPanel_->showSelection(s);
        viewport_->setSelectedLight(light);
        viewport_->setSelectedLights(s.lights);
        plan_->setSelectedLight(light);
        plan_->setSelectedLights(s.lights);
        plan_->setSelectedTaskArea(s.kind == Outliner::Kind::TaskArea ? s.index : -1);
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
            [this](double x0, double z0, double x1, double z1) { edits_->arrangeLights(std::array<double, 4>{x0, z0, x1, z1}); });
    connect(plan_, &PlanView::taskAreaDrawn, this,
            [this](double x0, double z0, double x1, double z1) { taskAreas_->addDrawnTaskArea(x0, z0, x1, z1); });
    connect(plan_, &PlanView::taskAreaClicked, this, [this](int i) { outliner_->select(Outliner::Kind::TaskArea, i); });
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
    // Or the Annual dock's metric per point, whichever was computed or chosen last.
    connect(annualPanel_, &AnnualPanel::resultChanged, this, [this] {
        plan_->setGridResult(annualPanel_->grid(), annualPanel_->layout(), annualPanel_->planValues(), annualPanel_->planUnit());
    });
    // A year computed in the dock puts its weather file in the next report (an annual section).
    connect(annualPanel_, &AnnualPanel::finished, this, [this] {
        if (!annualPanel_->result() || !annualPanel_->weatherFile()) return;
        ReportSettings settings = report_->settings();
        settings.weather = annualPanel_->weatherFile();
        settings.weatherPath = annualPanel_->weatherPath().toStdString();
        settings.occupancy = annualPanel_->occupancy();
        report_->setSettings(settings);
    });
    daylightPanel_->setWeatherQuestion(
        [this] { return dialogs_->open(tr("Weather file"), tr("EnergyPlus weather files (*.epw *.EPW);;All files (*)")); });
    annualPanel_->setFileQuestion(
        [this] { return dialogs_->open(tr("Weather file"), tr("EnergyPlus weather files (*.epw *.EPW);;All files (*)")); });
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

void MainWindow::createMenus() {
    files_ = std::make_unique<FileActions>(*doc_, *render_, *dialogs_, messages_);
    exports_ = std::make_unique<ExportActions>(*doc_, *render_, *preview_, *report_, *compare_, *dialogs_, messages_);
    imports_ = std::make_unique<ImportActions>(*doc_, *files_, *outliner_, *cameraPanel_, *dialogs_, messages_);
    edits_ = std::make_unique<EditActions>(*doc_, *files_, *outliner_, *dialogs_, messages_);
    taskAreas_ = std::make_unique<TaskAreaActions>(*doc_, *outliner_, messages_);
    rooms_ = std::make_unique<RoomActions>(*doc_, *outliner_, messages_);
    edits_->setRoomActions(rooms_.get());
    connect(plan_->roomDrawing(), &RoomDrawing::outlineDrawn, this,
            [this](const PlanPolygon& outline) { rooms_->addRoomInteractively(outline); });
    // A double click on a room or an opening opens its dialog.
    connect(outliner_, &QTreeWidget::itemDoubleClicked, this, [this] {
        const Outliner::Kind kind = outliner_->selection().kind;
        if (kind == Outliner::Kind::Room) rooms_->editRoomInteractively();
        else if (kind == Outliner::Kind::Opening) rooms_->editOpeningInteractively();
    });

    QMenu* file = menuBar()->addMenu(tr("&File"));
    files_->addTo(file);
    file->addSeparator();
    // The project's details and the scene's maintenance factor, one undo step on OK.
    addMenuEntry(file, tr("Project Se&ttings..."), "actionProjectSettings", {}, this, [this] {
        ProjectDialog dialog(doc_.get(), this);
        dialog.exec();
    });
    file->addSeparator();
    exports_->addTo(file);
    imports_->addTo(file);
    file->addSeparator();
    addMenuEntry(file, tr("&Quit"), "actionQuit", QKeySequence(tr("Ctrl+Q")), this, [this] { close(); });

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edits_->addTo(edit);
    taskAreas_->addTo(edit);
    // Placing and aiming by clicking a surface: the viewport's tools, also on a tool bar.
    edit->addSeparator();
    edit->addActions(viewport_->toolActions());
    QToolBar* tools = addToolBar(tr("Tools"));
    tools->setObjectName("toolsToolBar");
    tools->addActions(viewport_->toolActions());

    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->addActions(viewArea_->modeActions());
    view->addSeparator();
    addMenuEntry(view, tr("View &All"), "actionViewAll", QKeySequence(Qt::Key_Home), this, [this] {
        cameraPanel_->viewAll();
        plan_->fitToScene();
    });
    addMenuEntry(view, tr("&Reset Camera"), "actionResetCamera", QKeySequence(Qt::SHIFT | Qt::Key_Home), this,
                 [this] { cameraPanel_->resetCamera(); });
    view->addAction(plan_->labelsAction());
    view->addSeparator();
    for (QDockWidget* d : findChildren<QDockWidget*>()) view->addAction(d->toggleViewAction());
    view->addSeparator();
    addMenuEntry(view, tr("&Reset Layout"), "actionResetLayout", {}, this, [this] { layout_->reset(); });

    (new HelpActions(*this, messages_))->addTo(menuBar()->addMenu(tr("&Help")));

    // The menus' shortcuts work whatever has the focus, a dock (floating ones too) included; a
    // text field still takes the keys it edits with (Qt asks it first).
    for (QAction* menuAction : menuBar()->actions())
        if (QMenu* menu = menuAction->menu())
            for (QAction* a : menu->actions())
                if (!a->shortcut().isEmpty()) a->setShortcutContext(Qt::ApplicationShortcut);
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
    if (!files_->maybeSave()) {
        event->ignore();
        return;
    }
    files_->closedCleanly();
    layout_->save();
    event->accept();
}

}  // namespace lucerna
