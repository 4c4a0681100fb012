#include "ui/scene_panels/light_arrangement.h"

#include "core/number_format.h"
#include "core/scene/scene_geometry.h"
#include "ui/commands/light_group_commands.h"
#include "ui/document/document.h"

#include <QObject>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_set>

namespace lucerna {

namespace {

std::string num(double x) { return shortestNumber(x); }

// Lights along one side of length `side` (scene units): their count and the first one's offset
// from the side's start, and the step between them.
struct Line {
    int count;
    double first, step;
};

Line lineByCount(double side, int count) { return {count, side / count / 2, side / count}; }

Line lineBySpacing(double side, double spacing) {
    // A side that holds an exact number of spacings counts them all (floor(3 / 1) with rounding
    // must not give 2).
    const int count = std::max(1, int(std::floor(side / spacing * (1 + 1e-12))));
    return {count, (side - (count - 1) * spacing) / 2, spacing};
}

}  // namespace

FieldLayout layoutField(const FieldArrangement& f, double metersPerUnit) {
    for (double v : {f.x0, f.z0, f.x1, f.z1, f.ceilingY, f.suspensionM, f.spacingXm, f.spacingZm})
        if (!std::isfinite(v)) throw std::invalid_argument("the field's values must be finite numbers");
    const double x0 = std::min(f.x0, f.x1), x1 = std::max(f.x0, f.x1);
    const double z0 = std::min(f.z0, f.z1), z1 = std::max(f.z0, f.z1);
    const double width = x1 - x0, depth = z1 - z0;
    if (!(width > 0) || !(depth > 0))
        throw std::invalid_argument("the field's rectangle has no area (" + num(width) + " x " + num(depth) + ")");
    Line along{}, across{};
    if (f.bySpacing) {
        if (!(f.spacingXm > 0) || !(f.spacingZm > 0))
            throw std::invalid_argument("the spacing must be positive, got " + num(f.spacingXm) + " x " + num(f.spacingZm) + " m");
        const double sx = f.spacingXm / metersPerUnit, sz = f.spacingZm / metersPerUnit;
        // The counts before the lines are made: a tiny spacing must not build a huge field first.
        if (width / sx * (depth / sz) > 2.0 * kMaxFieldLights + 4)
            throw std::invalid_argument("a field is at most " + std::to_string(kMaxFieldLights) +
                                        " lights; this spacing gives about " + num(std::floor(width / sx) * std::floor(depth / sz)));
        along = lineBySpacing(width, sx);
        across = lineBySpacing(depth, sz);
    } else {
        if (f.columns < 1 || f.rows < 1)
            throw std::invalid_argument("a field has at least one column and one row, got " + std::to_string(f.columns) +
                                        " x " + std::to_string(f.rows));
        along = lineByCount(width, f.columns);
        across = lineByCount(depth, f.rows);
    }
    const long long total = (long long)along.count * across.count;
    if (total > kMaxFieldLights)
        throw std::invalid_argument("a field is at most " + std::to_string(kMaxFieldLights) + " lights, this one has " +
                                    std::to_string(along.count) + " x " + std::to_string(across.count) + " = " +
                                    std::to_string(total));
    FieldLayout layout;
    layout.columns = along.count;
    layout.rows = across.count;
    layout.positions.reserve(size_t(total));
    const double y = f.ceilingY - f.suspensionM / metersPerUnit;
    for (int j = 0; j < across.count; ++j)
        for (int i = 0; i < along.count; ++i)
            layout.positions.emplace_back(x0 + along.first + i * along.step, y, z0 + across.first + j * across.step);
    return layout;
}

double ceilingAbove(const Scene& scene, double x, double z) {
    // The triangles whose plan covers the point, at their height there (barycentric in x, z).
    std::optional<double> highest;
    for (const Object& o : scene.objects) {
        if (!o.worldMesh) continue;
        const TriangleMesh& m = *o.worldMesh;
        for (const V3i& t : m.triangles) {
            const V3d &a = m.vertices[size_t(t.x)], &b = m.vertices[size_t(t.y)], &c = m.vertices[size_t(t.z)];
            const double det = (b.x - a.x) * (c.z - a.z) - (c.x - a.x) * (b.z - a.z);
            if (std::abs(det) < 1e-12) continue;  // seen edge-on from above: a wall
            const double u = ((x - a.x) * (c.z - a.z) - (c.x - a.x) * (z - a.z)) / det;
            const double v = ((b.x - a.x) * (z - a.z) - (x - a.x) * (b.z - a.z)) / det;
            if (u < -1e-9 || v < -1e-9 || u + v > 1 + 1e-9) continue;
            const double y = a.y + u * (b.y - a.y) + v * (c.y - a.y);
            if (!highest || y > *highest) highest = y;
        }
    }
    return highest.value_or(sceneBounds(scene).hi.y);
}

std::vector<Light> fieldLights(const Scene& scene, const FieldLayout& layout, const Light& prototype,
                               const std::string& group) {
    std::unordered_set<std::string> used;
    for (const Object& o : scene.objects) used.insert(o.name);
    for (const Light& l : scene.lights) used.insert(l.name);
    const auto unique = [&used](const std::string& base) {
        std::string name = base;
        for (int k = 2; used.count(name); ++k) name = base + "-" + std::to_string(k);
        used.insert(name);
        return name;
    };
    std::vector<Light> lights;
    lights.reserve(layout.positions.size());
    for (int j = 0; j < layout.rows; ++j)
        for (int i = 0; i < layout.columns; ++i) {
            Light l = prototype;
            l.name = unique(group + "-" + std::to_string(j + 1) + "-" + std::to_string(i + 1));
            l.group = group;
            l.on = true;
            l.position = layout.positions[size_t(j) * size_t(layout.columns) + size_t(i)];
            // A luminaire's output is its file's: photometric keys of the light it was made from
            // mean nothing for it (and the file would not keep them).
            if (l.type == LightType::Luminaire) l.photometric.reset();
            lights.push_back(std::move(l));
        }
    return lights;
}

std::string unusedGroupName(const Scene& scene, const std::string& base) {
    std::unordered_set<std::string> used;
    for (const Light& l : scene.lights) used.insert(l.group);
    std::string name = base;
    for (int k = 2; used.count(name); ++k) name = base + "-" + std::to_string(k);
    return name;
}

int arrangeField(Document& doc, const FieldArrangement& field, const Light& prototype, const std::string& group) {
    if (group.empty()) throw std::invalid_argument("the field's group needs a name");
    if (prototype.type == LightType::Directional)
        throw std::invalid_argument("a directional light has no position to arrange; choose a point, spot or luminaire");
    const FieldLayout layout = layoutField(field, doc.scene().metersPerUnit);
    std::vector<Light> lights = doc.scene().lights;
    std::vector<Light> added = fieldLights(doc.scene(), layout, prototype, group);
    const int count = int(added.size());
    lights.insert(lights.end(), std::make_move_iterator(added.begin()), std::make_move_iterator(added.end()));
    doc.undoStack()->push(new ReplaceLightsCommand(&doc, std::move(lights),
                                                   QObject::tr("Arrange %1 x %2 lights in %3")
                                                       .arg(layout.columns)
                                                       .arg(layout.rows)
                                                       .arg(QString::fromStdString(group))));
    return count;
}

}  // namespace lucerna
