// The plan view's lights (ui/plan/plan_view.h): their symbols, one shape per type, the groups'
// boxes, the names placed clear of one another and of the legends, and the legends drawn last.

#include "ui/plan/plan_view.h"

#include "render/display/false_colour.h"
#include "ui/plan/label_placement.h"
#include "ui/plan/light_key.h"

#include <QAction>
#include <QFontMetricsF>
#include <QLayout>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <map>

namespace lucerna {

namespace {
constexpr int kMaxRings = 50;  // selections larger than this show as blue symbols

bool positioned(const Light& l) { return l.type != LightType::Directional && l.type != LightType::Sun; }
}  // namespace

void PlanView::paintLights(QPainter& painter) const {
    const Scene& scene = doc_->scene();
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& l = scene.lights[i];
        if (!positioned(l)) continue;  // at infinity
        const QPointF c = widgetOf(l.position);
        const double r = kSymbolRadius;
        // Selected: a ring; in a large selection (a dense field) the symbol itself turns blue,
        // where rings would cover the field.
        const bool inSet = i < selectedSet_.size() && selectedSet_[i];
        if (int(i) == selected_ || (inSet && selectedCount_ <= kMaxRings)) {
            painter.setPen(QPen(selectionColour(), 2.5));
            painter.setBrush(Qt::NoBrush);
            painter.drawEllipse(c, r + 5, r + 5);
        }
        // A light switched off is drawn grey.
        const QColor symbol = !l.on ? QColor(150, 150, 150) : inSet && selectedCount_ > kMaxRings ? selectionColour() : lightColour();
        painter.setPen(QPen(symbol, 2));
        painter.setBrush(QColor(255, 255, 255, 200));
        const int type = i < lightTypes_.typeOfLight.size() ? lightTypes_.typeOfLight[i] : -1;
        paintSymbol(painter, type >= 0 ? lightTypes_.types[size_t(type)].shape : SymbolShape::Circle, c, r);
        if (l.type == LightType::Spot || l.type == LightType::Luminaire) {
            // The axis's direction in this view, as a wedge of the cone's half-angle.
            const QPointF d = planPoint(projection_, l.position + l.direction.normalized()) - planPoint(projection_, l.position);
            const double len = std::hypot(d.x(), d.y());
            if (len > 0.05) {
                const double angle = std::atan2(d.y(), d.x());
                const double half = l.type == LightType::Spot ? l.coneAngleDeg * M_PI / 180 : M_PI / 6;
                const double reach = r + 6 + 14 * len;
                QPolygonF wedge;
                wedge << c << c + reach * QPointF(std::cos(angle - half), std::sin(angle - half))
                      << c + reach * QPointF(std::cos(angle + half), std::sin(angle + half));
                painter.setBrush(Qt::NoBrush);
                painter.drawPolygon(wedge);
            }
        }
    }
}

std::vector<QRectF> PlanView::paintGroups(QPainter& painter) const {
    // Each group's box around its lights, dashed, with its name and count once above it.
    struct Box {
        double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
        int count = 0;
    };
    std::map<std::string, Box> boxes;
    for (const Light& l : doc_->scene().lights) {
        if (l.group.empty() || !positioned(l)) continue;
        const QPointF c = widgetOf(l.position);
        Box& b = boxes[l.group];
        b.x0 = std::min(b.x0, c.x()), b.x1 = std::max(b.x1, c.x());
        b.y0 = std::min(b.y0, c.y()), b.y1 = std::max(b.y1, c.y());
        ++b.count;
    }
    const double pad = kSymbolRadius + 5;
    std::vector<QRectF> captions;
    for (const auto& [name, b] : boxes) {
        const QRectF r = QRectF(QPointF(b.x0, b.y0), QPointF(b.x1, b.y1)).adjusted(-pad, -pad, pad, pad);
        painter.setPen(QPen(lightColour().darker(130), 1, Qt::DashLine));
        painter.setBrush(Qt::NoBrush);
        painter.drawRect(r);
        const QString text = tr("%1 (%2)").arg(QString::fromStdString(name)).arg(b.count);
        const QRectF box = painter.fontMetrics().boundingRect(text).adjusted(-3, 0, 3, 0);
        const QRectF at(r.topLeft() - QPointF(0, box.height() + 1), box.size());
        painter.fillRect(at, QColor(255, 255, 255));
        painter.setPen(Qt::black);
        painter.drawText(at, Qt::AlignCenter, text);
        captions.push_back(at);
    }
    return captions;
}

void PlanView::layOutLegends(const QFont& font) {
    legendRects_.clear();
    keyRect_ = QRectF();
    if (gridLegend()) legendRects_.push_back(QRectF(legendFrame(rect())));
    const QSizeF key = lightKeySize(lightTypes_, font);
    if (key.isEmpty()) return;
    // The bottom right, above the out-of-date band when there is one, left of the false-colour
    // legend where a short view would put the two together.
    double bottom = height() - 8;
    if (gridOutOfDate()) bottom = height() - 3 * QFontMetricsF(font).height() - 34 - 4;
    QRectF box(QPointF(width() - 8 - key.width(), bottom - key.height()), key);
    if (!legendRects_.empty() && box.intersects(legendRects_.front())) box.moveRight(legendRects_.front().left() - 6);
    keyRect_ = box;
    legendRects_.push_back(box);
}

void PlanView::paintLabels(QPainter& painter, const std::vector<QRectF>& groupCaptions) {
    labelRects_.clear();
    if (!labels_->isChecked()) return;
    const Scene& scene = doc_->scene();
    // Nothing may be covered: the symbols (with a selection's ring), the groups' captions, the
    // legends and the scale bar; and the names stay below the bar of buttons.
    std::vector<QRectF> obstacles = groupCaptions;
    obstacles.insert(obstacles.end(), legendRects_.begin(), legendRects_.end());
    obstacles.emplace_back(8, height() - 32, width() / 5.0 + 70, 32);  // the scale bar
    std::vector<LabelRequest> requests;
    std::vector<size_t> lightOf;
    const QFontMetricsF fm(painter.font());
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& l = scene.lights[i];
        if (!positioned(l)) continue;
        const bool ringed = int(i) == selected_ || (i < selectedSet_.size() && selectedSet_[i] && selectedCount_ <= kMaxRings);
        const double r = ringed ? kSymbolRadius + 7 : kSymbolRadius * 1.3 + 1;  // the polygons reach 1.3 r
        const QPointF c = widgetOf(l.position);
        const QRectF symbol(c - QPointF(r, r), c + QPointF(r, r));
        obstacles.push_back(symbol);
        if (!l.group.empty()) continue;  // named once for its group (paintGroups)
        const QString name = QString::fromStdString(l.name);
        requests.push_back({symbol, QSizeF(fm.horizontalAdvance(name) + 4, fm.height())});
        lightOf.push_back(i);
    }
    // The selected light's name first: it is the one the user looks for.
    std::vector<size_t> order(requests.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::stable_partition(order.begin(), order.end(), [&](size_t k) { return int(lightOf[k]) == selected_; });
    std::vector<LabelRequest> ordered;
    for (size_t k : order) ordered.push_back(requests[k]);
    QRectF bounds = QRectF(rect()).adjusted(2, 2, -2, -2);
    if (layout() && layout()->count() > 0) bounds.setTop(layout()->itemAt(0)->geometry().bottom() + 2);
    const std::vector<std::optional<QRectF>> placed = placeLabels(ordered, obstacles, bounds);
    painter.setPen(Qt::black);
    for (size_t k = 0; k < placed.size(); ++k) {
        if (!placed[k]) continue;
        const QString name = QString::fromStdString(scene.lights[lightOf[order[k]]].name);
        painter.fillRect(*placed[k], QColor(255, 255, 255));
        painter.drawText(*placed[k], Qt::AlignCenter, name);
        labelRects_.push_back(*placed[k]);
    }
}

void PlanView::paintLegends(QPainter& painter) const {
    if (const std::optional<Legend> legend = gridLegend()) paintLegend(painter, rect(), *legend);
    if (!keyRect_.isEmpty()) paintLightKey(painter, keyRect_, lightTypes_, font(), lightColour());
}

}  // namespace lucerna
