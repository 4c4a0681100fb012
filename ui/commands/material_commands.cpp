#include "ui/commands/material_commands.h"

#include <QObject>

namespace lucerna {

Material withMaterialType(const Material& m, MaterialType type) {
    if (m.type == type) return m;
    // The colour the material shows most, to seed the new type's colour.
    Rgbd colour(0.8, 0.8, 0.8);
    switch (m.type) {
    case MaterialType::Diffuse:
    case MaterialType::Glossy: colour = m.albedo; break;
    case MaterialType::Mirror: colour = m.reflectance; break;
    case MaterialType::Dielectric: break;
    case MaterialType::Glazing: colour = m.transmittance; break;
    case MaterialType::Emitter: {
        const double peak = std::max({m.radiance.x, m.radiance.y, m.radiance.z});
        if (peak > 0) colour = m.radiance / peak;
        break;
    }
    }
    Material out;
    out.name = m.name;
    out.type = type;
    switch (type) {
    case MaterialType::Diffuse: out.albedo = colour; break;
    case MaterialType::Glossy:
        out.albedo = colour * 0.5;
        out.specular = Rgbd(0.5, 0.5, 0.5);
        out.roughness = 0.2;
        break;
    case MaterialType::Mirror: out.reflectance = colour; break;
    case MaterialType::Dielectric: out.ior = 1.5; break;
    case MaterialType::Emitter: out.radiance = colour * 10.0; break;
    case MaterialType::Glazing: out.transmittance = Rgbd(0.7, 0.7, 0.7); break;  // clear double glazing, about
    }
    return out;
}

QString materialTypeName(MaterialType type) {
    switch (type) {
    case MaterialType::Diffuse: return QObject::tr("diffuse");
    case MaterialType::Glossy: return QObject::tr("glossy");
    case MaterialType::Mirror: return QObject::tr("mirror");
    case MaterialType::Dielectric: return QObject::tr("dielectric");
    case MaterialType::Emitter: return QObject::tr("emitter");
    case MaterialType::Glazing: return QObject::tr("glazing");
    }
    return {};
}

}  // namespace lucerna
