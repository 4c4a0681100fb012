#include "render/trace/lights/daylight_portals.h"

#include "render/trace/warp.h"

#include <cmath>
#include <cstdio>

namespace lucerna {

namespace {

// Whether the infinite line through o along unit d crosses triangle (p0, p1, p2) (Moller and
// Trumbore, any t; a hair of tolerance at the edges, so that a point drawn on a pane is on it).
bool lineCrosses(const V3f& o, const V3f& d, const Portal& t) {
    const V3f e1 = t.p1 - t.p0, e2 = t.p2 - t.p0;
    const V3f q = d.cross(e2);
    const float det = e1.dot(q);
    if (std::abs(det) < 1e-20f) return false;  // the line lies in the pane's plane
    const float inv = 1.0f / det;
    const V3f s = o - t.p0;
    const float b1 = s.dot(q) * inv;
    const V3f r = s.cross(e1);
    const float b2 = d.dot(r) * inv;
    constexpr float tolerance = 1e-5f;
    return b1 >= -tolerance && b2 >= -tolerance && b1 + b2 <= 1 + tolerance;
}

}  // namespace

DaylightPortals::DaylightPortals(const std::vector<Portal>& portals, const V3f& sceneCenter, float sceneRadius)
    : center_(sceneCenter), radius_(sceneRadius) {
    if (portals.size() > kMaxPortalTriangles) return;
    for (const Portal& p : portals)
        if (p.area > 0) portals_.push_back(p);
}

bool DaylightPortals::facing(size_t k, const V3f& w) const {
    const Portal& p = portals_[k];
    const float c = p.normal.dot(w);
    return p.outside > 0 ? c > 0 : p.outside < 0 ? c < 0 : c != 0;
}

float DaylightPortals::projectedArea(const V3f& w) const {
    float s = 0;
    for (size_t k = 0; k < portals_.size(); ++k)
        if (facing(k, w)) s += portals_[k].area * std::abs(portals_[k].normal.dot(w));
    return s;
}

float DaylightPortals::lineDensity(const V3f& point, const V3f& w) const {
    return lineDensity(point, w, projectedArea(w));
}

float DaylightPortals::lineDensity(const V3f& point, const V3f& w, float s) const {
    const float disc = 1.0f / (kPi * radius_ * radius_);
    if (!(s > 0)) return disc;
    int crossed = 0;
    for (size_t k = 0; k < portals_.size(); ++k)
        if (facing(k, w) && lineCrosses(point, w, portals_[k])) ++crossed;
    return kDiscShare * disc + (1 - kDiscShare) * float(crossed) / s;
}

std::string DaylightPortals::describe(float metersPerUnit) const {
    if (portals_.empty())  // no sky or sun disc, no pane, or too many
        return "none (daylight particles leave from a disc around the scene)";
    double area = 0;
    int known = 0;
    for (const Portal& p : portals_) {
        area += double(p.area) * metersPerUnit * metersPerUnit;
        known += p.outside != 0;
    }
    char text[160];
    std::snprintf(text, sizeof text, "%zu portal triangles (panes and openings), %.2f m^2, outside known for %d (daylight particles: %.0f%% through them)",
                  portals_.size(), area, known, 100.0 * (1 - kDiscShare));
    return text;
}

V3f DaylightPortals::sampleLine(const V3f& w, const V2f& u, float& density) const {
    const float s = projectedArea(w);
    const Frame frame(w);
    const V3f onDiscPlane = center_ + w * radius_;
    V3f point;
    if (!(s > 0) || u.x < kDiscShare) {
        const V2f d = squareToUniformDisk(V2f(s > 0 ? u.x / kDiscShare : u.x, u.y)) * radius_;
        point = onDiscPlane + frame.s * d.x + frame.t * d.y;
    } else {
        // A pane by its projected area, then a uniform point of it (uniform across the line's
        // plane too: the projection scales every pane's area by one factor).
        float pick = (u.x - kDiscShare) / (1 - kDiscShare) * s;
        size_t k = 0, last = 0;
        for (; k < portals_.size(); ++k) {
            if (!facing(k, w)) continue;
            last = k;
            const float a = portals_[k].area * std::abs(portals_[k].normal.dot(w));
            if (pick < a) {
                pick /= a;
                break;
            }
            pick -= a;
        }
        if (k == portals_.size()) {  // rounding left pick past the last facing pane
            k = last;
            pick = 0.999999f;
        }
        const Portal& p = portals_[k];
        const V2f b = squareToUniformTriangle(V2f(std::min(pick, 0.999999f), u.y));
        const V3f onPane = p.p0 * (1 - b.x - b.y) + p.p1 * b.x + p.p2 * b.y;
        point = onPane + w * (onDiscPlane - onPane).dot(w);  // moved along the line to the disc's plane
    }
    density = lineDensity(point, w, s);
    return point;
}

}  // namespace lucerna
