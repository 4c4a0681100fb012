#include "report/report_text.h"

#include <cstdio>

namespace lucerna {

QString gridFiguresLine(const GridStatistics& s) {
    if (s.counted == 0) return QStringLiteral("Eavg, Emin, Emax, U0: none (every point is inside geometry)");
    return QString::asprintf("Eavg %.1f lx, Emin %.1f lx, Emax %.1f lx, U0 %.3f", s.average, s.minimum, s.maximum,
                             s.uniformity);
}

QString seconds(double s) {
    if (s < 60) return QString::asprintf("%.1f s", s);
    const int whole = int(s + 0.5);
    return QString::asprintf("%d min %02d s", whole / 60, whole % 60);
}

QString gridErrorLine(const GridResult& r, int counted) {
    if (r.errorBarUnknown)
        return QString::asprintf("%s cannot carry light through glass to %d of %d points: error bar unknown after %d "
                                 "passes, %lld samples per point, ",
                                 gridMethodName(r.method), r.litThroughGlass, counted, r.passes, r.samplesPerPoint) +
               seconds(r.seconds);
    return QString::asprintf("error bar (95%%) at most %.2f%% of each point's value after %d passes, %lld samples per "
                             "point, ",
                             100.0 * r.maxRelativeError, r.passes, r.samplesPerPoint) +
           seconds(r.seconds) + (r.converged ? QString() : QStringLiteral(" (target not reached)"));
}

QString lux(double value) { return QString::asprintf("%.1f", value); }

QString activityText(const ActivityRequirement& a) {
    return QStringLiteral("%1 %2: %3").arg(a.reference, a.area, a.activity);
}

QString methodDescription(GridMethod method) {
    switch (method) {
    case GridMethod::Path:
        return QStringLiteral("path: at each point, unidirectional path tracing with next-event estimation (every "
                              "lamp without size summed exactly) and path-traced interreflections; the error bar "
                              "comes from the spread of independent per-pass means");
    case GridMethod::Vpl:
        return QStringLiteral("ir: at each point, the direct light by next-event estimation and the interreflected "
                              "light from a fresh set of virtual point lights each pass (instant radiosity, clamped, "
                              "with its residual); the error bar comes from the spread of the per-pass means");
    case GridMethod::Bdpt:
    case GridMethod::Mir:
    case GridMethod::Mlt:
    case GridMethod::Cmlt:
        return QStringLiteral("%1: the renderer itself measures the points as irradiance sensors in independent "
                              "replicas (own seeds and chains); the error bar comes from the replicas' spread "
                              "(Student's t)")
            .arg(gridMethodName(method));
    case GridMethod::Preview:
        return QStringLiteral("preview: a hemicube of interactive-preview frames at each point; it converges to the "
                              "preview's own approximation (clamped virtual point lights, shadow maps), not to the "
                              "exact value");
    }
    return {};
}

QString outcomeText(const RequirementCheck& c) {
    if (!c.achieved) return c.quantity == "Ra" ? QStringLiteral("not stated") : QStringLiteral("not computed");
    return c.outcome == CheckOutcome::Met ? QStringLiteral("met") : QStringLiteral("not met");
}

}  // namespace lucerna
