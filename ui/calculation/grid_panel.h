#pragma once
// The calculation-grid dock: a work plane over the room (height, border, spacing by EN 12464-1
// unless set) or a rectangle drawn in the viewport on a floor, a table or a wall (two corner
// clicks; core/photometry/calculation_grid.h, gridFromCorners), its illuminance computed in the background with a Monte Carlo error bar per point
// (render/photometry/grid_calculation.h), shown as a false-colour table in lux with Eavg, Emin,
// Emax and U0 (points inside geometry grey, hatched and left out; a method that cannot carry
// light through glass flagged: render/photometry/grid_diagnosis.h), in the words of
// render/photometry/grid_text.h (the figures scroll in a pane above the table, a divider between
// them, so that a task area's thirty lines leave the table readable), and exported as CSV. A scene edit that changes the light
// (core/scene/scene_change.h: not a camera move) marks the result as out of date; Compute runs
// again on the current scene. The calculation is a foreground request: it runs in a task arena of
// its own (in the converging render's, whose job never ends, it could wait behind the render's
// passes indefinitely) and holds the yield gate, so the render waits until it is done.
// The quantity UGR puts an observer over each point, at eye height above the floor (seated 1.2 m
// or standing 1.7 m), all looking along one edge of the grid, and shows each one's UGR
// (render/photometry/ugr_grid.h, ui/calculation/ugr_table.h).
// The scene's task areas (README, "Task areas") are offered as areas too: computed on their own
// rectangle and spacing, as `lucerna grid --task-area` and the report compute them, with the
// activity's requirements checked under the figures (core/photometry/lighting_standards.h: met,
// borderline within the error bar, not met; Em not checked without a maintenance factor). A task
// area's surrounding zone and background area are computed with it and their figures and checks
// follow its own (render/photometry/zone_grids.h). After a task area's Em grid, the figures
// EN 12464-1:2021 adds (Ez at the posture's height, the room's walls and ceiling) are computed
// as a second job, with progress and Cancel, where its requirement asks for them or the designer
// ticks them (task areas only), and checked with the rest (ui/calculation/task_area_extras.h).

#include "core/photometry/calculation_grid.h"
#include "core/photometry/lighting_standards.h"
#include "core/task_system.h"
#include "render/photometry/grid_calculation.h"
#include "render/photometry/ugr_grid.h"
#include "ui/calculation/task_area_extras.h"
#include "render/photometry/zone_grids.h"
#include "ui/document/document.h"
#include "ui/rendering/yield_gate.h"

#include <QTimer>
#include <QWidget>

#include <memory>
#include <optional>
#include <string>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace lucerna {

class GridPanel : public QWidget {
    Q_OBJECT
public:
    GridPanel(Document* doc, const YieldGate& gate, QWidget* parent = nullptr);
    ~GridPanel() override;

    void compute();   // starts on the document's current scene (cancels a running calculation)
    void cancel();
    // The grid becomes the rectangle drawn with corners a (on a surface of unit normal `normal`,
    // facing the viewer) and b, lifted by the height field; "Whole room" goes back to the work plane.
    void setDrawnRectangle(const V3d& a, const V3d& normal, const V3d& b);
    void useWholeRoom();
    // The grid becomes the scene's task area `index` (in Scene::taskAreas).
    void useTaskArea(int index);
    bool isComputing() const { return job_ != nullptr; }
    // The running job is the task area's 2021 figures' (its Em grid has finished).
    bool isComputingExtras() const { return job_ && extras_.state() == TaskAreaExtrasFigures::State::Computing; }
    // The scene changed since the shown result was computed in a way that changes its values.
    bool resultOutOfDate() const { return stale_; }
    // The newest result and its layout (null before the first pass of a calculation).
    std::shared_ptr<const GridResult> result() const { return shown_; }
    const GridLayout& layout() const { return layout_; }
    // The rectangle of the newest calculation (its normal says which views can show it).
    const CalculationGrid& grid() const { return grid_; }
    // Writes the shown result as CSV (core/photometry/calculation_grid.h); throws std::runtime_error.
    void exportCsv(const QString& path) const;
    // With the quantity "Daylight factor", 100 / Eh,sky of the newest calculation (SPEC.md
    // section 5: it ran on the daylight-factor scene, and the result's lux times this is DF in %).
    std::optional<double> daylightFactorPerLux() const { return dfPerLux_; }
    // With the quantity "UGR": the newest result (null before the first pass), the eyes and the
    // view of the newest calculation.
    std::shared_ptr<const GlareGridResult> glareResult() const { return shownGlare_; }
    const std::vector<V3d>& observers() const { return eyes_; }
    const V3d& observerView() const { return view_; }

signals:
    // The user asked to draw the rectangle in the viewport (two clicks there).
    void drawRequested();
    void resultChanged();
    void finished();

private:
    static constexpr int kAutoMethod = -1;  // the estimator box's item for auto
    enum Quantity { kIlluminance = 0, kDaylightFactor = 1, kUgr = 2 };  // the quantity box's items

    void poll();
    // The Em grid's job finished: the task area's 2021 figures start, if asked (true).
    bool startExtras();
    void showResult();
    // The figures' text of the shown result (showResult, and the 2021 figures' lines as they change).
    void showFigures();
    void showGlareResult();
    void quantityChanged();
    void sceneChanged();
    // The UGR grid's calculation over `grid` of `scene` (compute() with the quantity UGR).
    void computeUgr(const SceneSnapshot& scene, const CalculationGrid& grid);
    void exportClicked();
    // The task areas offered follow the scene's.
    void listTaskAreas();
    void areaChosen();
    // Back to the work plane or a drawn rectangle: the height and spacing fields are the user's again.
    void leaveTaskArea();
    // The 2021 figures' boxes: for a task area's illuminance only.
    void enableExtras();
    // The activity's checks on the shown result (none without a task area with an activity).
    QStringList requirementLines(const GridStatistics& s) const;

    Document* doc_;
    YieldGate gate_;
    QDoubleSpinBox *height_, *border_, *spacing_, *target_;
    QComboBox *method_, *quantity_, *eyeHeight_, *viewAlong_, *areaChoice_;
    QCheckBox *cylindrical_, *roomSurfaces_;  // the task area's 2021 figures to compute
    QPushButton *compute_, *cancel_, *export_, *draw_, *wholeRoom_;
    QProgressBar* progress_;
    QLabel *area_, *figures_, *status_;
    QTableWidget* table_;
    QTimer poll_;

    struct Drawn {
        V3d a, normal, b;
    };
    std::optional<Drawn> drawn_;  // nothing: the work plane over the whole room
    std::optional<std::string> taskArea_;  // the task area's name, when one is chosen
    double userSpacing_ = 0;               // the spacing field's value while a task area shows its own
    const ActivityRequirement* requirement_ = nullptr;  // of the newest calculation's task area
    CalculationGrid grid_;
    GridLayout layout_;
    std::shared_ptr<Latest<GridResult>> latest_;
    TaskSystem tasks_;  // before job_: the job ends before its arena goes
    std::shared_ptr<TaskHandle> job_;
    std::shared_ptr<const GridResult> shown_;
    ZoneGrids zones_;                      // the chosen task area's zones (empty: none)
    TaskAreaExtrasFigures extras_;           // its 2021 figures, after its Em grid
    GridSettings settings_;                  // the Em grid's, for the 2021 figures
    QString doneText_;                       // the Em grid's "Done: ..."
    std::shared_ptr<const GridResult> all_;  // with zones: the result over the task area's points and theirs
    uint64_t shownVersion_ = 0;
    SceneSnapshot resultScene_;  // the document's scene when the calculation started
    bool stale_ = false;
    std::optional<double> dfPerLux_;
    QString maintenance_;  // which illuminance the result is: maintained or the new installation's
    double medianDiffuseIlluminance_ = 0;  // lx, for EN 17037's check (the site's, or the usual value)
    bool medianGiven_ = false;
    // The UGR grid.
    std::shared_ptr<Latest<GlareGridResult>> latestGlare_;
    std::shared_ptr<const GlareGridResult> shownGlare_;
    std::vector<V3d> eyes_;
    V3d view_{1, 0, 0};
    double eyeHeightM_ = 1.2;
    std::string viewLabel_;
};

}  // namespace lucerna
