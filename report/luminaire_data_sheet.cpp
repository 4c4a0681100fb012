#include "report/luminaire_data_sheet.h"

#include "core/photometry/luminaire.h"
#include "report/report_data.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lucerna {

namespace {

const Light* findLuminaire(const Scene& scene, const std::string& name) {
    for (const Light& l : scene.lights)
        if (l.name == name && l.type == LightType::Luminaire && l.luminaire && l.luminaire->distribution) return &l;
    return nullptr;
}

bool sameArea(const LuminousArea& a, const LuminousArea& b) {
    return a.lengthM == b.lengthM && a.widthM == b.widthM && a.elliptical == b.elliptical &&
           std::equal(std::begin(a.heightsM), std::end(a.heightsM), std::begin(b.heightsM));
}

// The UGR tables of `sheet` at the spacings `lucerna glare --table` prints, or why there are none.
void addUgrTables(LuminaireDataSheet& sheet) {
    if (sheet.luminousArea.empty()) {
        sheet.ugrMissing = "the file states no luminous area and the scene gives none (luminous_area): a point "
                           "source, which UGR does not rate";
        return;
    }
    UgrLuminaire luminaire;
    luminaire.distribution = sheet.distribution.get();
    luminaire.fluxLm = sheet.lumensEach;
    luminaire.area = sheet.luminousArea;
    try {
        for (double spacing : {1.0, 0.25}) sheet.ugr.push_back(ugrTable(luminaire, spacing));
    } catch (const std::invalid_argument& e) {
        sheet.ugr.clear();
        sheet.ugrMissing = e.what();
    }
}

}  // namespace

std::optional<double> LuminaireDataSheet::efficacy() const {
    if (!watts || !(*watts > 0) || !(fileLumens > 0)) return std::nullopt;
    return fileLumens / *watts;
}

double LuminaireDataSheet::cdPerKlmPerTableCd() const { return fileLumens > 0 ? 1000.0 / fileLumens : 0.0; }

std::vector<LuminaireDataSheet> luminaireDataSheets(const Scene& scene, const Schedule& schedule) {
    std::vector<LuminaireDataSheet> sheets;
    // Light by light: the schedule's lines do not compare luminous areas, which UGR reads.
    for (const ScheduleEntry& e : schedule.entries) {
        if (e.kind != "Luminaire") continue;
        for (const std::string& name : e.names) {
            const Light* l = findLuminaire(scene, name);
            if (!l) continue;
            const LuminaireSpec& spec = *l->luminaire;
            const LuminousArea area = luminousAreaOf(*l);
            const auto same = std::find_if(sheets.begin(), sheets.end(), [&](const LuminaireDataSheet& s) {
                return s.file == e.file && std::abs(s.lumensEach - e.lumensEach) < 0.05 &&
                       sameArea(s.luminousArea, area) && s.sceneTemperatureK == spec.temperatureK;
            });
            if (same != sheets.end()) {
                ++same->count;
                continue;
            }
            LuminaireDataSheet s;
            const GoniometricDistribution& d = *spec.distribution;
            s.product = d.name;
            s.file = e.file;
            s.count = 1;
            s.lumensEach = e.lumensEach;
            s.distribution = spec.distribution;
            s.fileLumens = d.integratedFlux();
            s.watts = d.inputWatts;
            s.temperatureK = d.colourTemperatureK;
            s.colourRenderingIndex = d.colourRenderingIndex;
            s.sceneTemperatureK = spec.temperatureK;
            s.luminousArea = area;
            s.luminousAreaFromScene = spec.luminousAreaM.has_value();
            addUgrTables(s);
            sheets.push_back(std::move(s));
        }
    }
    return sheets;
}

}  // namespace lucerna
