#include "core/scene/scene.h"
#include "core/photometry/goniometric_distribution.h"
#include "core/number_format.h"

#include <algorithm>
#include <cmath>

namespace lucerna {

namespace {

// cos and sin of a whole number of quarter turns are exact, so that "rotate 90 degrees" moves
// (1, 0, 0) to exactly (0, 1, 0) rather than to (6e-17, 1, 0).
void exactCosSin(double degrees, double& c, double& s) {
    const double quarters = degrees / 90.0;
    if (quarters == std::floor(quarters) && std::abs(quarters) < 1e15) {
        const long long q = static_cast<long long>(quarters) % 4;
        static constexpr double kCos[4] = {1, 0, -1, 0};
        static constexpr double kSin[4] = {0, 1, 0, -1};
        const int i = int((q + 4) % 4);
        c = kCos[i];
        s = kSin[i];
        return;
    }
    const double a = radians(degrees);
    c = std::cos(a);
    s = std::sin(a);
}

}  // namespace

M44d Transform::toMatrix() const {
    if (isMatrix) return matrix;

    // Rodrigues' rotation about the unit axis (right-hand rule), in column-vector form.
    double r[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    if (hasRotate && rotateAxis.length() > 0) {
        const V3d k = rotateAxis / rotateAxis.length();
        double c = 1, s = 0;
        exactCosSin(rotateDeg, c, s);
        const double t = 1 - c;
        r[0][0] = t * k.x * k.x + c;        r[0][1] = t * k.x * k.y - s * k.z;  r[0][2] = t * k.x * k.z + s * k.y;
        r[1][0] = t * k.x * k.y + s * k.z;  r[1][1] = t * k.y * k.y + c;        r[1][2] = t * k.y * k.z - s * k.x;
        r[2][0] = t * k.x * k.z - s * k.y;  r[2][1] = t * k.y * k.z + s * k.x;  r[2][2] = t * k.z * k.z + c;
    }
    // M = T * R * S: the columns of R scaled by S, translation in the last column.
    M44d m;  // identity
    const double sc[3] = {scale.x, scale.y, scale.z};
    const double tr[3] = {translate.x, translate.y, translate.z};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) m[i][j] = r[i][j] * sc[j];
        m[i][3] = tr[i];
    }
    return m;
}

const Material* Scene::findMaterial(const std::string& name) const {
    const int i = materialIndex(name);
    return i < 0 ? nullptr : &materials[size_t(i)];
}

int Scene::materialIndex(const std::string& name) const {
    for (size_t i = 0; i < materials.size(); ++i)
        if (materials[i].name == name) return int(i);
    return -1;
}

SceneSnapshot withoutLightsSwitchedOff(SceneSnapshot scene) {
    if (!scene || std::all_of(scene->lights.begin(), scene->lights.end(), [](const Light& l) { return l.on; })) return scene;
    auto lit = std::make_shared<Scene>(*scene);
    std::erase_if(lit->lights, [](const Light& l) { return !l.on; });
    return lit;
}

double MaintenanceFactor::factor() const {
    if (value) return *value;
    return lampLumenMaintenance.value_or(1) * lampSurvival.value_or(1) * luminaireMaintenance.value_or(1) *
           roomSurfaceMaintenance.value_or(1);
}

double maintenanceFactor(const Scene& scene, const Light& light) {
    if (light.type == LightType::Sun || light.type == LightType::Directional) return 1;
    if (light.maintenance) return light.maintenance->factor();
    return scene.maintenance ? scene.maintenance->factor() : 1;
}

namespace {

bool hasEmitterObjects(const Scene& scene) {
    return std::any_of(scene.objects.begin(), scene.objects.end(), [&](const Object& o) {
        const Material* m = scene.findMaterial(o.material);
        return m && m->type == MaterialType::Emitter;
    });
}

}  // namespace

MaintenanceRange maintenanceRange(const Scene& scene) {
    std::vector<double> factors;
    for (const Light& l : scene.lights)
        if (l.on && l.type != LightType::Sun && l.type != LightType::Directional)
            factors.push_back(maintenanceFactor(scene, l));
    if (hasEmitterObjects(scene)) factors.push_back(scene.maintenance ? scene.maintenance->factor() : 1.0);
    if (factors.empty()) return {};
    const auto [lo, hi] = std::minmax_element(factors.begin(), factors.end());
    return {*lo, *hi, true};
}

std::string describeMaintenance(const MaintenanceRange& range) {
    if (!range.electric) return "daylight only (no electric light to maintain)";
    if (!range.maintained()) return "values of the new installation (no maintenance factor)";
    if (range.lowest == range.highest) return "maintained values (maintenance factor " + fixedNumber(range.lowest, 2) + ")";
    return "maintained values (maintenance factors " + fixedNumber(range.lowest, 2) + " to " +
           fixedNumber(range.highest, 2) + ")";
}

SceneSnapshot sceneAsRendered(SceneSnapshot scene) {
    scene = withoutLightsSwitchedOff(std::move(scene));
    if (!scene || !maintenanceRange(*scene).maintained()) return scene;
    auto maintained = std::make_shared<Scene>(*scene);
    for (Light& l : maintained->lights) {
        const double mf = maintenanceFactor(*scene, l);
        if (mf == 1) continue;
        l.intensity *= mf;
        if (l.luminaire && l.luminaire->distribution)
            l.luminaire->lumens = l.luminaire->lumens.value_or(l.luminaire->distribution->integratedFlux()) * mf;
    }
    if (scene->maintenance)
        for (Material& m : maintained->materials)
            if (m.type == MaterialType::Emitter) m.radiance *= scene->maintenance->factor();
    return maintained;
}

Scene withoutMaintenance(Scene scene) {
    scene.maintenance.reset();
    for (Light& l : scene.lights) l.maintenance.reset();
    return scene;
}

SceneFeatures analyseFeatures(const Scene& scene) {
    SceneFeatures f;
    for (const Object& o : scene.objects) {
        // Before resolveMeshes there is no world mesh; inline and quad meshes still say how many
        // triangles they will have (degenerate ones included), file meshes do not.
        size_t count = 0;
        bool known = true;
        if (o.worldMesh) count = o.worldMesh->triangles.size();
        else if (o.mesh.kind == MeshSource::Kind::Inline) count = o.mesh.inlineMesh.triangles.size();
        else if (o.mesh.kind == MeshSource::Kind::Quad) count = 2;
        else known = false;
        f.triangles += count;

        // An object known to have no triangles does not call for its material's model.
        const Material* m = scene.findMaterial(o.material);
        if (!m || (known && count == 0)) continue;
        switch (m->type) {
        case MaterialType::Diffuse: f.hasDiffuse = true; break;
        case MaterialType::Glossy: f.hasGlossy = true; break;
        case MaterialType::Mirror: f.hasMirror = true; break;
        case MaterialType::Dielectric: f.hasDielectric = true; break;
        case MaterialType::Emitter: f.emitterTriangles += int(count); break;
        case MaterialType::Glazing: f.hasGlazing = true; break;
        }
    }
    for (const Light& l : scene.lights) {
        if (!l.on) continue;  // a light switched off calls for nothing
        switch (l.type) {
        case LightType::Point: ++f.pointLights; break;
        case LightType::Spot: ++f.spotLights; break;
        case LightType::Directional: ++f.directionalLights; break;
        case LightType::Luminaire: ++f.luminaires; break;
        case LightType::Sun: f.hasSun = true; break;
        }
    }
    f.hasSky = scene.sky.has_value();
    return f;
}

}  // namespace lucerna
