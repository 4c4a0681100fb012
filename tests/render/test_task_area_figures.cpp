// EN 12464-1:2021's figures of a task area (render/photometry/task_area_figures.h) against
// closed forms: the cylindrical illuminance Ez and Eh of an isotropic point light and of a small
// Lambertian disc (Ez = I sin(eps) / (pi d^2), Eh = I cos(eps) / d^2), exact for the delta light
// with path and ir, within the Monte Carlo error bar for the disc; the walls' and ceiling's
// average illuminance in a closed cube lit from its centre (Phi / ((1 - rho) 6 a^2): all the
// flux is absorbed in the end, a sixth by each face), and direct only (rho = 0) exactly at the
// sensors. Then the room a task area lies in (a drawn room, a marked one, the scene's bounds),
// the Ez grid's height for each posture, and the `posture` key both ways.

#include "core/photometry/lighting_standards.h"
#include "core/scene/room_geometry.h"
#include "core/scene/scene_io.h"
#include "render/photometry/grid_calculation.h"
#include "render/photometry/task_area_figures.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace lucerna;

namespace {

const std::string kResources = LUCERNA_RESOURCE_DIR;
constexpr double pi = std::numbers::pi;

SceneSnapshot parse(const std::string& json) {
    return std::make_shared<const Scene>(parseScene(json, kResources + "/scenes/case.json"));
}

std::string sceneJson(const std::string& materials, const std::string& objects, const std::string& lights,
                      const std::string& extra = {}) {
    return R"({"lucerna": 1, "camera": {"position": [0, 2, 6], "target": [0, 0, 0], "fov_y": 40, "resolution": [16, 16]},
  "materials": {)" + materials + R"(}, "objects": [)" + objects + R"(], "lights": [)" + lights + "]" + extra + "}\n";
}

GridResult gridOf(const SceneSnapshot& scene, const std::vector<V3d>& points, const GridSettings& settings) {
    TaskSystem tasks(0);
    GridResult result;
    auto job = tasks.submit(
        [&](TaskContext& ctx) { result = computeSceneGrid(scene, points, V3d(0, 1, 0), settings, ctx); });
    job->wait();
    job->rethrowIfFailed();
    return result;
}

// The grid's points at angles eps from the vertical below a source at height h (y = 0).
constexpr double kSourceHeight = 2;
const double kAngles[] = {15, 35, 55, 75};  // degrees
std::vector<V3d> pointsBelow() {
    std::vector<V3d> points;
    for (double eps : kAngles) points.emplace_back(kSourceHeight * std::tan(eps * pi / 180), 0, 0);
    return points;
}

struct ClosedForm {
    double eh, ez;
};
// Eh and Ez at pointsBelow(), by one method and its settings.
std::pair<GridResult, GridResult> ehAndEz(const SceneSnapshot& scene, GridSettings settings) {
    GridResult eh = gridOf(scene, pointsBelow(), settings);
    settings.quantity = GridQuantity::Cylindrical;
    return {std::move(eh), gridOf(scene, pointsBelow(), settings)};
}

// A source of intensity intensityCd(eps) toward each point.
template <class Intensity> std::vector<ClosedForm> closedForms(const Intensity& intensityCd) {
    std::vector<ClosedForm> out;
    for (double eps : kAngles) {
        const double e = eps * pi / 180, d = kSourceHeight / std::cos(e), i = intensityCd(e);
        out.push_back({i * std::cos(e) / (d * d), i * std::sin(e) / (pi * d * d)});
    }
    return out;
}

// A black floor far below, so that nothing comes back.
const std::string kBlack = R"("black": {"type": "diffuse", "albedo": [0, 0, 0]})";
const std::string kBlackFloor =
    R"({"name": "floor", "material": "black", "mesh": {"quad": [[-60, -40, -60], [-60, -40, 60], [60, -40, 60], [60, -40, -60]]}})";

// A closed cube [0, a]^3 of albedo rho, a point light of `candela` at its centre.
std::string cubeJson(double a, double rho, double candela, const std::string& extra = {}) {
    const std::string s = QString::number(a).toStdString(), half = QString::number(a / 2).toStdString();
    const auto v = [&](int x, int y, int z) {
        return "[" + std::string(x ? s : "0") + ", " + (y ? s : "0") + ", " + (z ? s : "0") + "]";
    };
    const auto quad = [&](const char* name, std::initializer_list<std::array<int, 3>> c) {
        std::string q = std::string(R"({"name": ")") + name + R"(", "material": "walls", "mesh": {"quad": [)";
        int k = 0;
        for (const auto& p : c) q += (k++ ? ", " : "") + v(p[0], p[1], p[2]);
        return q + "]}}";
    };
    const std::string objects = quad("floor", {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}) + ",\n" +
                                quad("ceiling", {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}}) + ",\n" +
                                quad("x0", {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}}) + ",\n" +
                                quad("x1", {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}) + ",\n" +
                                quad("z0", {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}) + ",\n" +
                                quad("z1", {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}});
    const std::string r = QString::number(rho).toStdString();
    return sceneJson(R"("walls": {"type": "diffuse", "albedo": [)" + r + ", " + r + ", " + r + "]}", objects,
                     R"({"name": "bulb", "type": "point", "position": [)" + half + ", " + half + ", " + half +
                         R"(], "candela": )" + QString::number(candela).toStdString() + "}",
                     extra);
}

// The direct illuminance of an isotropic source of `candela` at `source` on the sensors of the
// grids (their points, facing the grid's normal), averaged over the points (equal cells).
double directAverage(const std::vector<const RoomSurfaceGrid*>& grids, const V3d& source, double candela) {
    double sum = 0;
    size_t n = 0;
    for (const RoomSurfaceGrid* g : grids)
        for (const V3d& p : g->points) {
            const V3d to = source - p;
            const double d = to.length();
            sum += candela * std::max(0.0, to.dot(g->grid.normal()) / d) / (d * d);
            ++n;
        }
    return sum / double(n);
}

}  // namespace

class TestTaskAreaFigures : public QObject {
    Q_OBJECT
private slots:
    void cylindricalOfAPointLightIsExact();
    void cylindricalOfADiscWithinItsErrorBar();
    void roomSurfacesOfAClosedCube();
    void roomSurfacesDirectOnly();
    void roomSurfacesLeaveOutWindowsAndDoors();
    void taskAreaRoomIsTheRoomThatHoldsIt();
    void cylindricalGridStandsAtThePosturesHeight();
    void postureKeyBothWays();
};

void TestTaskAreaFigures::cylindricalOfAPointLightIsExact() {
    constexpr double candela = 1000;
    const SceneSnapshot scene = parse(sceneJson(kBlack, kBlackFloor,
                                                R"({"name": "bulb", "type": "point", "position": [0, 2, 0], "candela": 1000})"));
    const std::vector<ClosedForm> exact = closedForms([](double) { return candela; });
    for (GridMethod method : {GridMethod::Path, GridMethod::Vpl}) {
        GridSettings settings;
        settings.method = method;
        const auto [eh, ez] = ehAndEz(scene, settings);
        QVERIFY(eh.converged && ez.converged);
        for (size_t i = 0; i < exact.size(); ++i) {
            const QByteArray where = QByteArray(gridMethodName(method)) + " at " + QByteArray::number(kAngles[i]) +
                                     " deg: Eh " + QByteArray::number(eh.lux[i], 'g', 9) + " (" +
                                     QByteArray::number(exact[i].eh, 'g', 9) + "), Ez " +
                                     QByteArray::number(ez.lux[i], 'g', 9) + " (" + QByteArray::number(exact[i].ez, 'g', 9) + ")";
            QVERIFY2(std::abs(eh.lux[i] / exact[i].eh - 1) < 2e-6, where.constData());
            QVERIFY2(std::abs(ez.lux[i] / exact[i].ez - 1) < 2e-6, where.constData());
            QVERIFY2(std::abs(ez.lux[i] / eh.lux[i] - std::tan(kAngles[i] * pi / 180) / pi) < 2e-6, where.constData());
        }
    }
}

void TestTaskAreaFigures::cylindricalOfADiscWithinItsErrorBar() {
    // A 16-gon of radius 5 cm at 2 m, facing down: I(eps) = L A cos(eps), the point source's form
    // within (r / d)^2 ~ 6e-4.
    constexpr int sides = 16;
    constexpr double radius = 0.05, radiance = 200;  // W / (sr m^2): 683 x 200 cd/m^2
    std::string vertices = "[0, 2, 0]", triangles;
    for (int k = 0; k < sides; ++k) {
        const double t = 2 * pi * k / sides;
        vertices += ", [" + QString::number(radius * std::cos(t), 'g', 17).toStdString() + ", 2, " +
                    QString::number(radius * std::sin(t), 'g', 17).toStdString() + "]";
        triangles += std::string(k ? ", " : "") + "[0, " + std::to_string(1 + k) + ", " + std::to_string(1 + (k + 1) % sides) + "]";
    }
    const SceneSnapshot scene = parse(sceneJson(
        kBlack + R"(, "lamp": {"type": "emitter", "radiance": [200, 200, 200]})",
        kBlackFloor + R"(, {"name": "disc", "material": "lamp", "mesh": {"vertices": [)" + vertices + R"(], "triangles": [)" +
            triangles + "]}}",
        ""));
    const double area = 0.5 * sides * radius * radius * std::sin(2 * pi / sides);
    const std::vector<ClosedForm> exact = closedForms([&](double eps) { return 683 * radiance * area * std::cos(eps); });
    for (GridMethod method : {GridMethod::Path, GridMethod::Vpl}) {
        GridSettings settings;
        settings.method = method;
        settings.targetRelativeError = 0.03;
        settings.seed = 11;
        const auto [eh, ez] = ehAndEz(scene, settings);
        QVERIFY(eh.converged && ez.converged);
        for (size_t i = 0; i < exact.size(); ++i) {
            const QByteArray where = QByteArray(gridMethodName(method)) + " at " + QByteArray::number(kAngles[i]) +
                                     " deg: Eh " + QByteArray::number(eh.lux[i]) + " +- " + QByteArray::number(eh.errorLux[i]) +
                                     " (" + QByteArray::number(exact[i].eh) + "), Ez " + QByteArray::number(ez.lux[i]) +
                                     " +- " + QByteArray::number(ez.errorLux[i]) + " (" + QByteArray::number(exact[i].ez) + ")";
            QVERIFY2(eh.errorLux[i] > 0 && eh.errorLux[i] < 0.05 * exact[i].eh, where.constData());
            QVERIFY2(ez.errorLux[i] > 0 && ez.errorLux[i] < 0.05 * exact[i].ez, where.constData());
            QVERIFY2(std::abs(eh.lux[i] - exact[i].eh) < 3 * eh.errorLux[i], where.constData());
            QVERIFY2(std::abs(ez.lux[i] - exact[i].ez) < 3 * ez.errorLux[i], where.constData());
            // The ratio, within the two relative bars together.
            const double ratio = ez.lux[i] / eh.lux[i], expected = std::tan(kAngles[i] * pi / 180) / pi;
            QVERIFY2(std::abs(ratio / expected - 1) < 3 * (eh.errorLux[i] / eh.lux[i] + ez.errorLux[i] / ez.lux[i]),
                     where.constData());
        }
    }
}

void TestTaskAreaFigures::roomSurfacesOfAClosedCube() {
    constexpr double a = 2, rho = 0.5, candela = 100;
    const std::string area =
        R"(, "task_areas": [{"name": "desk", "corner": [0.5, 0.8, 1.5], "u": [1, 0, 0], "v": [0, 0, -1], "spacing": 0.5}])";
    const SceneSnapshot scene = parse(cubeJson(a, rho, candela, area));
    GridSettings settings;
    settings.targetRelativeError = 0.025;
    settings.seed = 5;
    TaskSystem tasks(0);
    TaskAreaExtras extras;
    auto job = tasks.submit([&](TaskContext& ctx) {
        extras = computeTaskAreaExtras(scene, scene->taskAreas[0], settings, {false, true}, ctx);
    });
    job->wait();
    job->rethrowIfFailed();
    QVERIFY(extras.complete && !extras.cylindrical && extras.roomSurfaces);
    QCOMPARE(extras.room.description, std::string("the scene's bounds"));
    const RoomSurfaceResult& r = *extras.roomSurfaces;
    QCOMPARE(r.grids.size(), size_t(5));
    // All the flux is absorbed in the end, a sixth by each face: Phi / ((1 - rho) 6 a^2) on
    // average. Of that, Phi / (6 a^2) is direct, which the grid samples at its sensors (a
    // centimetre in front of the faces, at the cells' centres): that part is taken exactly there,
    // the indirect rest, smooth, as its average.
    const double flux = 4 * pi * candela;
    const double indirect = rho / (1 - rho) * flux / (6 * a * a);
    const V3d centre(a / 2, a / 2, a / 2);
    std::vector<const RoomSurfaceGrid*> walls;
    const RoomSurfaceGrid* ceiling = nullptr;
    for (const RoomSurfaceGrid& g : r.grids) {
        if (g.ceiling) ceiling = &g;
        else walls.push_back(&g);
    }
    QVERIFY(ceiling && walls.size() == 4);
    const struct {
        const char* name;
        const SurfaceFigures& figures;
        double expected;
    } faces[] = {{"walls", r.walls, directAverage(walls, centre, candela) + indirect},
                 {"ceiling", r.ceiling, directAverage({ceiling}, centre, candela) + indirect}};
    for (const auto& f : faces) {
        const QByteArray where = QByteArray(f.name) + ": Eavg " + QByteArray::number(f.figures.stats.average) + " +- " +
                                 QByteArray::number(f.figures.errors.average) + " lx, expected " +
                                 QByteArray::number(f.expected) + " (closed form over the faces " +
                                 QByteArray::number(flux / ((1 - rho) * 6 * a * a)) + ")";
        QVERIFY2(f.figures.errorKnown && f.figures.stats.excluded == 0, where.constData());
        QVERIFY2(f.figures.errors.average > 0 && f.figures.errors.average < 0.03 * f.expected, where.constData());
        QVERIFY2(std::abs(f.figures.stats.average - f.expected) < 3 * f.figures.errors.average, where.constData());
        // The sensors' offset and the cells' centres move the grid's figure off the faces' own
        // average by a few per cent at most.
        QVERIFY2(std::abs(f.expected / (flux / ((1 - rho) * 6 * a * a)) - 1) < 0.02, where.constData());
    }
    QCOMPARE(r.walls.points, 4 * int(walls[0]->points.size()));
    QCOMPARE(r.ceiling.points, int(ceiling->points.size()));
}

void TestTaskAreaFigures::roomSurfacesDirectOnly() {
    // Black faces: the direct light alone, which every method sums exactly.
    constexpr double a = 2, candela = 100;
    const SceneSnapshot scene = parse(cubeJson(a, 0, candela));
    TaskSystem tasks(0);
    RoomSurfaceResult r;
    auto job = tasks.submit([&](TaskContext& ctx) {
        r = computeRoomSurfaces(scene, V3d(0, 0, 0), V3d(a, a, a), GridSettings{}, ctx);
    });
    job->wait();
    job->rethrowIfFailed();
    QVERIFY(r.complete);
    std::vector<const RoomSurfaceGrid*> walls;
    for (const RoomSurfaceGrid& g : r.grids)
        if (!g.ceiling) walls.push_back(&g);
    const V3d centre(a / 2, a / 2, a / 2);
    const double wallsExact = directAverage(walls, centre, candela), ceilingExact = directAverage({&r.grids.back()}, centre, candela);
    QVERIFY(r.grids.back().ceiling);
    QVERIFY2(std::abs(r.walls.stats.average / wallsExact - 1) < 2e-6,
             qPrintable(QString("walls %1, exact %2").arg(r.walls.stats.average, 0, 'g', 9).arg(wallsExact, 0, 'g', 9)));
    QVERIFY2(std::abs(r.ceiling.stats.average / ceilingExact - 1) < 2e-6,
             qPrintable(QString("ceiling %1, exact %2").arg(r.ceiling.stats.average, 0, 'g', 9).arg(ceilingExact, 0, 'g', 9)));
    // The faces' own average is a sixth of the flux over each: the grid's is that within the
    // cells' and the sensors' offset (7 x 7 cells, 1 cm in front: 1.6%).
    const double faceAverage = 4 * pi * candela / (6 * a * a);
    QVERIFY(std::abs(wallsExact / faceAverage - 1) < 0.02);
    QVERIFY(std::abs(ceilingExact / faceAverage - 1) < 0.02);
    // The ceiling is a wall turned: the same sensors about the light, the same figures.
    QVERIFY(std::abs(r.walls.stats.minimum / r.ceiling.stats.minimum - 1) < 1e-5);
    QVERIFY(std::abs(r.walls.stats.maximum / r.ceiling.stats.maximum - 1) < 1e-5);
}

void TestTaskAreaFigures::roomSurfacesLeaveOutWindowsAndDoors() {
    // A drawn 5 x 4 x 2.8 m room, its surfaces generated as the window generates them, with a
    // glazed window in wall 1 (z = 0) and a door, a hole, in wall 2 (x = 5): EN 12464-1 asks for
    // the walls' surfaces, so exactly the points in front of the window and the door are left out.
    Scene loaded = parseScene(sceneJson(
        R"("grey": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}, "pane": {"type": "glazing", "transmittance": [0.7, 0.7, 0.7]})",
        "", R"({"name": "bulb", "type": "point", "position": [2.5, 2.5, 2], "intensity": [1, 1, 1]})",
        R"(, "rooms": [{"name": "office", "outline": [[0, 0], [5, 0], [5, 4], [0, 4]], "floor_level": 0, "height": 2.8,
                        "materials": {"floor": "grey", "walls": "grey", "ceiling": "grey"},
                        "openings": [{"type": "window", "wall": 1, "offset": 1.5, "sill": 0.9, "width": 2, "height": 1.4, "glazing": "pane"},
                                     {"type": "door", "wall": 2, "offset": 1, "width": 0.9, "height": 2.1}]}])"),
        kResources + "/scenes/case.json");
    std::set<std::string> taken;
    const std::vector<Object> surfaces = roomSurfaces(loaded.rooms[0], loaded, taken);
    loaded.objects.insert(loaded.objects.end(), surfaces.begin(), surfaces.end());
    const RenderScene scene(std::make_shared<const Scene>(std::move(loaded)), 16, 16);
    const std::vector<RoomSurfaceGrid> grids = roomSurfaceGrids(scene, V3d(0, 0, 0), V3d(5, 2.8, 4), 1.0);
    QCOMPARE(grids.size(), size_t(5));
    // Where each point's cell centre lies on the box's face: in the window (x 1.5..3.5, y 0.9..2.3
    // on z = 0) or the door (z 1..1.9, y 0..2.1 on x = 5).
    const auto inWindow = [](const V3d& p) { return p.z < 1e-9 && p.x > 1.5 && p.x < 3.5 && p.y > 0.9 && p.y < 2.3; };
    const auto inDoor = [](const V3d& p) { return p.x > 5 - 1e-9 && p.z > 1 && p.z < 1.9 && p.y < 2.1; };
    // A point on an opening's edge may go either way.
    const auto onEdge = [](const V3d& p) {
        for (double c : {p.x - 1.5, p.x - 3.5, p.y - 0.9, p.y - 2.3, p.z - 1, p.z - 1.9, p.y - 2.1})
            if (std::abs(c) < 1e-6) return true;
        return false;
    };
    int window = 0, door = 0, wall = 0;
    for (const RoomSurfaceGrid& g : grids)
        for (size_t i = 0; i < g.layout.points.size(); ++i) {
            const V3d& p = g.layout.points[i];
            if (onEdge(p)) continue;
            const bool opening = inWindow(p) || inDoor(p);
            QVERIFY2(bool(g.opening[i]) == opening,
                     qPrintable(QString("%1 point (%2, %3, %4): opening %5").arg(QString::fromStdString(g.name))
                                    .arg(p.x).arg(p.y).arg(p.z).arg(int(g.opening[i]))));
            window += inWindow(p);
            door += inDoor(p);
            wall += !opening;
        }
    QVERIFY2(window >= 4 && door >= 2 && wall > 100,
             qPrintable(QString("window %1, door %2, wall %3 points").arg(window).arg(door).arg(wall)));
}

void TestTaskAreaFigures::taskAreaRoomIsTheRoomThatHoldsIt() {
    // A drawn room (office), a marked one (lobby: the bounds of its surfaces) and ground beyond
    // both, with task areas in each, one above the office and one outside every room.
    const auto area = [](const char* name, const char* corner) {
        return std::string(R"({"name": ")") + name + R"(", "corner": )" + corner + R"(, "u": [1, 0, 0], "v": [0, 0, -1]})";
    };
    const SceneSnapshot scene = parse(sceneJson(
        R"("grey": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]})",
        R"({"name": "ground", "material": "grey", "mesh": {"quad": [[-5, -1, -5], [-5, -1, 8], [30, -1, 8], [30, -1, -5]]}},
           {"name": "lobby floor", "material": "grey", "room": "lobby", "mesh": {"quad": [[10, 0.5, 0], [10, 0.5, 3], [14, 0.5, 3], [14, 0.5, 0]]}},
           {"name": "lobby ceiling", "material": "grey", "room": "lobby", "mesh": {"quad": [[10, 3.5, 0], [14, 3.5, 0], [14, 3.5, 3], [10, 3.5, 3]]}})",
        R"({"name": "bulb", "type": "point", "position": [2, 2.5, 1.5], "intensity": [1, 1, 1]})",
        R"(, "rooms": [{"name": "office", "outline": [[0, 0], [4, 0], [4, 3], [0, 3]], "floor_level": 0, "height": 2.8,
                        "materials": {"floor": "grey", "walls": "grey", "ceiling": "grey"}},
                       {"name": "lobby"}],
            "task_areas": [)" + area("desk", "[1, 0.8, 2]") + ", " + area("loft", "[1, 3.2, 2]") + ", " +
            area("counter", "[11, 1.3, 2]") + ", " + area("yard", "[20, 0, 2]") + "]"));
    const TaskAreaRoom desk = taskAreaRoom(*scene, scene->taskAreas[0]);
    QCOMPARE(desk.description, std::string("room 'office'"));
    QCOMPARE(desk.lo, V3d(0, 0, 0));
    QCOMPARE(desk.hi, V3d(4, 2.8, 3));
    QCOMPARE(desk.floorLevel, 0.0);
    const TaskAreaRoom counter = taskAreaRoom(*scene, scene->taskAreas[2]);
    QCOMPARE(counter.description, std::string("room 'lobby'"));
    QCOMPARE(counter.lo, V3d(10, 0.5, 0));
    QCOMPARE(counter.hi, V3d(14, 3.5, 3));
    QCOMPARE(counter.floorLevel, 0.5);
    // Above the office's ceiling and outside every room: the scene's bounds, whose lowest point
    // is the floor.
    for (size_t i : {size_t(1), size_t(3)}) {
        const TaskAreaRoom r = taskAreaRoom(*scene, scene->taskAreas[i]);
        QCOMPARE(r.description, std::string("the scene's bounds"));
        QCOMPARE(r.lo, V3d(-5, -1, -5));
        QCOMPARE(r.hi, V3d(30, 3.5, 8));
        QCOMPARE(r.floorLevel, -1.0);
    }
}

void TestTaskAreaFigures::cylindricalGridStandsAtThePosturesHeight() {
    // A millimetre scene, an area whose u and v face down: the Ez grid faces up (its normal is the
    // cylinder's axis) at 1200 mm (seated) or 1600 mm (standing) above the room's floor.
    TaskArea area;
    area.grid.name = "bench";
    area.grid.corner = V3d(1000, 850, 2000);
    area.grid.edgeU = V3d(1600, 0, 0);
    area.grid.edgeV = V3d(0, 0, 800);
    area.grid.spacingMeters = 0.2;
    QCOMPARE(area.grid.normal(), V3d(0, -1, 0));
    TaskAreaRoom room;
    room.lo = V3d(0, 100, 0);
    room.hi = V3d(5000, 3100, 4000);
    room.floorLevel = 100;
    for (bool standing : {false, true}) {
        area.standing = standing;
        const CalculationGrid g = cylindricalGrid(area, room, 0.001);
        QCOMPARE(g.name, std::string("bench (Ez)"));
        QCOMPARE(g.corner.y, standing ? 1700.0 : 1300.0);
        QCOMPARE(g.normal(), V3d(0, 1, 0));
        QCOMPARE(g.spacingMeters, area.grid.spacingMeters);
        const GridLayout layout = layoutGrid(g, 0.001), own = layoutGrid(area.grid, 0.001);
        QCOMPARE(layout.points.size(), own.points.size());
        for (const V3d& p : layout.points) {  // over the area's rectangle in plan
            QVERIFY(p.x > 1000 && p.x < 2600 && p.z > 2000 && p.z < 2800);
            QCOMPARE(p.y, g.corner.y);
        }
    }
    QCOMPARE(kSeatedCylindricalHeightM, 1.2);
    QCOMPARE(kStandingCylindricalHeightM, 1.6);
}

void TestTaskAreaFigures::postureKeyBothWays() {
    const auto withPosture = [](const std::string& posture) {
        return sceneJson(kBlack, kBlackFloor, R"({"name": "bulb", "type": "point", "position": [0, 2, 0], "candela": 100})",
                         R"(, "task_areas": [{"name": "a", "corner": [0, 0, 0], "u": [1, 0, 0], "v": [0, 0, -1])" +
                             (posture.empty() ? std::string() : R"(, "posture": )" + posture) + "}]");
    };
    const SceneSnapshot standing = parse(withPosture(R"("standing")"));
    QVERIFY(standing->taskAreas[0].standing);
    const std::string written = saveSceneToString(*standing);
    QVERIFY2(written.find(R"("posture": "standing")") != std::string::npos, written.c_str());
    QVERIFY(*parse(written) == *standing);
    // Seated is the default: given or not, it is not written back.
    for (const std::string& seated : {std::string(R"("seated")"), std::string()}) {
        const SceneSnapshot s = parse(withPosture(seated));
        QVERIFY(!s->taskAreas[0].standing);
        QVERIFY(saveSceneToString(*s).find("posture") == std::string::npos);
    }
    for (const auto& [bad, message] :
         {std::pair<std::string, std::string>{R"("kneeling")", R"(task_areas[0].posture: unknown posture "kneeling" (expected "seated" or "standing"))"},
          {"1", "task_areas[0].posture"}}) {
        try {
            parse(withPosture(bad));
            QFAIL(("accepted posture " + bad).c_str());
        } catch (const SceneError& e) {
            const std::string what = e.what();
            QVERIFY2(what.find(message) != std::string::npos && what.find('\n') == std::string::npos, what.c_str());
        }
    }
}

QTEST_GUILESS_MAIN(TestTaskAreaFigures)
#include "test_task_area_figures.moc"
