#include "report/report_text.h"

namespace lucerna {

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
    const QString word = QString::fromStdString(c.outcomeWord());
    return c.outcome == CheckOutcome::NotChecked ? word + ": " + QString::fromStdString(c.notCheckedBecause) : word;
}

}  // namespace lucerna
