#include "ui/plan/label_placement.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace lucerna {

namespace {

// The rectangles taken so far in buckets of a coarse grid, so that a plan of thousands of
// symbols checks each candidate against its neighbours only.
class Occupancy {
public:
    explicit Occupancy(double cell) : cell_(cell) {}

    void add(const QRectF& r) {
        const size_t index = rects_.size();
        rects_.push_back(r);
        forCells(r, [&](long long key) { buckets_[key].push_back(index); });
    }
    bool clear(const QRectF& r) const {
        bool free = true;
        forCells(r, [&](long long key) {
            if (!free) return;
            const auto it = buckets_.find(key);
            if (it == buckets_.end()) return;
            for (size_t i : it->second)
                if (rects_[i].intersects(r)) {
                    free = false;
                    return;
                }
        });
        return free;
    }

private:
    template <class F>
    void forCells(const QRectF& r, F f) const {
        const long long x0 = (long long)std::floor(r.left() / cell_), x1 = (long long)std::floor(r.right() / cell_);
        const long long y0 = (long long)std::floor(r.top() / cell_), y1 = (long long)std::floor(r.bottom() / cell_);
        for (long long y = y0; y <= y1; ++y)
            for (long long x = x0; x <= x1; ++x) f(y * 1000003LL + x);
    }

    double cell_;
    std::vector<QRectF> rects_;
    std::unordered_map<long long, std::vector<size_t>> buckets_;
};

}  // namespace

std::vector<std::optional<QRectF>> placeLabels(const std::vector<LabelRequest>& requests,
                                               const std::vector<QRectF>& obstacles, const QRectF& bounds, double gap) {
    std::vector<std::optional<QRectF>> out(requests.size());
    Occupancy taken(64);
    for (const QRectF& o : obstacles)
        if (o.intersects(bounds)) taken.add(o);
    for (size_t i = 0; i < requests.size(); ++i) {
        const QRectF& s = requests[i].symbol;
        const QSizeF& size = requests[i].size;
        if (!bounds.intersects(s) || size.isEmpty()) continue;
        const double midY = s.center().y() - size.height() / 2, midX = s.center().x() - size.width() / 2;
        const QRectF candidates[] = {
            QRectF(QPointF(s.right() + gap, midY), size),                       // right
            QRectF(QPointF(s.left() - gap - size.width(), midY), size),         // left
            QRectF(QPointF(midX, s.top() - gap - size.height()), size),         // above
            QRectF(QPointF(midX, s.bottom() + gap), size),                      // below
        };
        for (const QRectF& c : candidates)
            if (bounds.contains(c) && taken.clear(c)) {
                out[i] = c;
                taken.add(c);
                break;
            }
    }
    return out;
}

}  // namespace lucerna
