#pragma once
// The plan view: the scene seen orthographically from above (the plan) or from the front or the
// side (elevations), drawn with QPainter, as DIALux users place luminaires. The geometry is cut
// (render/display/plan_projection.h; in the plan above three quarters of the scene's height, so ceilings do not hide the room; in
// the elevations at the middle of the depth, a section) and drawn farthest first, faces filled in
// a light shade of their material and walls seen edge-on as dark lines. Lights are symbols with
// their names: a circle with a cross for a point light, a circle with a wedge along its axis for
// a spot, a square with a cross for a luminaire (directional lights have no position); the scene
// camera is a dot with its field of view.
// The newest calculation grid facing the view is drawn on its plane in false colour, with
// iso-lux lines and a legend as the report's plans have them (render/display/plan_scales.h), on
// the scale the bar's choice gives (the plan's own, linear, logarithmic or bands); a task area's
// grid has its required Em marked on the legend, in the middle of the ramp.
// The mouse and keys (ui/plan/plan_interaction.h):
// - Left drag on a light moves it in the view's plane (the plan: x and z, y unchanged), its
//   moved coordinates snapped to the snap step (a grid in metres, drawn faintly); one undo step
//   per drag. A click selects it.
// - Left drag elsewhere, or a right or middle drag, pans; the wheel zooms about the cursor.
// - Draw field (the bar's button, the plan only): a left drag draws the rectangle of a field of
//   luminaires (snapped like a move), which the window's arrangement dialog then fills.
// - Draw task area (the bar's button, the plan only; ui/plan/task_area_drawing.h): two corners
//   give a task area's rectangle. The scene's task areas are drawn in the plan
//   (ui/plan/task_area_outlines.h); a click on one selects it.
// Lights of a group carry no name each: the group's name stands once by the box around them,
// so a field of thousands draws as a field.

#include "core/photometry/calculation_grid.h"
#include "render/display/plan_projection.h"
#include "render/display/luminaire_symbols.h"
#include "render/display/plan_scales.h"
#include "render/photometry/grid_calculation.h"
#include "ui/document/document.h"
#include "ui/rendering/yield_gate.h"

#include <QWidget>

#include <memory>
#include <optional>

class QAction;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QToolButton;

namespace lucerna {

class PlanInteraction;
class TaskAreaDrawing;
class RoomDrawing;
class TaskAreaOutlines;

class PlanView : public QWidget {
    Q_OBJECT
public:
    // Which way the view looks: down -y (plan), along -z (front elevation), along -x (side).
    using Projection = PlanAxis;
    // A light's symbol's radius, widget pixels.
    static constexpr double kSymbolRadius = 7.0;

    PlanView(Document* doc, const YieldGate& gate, QWidget* parent = nullptr);
    ~PlanView() override;

    Projection projection() const { return projection_; }
    void setProjection(Projection projection);
    void setSelectedLight(int index);
    // Lights shown selected together (a group or a multi-selection), besides the one above.
    void setSelectedLights(const std::vector<int>& lights);
    // The task area shown selected (-1: none).
    void setSelectedTaskArea(int index);
    int selectedTaskArea() const { return selectedTaskArea_; }

    // The field tool: the next left drag in the plan draws a field's rectangle.
    QToolButton* drawFieldButton() const { return drawField_; }
    void setDrawingField(bool on);
    // The task area tool: two corners clicked in the plan give a task area's rectangle.
    QToolButton* drawTaskAreaButton() const;
    // The room tool (ui/plan/room_drawing.h): a rectangle or polygon drawn in the plan gives a
    // room's outline; it also draws the scene's rooms.
    RoomDrawing* roomDrawing() const { return roomDrawing_; }
    // The calculation grid to draw (its rectangle, layout and newest result; null: none).
    // `unit` labels the legend: the values may be another quantity than lux (the Annual dock's
    // metrics per point, in result->lux).
    void setGridResult(const CalculationGrid& grid, const GridLayout& layout, std::shared_ptr<const GridResult> result,
                       const QString& unit = QString());

    // Snapping of moved lights: a step in metres, 0 for none.
    double snapMeters() const;
    void setSnapMeters(double meters);

    // Frames the geometry and the lights.
    void fitToScene();

    // Widget position of a world point in the current view.
    QPointF widgetOf(const V3d& world) const;
    // The plan coordinates (planPoint's) under a widget position.
    QPointF planOfWidget(const QPointF& widget) const;
    // The widget position of plan coordinates.
    QPointF widgetOfPlanPoint(const QPointF& plan) const { return widgetOfPlan(plan); }
    // The user frames the view (the mouse's pan and zoom): it is fitted to the scene again only
    // when the projection, the widget's size or the scene changes.
    void panBy(const QPointF& pixels);
    // Scales by `factor` about a widget point, which stays where it is.
    void zoomAbout(const QPointF& widget, double factor);
    // The widget position of a light's symbol (nothing for directional lights).
    std::optional<QPointF> lightSymbol(int index) const;
    // The false-colour legend of the grid drawn now (nothing without a grid shown), on the
    // chosen scale. A task area's grid whose activity states Em has it as the legend's target,
    // and its colours centre on it (requirementScale: 0 to 2 Em), as in the report.
    std::optional<Legend> gridLegend() const;
    // The legend's scale: nothing for the plan's own (planScale's), else the one given.
    void setLegendScale(std::optional<LegendScale> scale);
    std::optional<LegendScale> legendScale() const;

    // Shows or hides the lights' names (the View menu's Luminaire Labels; checkable, on).
    QAction* labelsAction() const { return labels_; }
    // The lights' names' rectangles as last painted, and the legends' (the false-colour legend's
    // box, the key of light types), widget pixels.
    const std::vector<QRectF>& visibleLabelRects() const { return labelRects_; }
    const std::vector<QRectF>& legendRects() const { return legendRects_; }
    // The scene changed since the grid's result was computed in a way that changes its values
    // (lights, geometry, materials): the plan says so over the grid.
    bool gridOutOfDate() const;
    // The iso-lux levels drawn now.
    const std::vector<double>& isoLevelsShown() const { return gridScale_.levels; }
    // The colours the view draws lights and iso-lux lines in (for tests reading pixels back).
    static QColor lightColour();
    static QColor selectionColour();
    static QColor isoLineColour();
    static QColor cameraColour();

signals:
    void lightClicked(int index);
    // A field's rectangle drawn in the plan: corners (x0, z0) and (x1, z1), scene units.
    void fieldDrawn(double x0, double z0, double x1, double z1);
    // A task area's rectangle drawn in the plan: corners (x0, z0) and (x1, z1), scene units.
    void taskAreaDrawn(double x0, double z0, double x1, double z1);
    void taskAreaClicked(int index);
    void message(const QString& text);

protected:
    void paintEvent(QPaintEvent*) override;
    void resizeEvent(QResizeEvent*) override;

private:
    QPointF widgetOfPlan(const QPointF& plan) const;
    // The faces of the geometry (planFaces), built again only when the geometry, the materials
    // or the projection changed since they were (not when a light or the camera moves: a drag
    // redraws at every step).
    const std::vector<PlanFace>& faces();
    QTransform planToWidget() const;
    void paintSnapGrid(QPainter& painter) const;
    void paintCalculationGrid(QPainter& painter) const;
    void paintLights(QPainter& painter) const;
    // Returns the groups' captions' rectangles.
    std::vector<QRectF> paintGroups(QPainter& painter) const;
    // Where the legends go this time (the false-colour legend's box, the key's): set in
    // legendRects_ before the names are placed.
    void layOutLegends(const QFont& font);
    void paintLabels(QPainter& painter, const std::vector<QRectF>& groupCaptions);
    void paintLegends(QPainter& painter) const;
    void paintField(QPainter& painter) const;
    void paintCamera(QPainter& painter) const;
    void paintScaleBar(QPainter& painter) const;

    Document* doc_;
    Projection projection_ = Projection::Top;
    QLabel* title_;
    QCheckBox* snap_;
    QDoubleSpinBox* snapStep_;
    QToolButton* drawField_;
    QComboBox* scaleChoice_;
    QAction* labels_;

    std::vector<PlanFace> faces_;      // of the geometry, for the projection
    SceneSnapshot facesScene_;         // the scene faces_ were built from
    Projection facesProjection_ = Projection::Top;
    double scale_ = 100;               // pixels per scene unit
    QPointF offset_;                   // widget position of plan point (0, 0)
    bool fitted_ = false;
    int selected_ = -1;
    std::vector<char> selectedSet_;  // by light index
    int selectedCount_ = 0;

    CalculationGrid grid_;
    GridLayout layout_;
    std::shared_ptr<const GridResult> result_;
    SceneSnapshot resultScene_;  // the scene when the result arrived
    PlanScale gridScale_;        // the result's legend and iso-lux levels
    GridStatistics gridStatistics_;  // the result's
    QString gridUnit_;           // the legend's unit; empty: lx

    PlanInteraction* interaction_;  // the mouse and keys (a child)
    TaskAreaDrawing* taskAreaDrawing_;  // the task area tool (a child; sees the mouse first)
    std::unique_ptr<TaskAreaOutlines> taskAreaOutlines_;
    RoomDrawing* roomDrawing_;  // the room tool (a child; sees the mouse before the plan's own)
    int selectedTaskArea_ = -1;

    PlanLightTypes lightTypes_;         // of the scene, at the last paint
    std::vector<QRectF> labelRects_;    // the names painted last
    std::vector<QRectF> legendRects_;   // the legends' boxes painted last
    QRectF keyRect_;                    // the key of light types (empty: none)
};

}  // namespace lucerna
