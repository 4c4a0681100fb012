#pragma once
// The viewport: the live preview's newest frame, the lights drawn over it, and editing with the
// mouse and keyboard.
// - Over the picture, and only there: each light a ball that shrinks with distance
//   (ui/viewport/light_symbols.h), the selected lights' aims as dashed lines to where they meet
//   the scene, the selected light's gizmo, the selected object's outline.
// - Left drag on a light moves it in the image plane at its depth; on an arrow of the selected
//   light's gizmo, along that world axis; on a spot's (or luminaire's) aim handle, re-aims it. Left drag elsewhere
//   orbits the camera about its target; right or middle drag pans; the wheel zooms.
// - A left click (no drag) selects the light or the object under the mouse, or nothing.
// - Tools: place a point or spot light on the next surface clicked; aim the selected spot,
//   luminaire or directional light at the next surface clicked, as Ctrl+click does. Escape cancels a tool.
// - W/S or Up/Down fly forward and back, A/D or Left/Right sideways, E/Q up and down (Shift:
//   four times as far).
// Each drag, and each run of held fly keys, is one undo command (its steps merge); while a
// button is down the converging render yields.

#include "render/trace/surface_pick.h"
#include "ui/document/document.h"
#include "ui/viewport/image_view.h"
#include "ui/viewport/light_gizmo.h"
#include "ui/rendering/yield_gate.h"

#include <QSet>

#include <memory>
#include <optional>

class QAction;

namespace lucerna {

// A key that no earlier interaction used, so that the steps of one drag merge with each other
// and with nothing else (undo commands' mergeKey).
int nextMergeKey();

class Viewport : public ImageView {
    Q_OBJECT
public:
    enum class Tool { Navigate, PlacePoint, PlaceSpot, Aim, GridRectangle };

    Viewport(Document* doc, const YieldGate& gate, QWidget* parent = nullptr);
    ~Viewport() override;

    void setSelectedLight(int index);
    // The lights selected together (a group, several lights): their aims are drawn too.
    void setSelectedLights(const std::vector<int>& lights);
    // The selected object is outlined (-1: none).
    void setSelectedObject(int index);
    // Widget position of a light's symbol; nothing where none is drawn (directional lights,
    // lights behind or too near the camera, or outside the picture): a click there picks nothing.
    std::optional<QPointF> lightMarker(int index) const;
    // The selected light's gizmo as drawn now (nothing without a selected light whose symbol is drawn).
    std::optional<LightGizmo> gizmo() const;

    Tool tool() const { return tool_; }
    // Aim needs a selected spot, luminaire or directional light; returns false (and says why) without one.
    bool setTool(Tool tool);
    // The checkable actions that choose the tools (for the window's menus and tool bar).
    QList<QAction*> toolActions() const;

    // The surface seen under a widget point, by SPEC.md's camera and the document's geometry
    // (the acceleration structure is built at the first pick and again only after the geometry
    // changes, not when lights or the camera move).
    std::optional<SurfaceHit> surfaceAt(const QPointF& widget) const;
    // Where the camera's image is in the widget.
    ViewMapping mapping() const;
    // No preview frame to show: the picture goes, and the placeholder says why (the preview's
    // error in one line) or, without an error, that a frame is on its way.
    void showNoFrame(const QString& error = {});

signals:
    void lightClicked(int index);
    // An object's surface was clicked (-1: nothing was under the mouse).
    void objectClicked(int index);
    void lightPlaced(int index);
    // A calculation-grid rectangle drawn with the GridRectangle tool: corner a on a surface of
    // unit normal `normal` (facing the camera), the opposite corner b (core/photometry/calculation_grid.h).
    void gridRectangleDrawn(const lucerna::V3d& a, const lucerna::V3d& normal, const lucerna::V3d& b);
    void toolChanged(lucerna::Viewport::Tool tool);
    // A line for the status bar.
    void message(const QString& text);

protected:
    void paintOverlay(QPainter& painter) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    void leaveEvent(QEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;

private:
    // Orbit waits for the mouse to move a little, so that a click can select instead.
    enum class Drag { None, Pending, Orbit, Pan, MoveLight, Axis, Aim };
    int lightAt(const QPointF& pos) const;
    void placeAt(const QPointF& pos);
    void aimAt(const QPointF& pos);
    void selectAt(const QPointF& pos);
    void gridCornerAt(const QPointF& pos);
    bool aimable(int light) const;
    void endDrag();
    // The picker over the document's geometry, built when first needed and again after the
    // geometry changes; null when the ray tracer cannot start.
    const SurfacePicker* picker() const;
    void paintAimLines(QPainter& painter) const;
    void paintGizmo(QPainter& painter, const LightGizmo& g) const;
    void paintSelectedObject(QPainter& painter) const;
    void paintToolHint(QPainter& painter) const;

    Document* doc_;
    YieldGate gate_;
    int selected_ = -1, selectedObject_ = -1;
    QSet<int> selectedLights_;
    Tool tool_ = Tool::Navigate;
    QAction *placePoint_, *placeSpot_, *aim_, *drawGrid_;
    mutable std::unique_ptr<SurfacePicker> picker_;
    mutable bool pickerFailed_ = false;

    Drag drag_ = Drag::None;
    int dragLight_ = -1;
    GizmoHandle dragHandle_ = GizmoHandle::None, hoverHandle_ = GizmoHandle::None;
    Light dragStart_;       // the light as it was when a gizmo drag began
    V3d aimTipStart_;       // the aim handle's world position when its drag began
    QPointF pressed_, last_;
    std::optional<SurfaceHit> hover_;  // the surface under the mouse while a tool is active
    std::optional<SurfaceHit> gridCorner_;  // the first corner of a grid rectangle being drawn
    int mergeKey_ = 0;
    int wheelKey_ = nextMergeKey();  // renewed by each press, so a run of wheel steps is one command
    int flyKey_ = 0;
    QSet<int> flyKeysHeld_;
    std::unique_ptr<YieldGate::Scope> hold_;
};

}  // namespace lucerna
