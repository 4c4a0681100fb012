#include "ui/io/luminaire_import.h"

#include "core/photometry/goniometric_distribution.h"
#include "core/photometry/luminaire.h"
#include "ui/commands/light_commands.h"
#include "ui/io/mesh_import.h"

#include <QFileInfo>

namespace lucerna {

Light luminaireFromFile(const Document& doc, const QString& file) {
    const QFileInfo info(file);
    auto distribution = std::make_shared<const GoniometricDistribution>(
        loadLuminaireFile(info.absoluteFilePath().toStdString()));  // throws LuminaireFileError
    const std::string base = info.completeBaseName().isEmpty() ? std::string("luminaire") : info.completeBaseName().toStdString();
    Light l = defaultLight(doc.scene(), LightType::Point, doc.uniqueName(base));
    l.type = LightType::Luminaire;
    l.intensity = Rgbd(0, 0, 0);
    l.direction = V3d(0, -1, 0);
    LuminaireSpec spec;
    spec.file = scenePathOf(doc, file);
    spec.distribution = std::move(distribution);
    l.luminaire = std::move(spec);
    return l;
}

}  // namespace lucerna
