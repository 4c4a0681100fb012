#pragma once
// The scene's task areas as the plan shows them (README, "Task areas"): each rectangle outlined
// and lightly filled, its name (and activity) by its corner, the selected one in the selection's
// blue; a surrounding zone as a tinted band with a dashed outer edge, a background area as a
// paler band with a dotted one, both clipped to the room as they are computed
// (core/photometry/surrounding_zones.h). And which task area a click in the plan falls in.

#include "core/scene/scene.h"
#include "core/scene/scene_geometry.h"

#include <QColor>
#include <QPointF>

#include <functional>

class QPainter;

namespace lucerna {

class TaskAreaOutlines {
public:
    // Draws `scene`'s task areas; `widgetOf` maps a world point to the widget.
    void paint(QPainter& painter, const SceneSnapshot& scene, const std::function<QPointF(const V3d&)>& widgetOf,
               int selected);
    // The task area whose rectangle holds the plan point (x, z), the smallest of those that do;
    // -1 when none does.
    static int taskAreaAt(const Scene& scene, const QPointF& plan);
    static QColor colour();

private:
    // The room the zones are clipped to, for the scene it was computed for.
    SceneSnapshot boundsScene_;
    SceneBounds bounds_;
};

}  // namespace lucerna
