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

DaylightPortals::DaylightPortals(const std::vector<Portal>& portals, const EnvironmentLight& environment,
                                 const V3f& sceneCenter, float sceneRadius)
    : environment_(environment), center_(sceneCenter), radius_(sceneRadius) {
    if (portals.size() > kMaxPortalTriangles) return;
    for (const Portal& p : portals) {
        if (!(p.area > 0)) continue;
        portals_.push_back(p);
        bool merged = false;
        for (Facing& f : orientations_)
            if (f.outside == p.outside && (f.normal - p.normal).length2() < 1e-10f) {
                f.area += p.area;
                merged = true;
                break;
            }
        if (!merged) orientations_.push_back({p.normal, p.outside, p.area});
    }
    throughPortals_ = environment_.reweighted([this](const V3d& w) { return double(projectedArea(toFloat(w))); });
    if (!(throughPortals_.integratedLuminance() > 0)) {  // no portal faces any lit direction
        portals_.clear();
        orientations_.clear();
    }
}

bool DaylightPortals::faces(const V3f& normal, int8_t outside, const V3f& w) {
    const float c = normal.dot(w);
    return outside > 0 ? c > 0 : outside < 0 ? c < 0 : c != 0;
}

float DaylightPortals::projectedArea(const V3f& w) const {
    float s = 0;
    for (const Facing& f : orientations_)
        if (faces(f.normal, f.outside, w)) s += f.area * std::abs(f.normal.dot(w));
    return s;
}

float DaylightPortals::lineDensity(const V3f& point, const V3f& w) const {
    const float disc = kDiscShare / (kPi * radius_ * radius_);
    const float s = projectedArea(w);
    if (!(s > 0)) return disc;
    const float pEnv = environment_.pdf(w);
    if (!(pEnv > 0)) return disc;
    return disc + (1 - kDiscShare) * (throughPortals_.pdf(w) / pEnv) * float(crossings(point, w)) / s;
}

int DaylightPortals::crossings(const V3f& point, const V3f& w) const {
    int crossed = 0;
    for (const Portal& p : portals_)
        if (faces(p.normal, p.outside, w) && lineCrosses(point, w, p)) ++crossed;
    return crossed;
}

float DaylightPortals::parallelDensity(const V3f& point, const V3f& w) const {
    const float disc = 1.0f / (kPi * radius_ * radius_);
    const float s = projectedArea(w);
    if (!(s > 0)) return disc;
    return kDiscShare * disc + (1 - kDiscShare) * float(crossings(point, w)) / s;
}

V3f DaylightPortals::sampleParallel(const V3f& w, const V2f& u, float& density) const {
    const float s = projectedArea(w);
    V3f point;
    if (!(s > 0)) point = onDisc(w, u);
    else if (u.x < kDiscShare) point = onDisc(w, V2f(std::min(u.x / kDiscShare, 0x1.fffffep-1f), u.y));
    else point = throughPortal(w, s, V2f(std::min((u.x - kDiscShare) / (1 - kDiscShare), 0x1.fffffep-1f), u.y));
    density = parallelDensity(point, w);
    return point;
}

bool DaylightPortals::sample(const V2f& uLine, const V2f& uDirection, DaylightParticle& out) const {
    float pdf = 0;
    if (uLine.x < kDiscShare) {
        if (!environment_.sample(uDirection, out.towardSky, pdf, out.radiance)) return false;
        out.point = onDisc(out.towardSky, V2f(std::min(uLine.x / kDiscShare, 0x1.fffffep-1f), uLine.y));
    } else {
        if (!throughPortals_.sample(uDirection, out.towardSky, pdf, out.radiance)) return false;
        const float s = projectedArea(out.towardSky);
        if (!(s > 0)) return false;  // a cell's edge where the portals turn away: the disc covers it
        const float u = std::min((uLine.x - kDiscShare) / (1 - kDiscShare), 0x1.fffffep-1f);
        out.point = throughPortal(out.towardSky, s, V2f(u, uLine.y));
    }
    out.pdfDirection = environment_.pdf(out.towardSky);
    out.lineDensity = lineDensity(out.point, out.towardSky);
    return out.pdfDirection > 0 && out.lineDensity > 0;
}

V3f DaylightPortals::onDisc(const V3f& w, const V2f& u) const {
    const V2f d = squareToUniformDisk(u) * radius_;
    const Frame frame(w);
    return center_ + w * radius_ + frame.s * d.x + frame.t * d.y;
}

V3f DaylightPortals::throughPortal(const V3f& w, float s, V2f u) const {
    // A portal by its projected area, then a uniform point of it (uniform across the line's
    // plane too: the projection scales every portal's area by one factor).
    float pick = u.x * s;
    size_t k = 0, last = 0;
    for (; k < portals_.size(); ++k) {
        if (!faces(portals_[k].normal, portals_[k].outside, w)) continue;
        last = k;
        const float a = portals_[k].area * std::abs(portals_[k].normal.dot(w));
        if (pick < a) {
            pick /= a;
            break;
        }
        pick -= a;
    }
    if (k == portals_.size()) {  // rounding left pick past the last facing portal
        k = last;
        pick = 0.999999f;
    }
    const Portal& p = portals_[k];
    const V2f b = squareToUniformTriangle(V2f(std::min(pick, 0.999999f), u.y));
    const V3f onPortal = p.p0 * (1 - b.x - b.y) + p.p1 * b.x + p.p2 * b.y;
    const V3f onDiscPlane = center_ + w * radius_;
    return onPortal + w * (onDiscPlane - onPortal).dot(w);  // moved along the line to the disc's plane
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

}  // namespace lucerna
