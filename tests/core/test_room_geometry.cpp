// Parametric rooms (README, "Rooms"): the plan polygon's checks and its ear-clipping
// triangulation, the generated floor, ceiling and walls (areas, normals facing in, an L-shaped
// room, the holes of openings and their panes), the room edits the window makes (applied and
// reverted exactly, the new scene's floor taken away), marking a closed shell as a room, and the
// "rooms" key of the scene file: strict parsing with one-line errors and an exact round trip.

#include "core/scene/room_edit.h"
#include "core/scene/scene_io.h"

#include <QtTest>

#include <cmath>

using namespace lucerna;

namespace {

// The L: 6 x 6 m less the 3 x 3 m square at x > 3, z > 3 (area 27), counter-clockwise with z up.
const PlanPolygon kL{{0, 0}, {6, 0}, {6, 3}, {3, 3}, {3, 6}, {0, 6}};

double triangleArea2d(const PlanPolygon& p, const std::array<int, 3>& t) {
    const V2d a = p[size_t(t[1])] - p[size_t(t[0])], b = p[size_t(t[2])] - p[size_t(t[0])];
    return 0.5 * (a.x * b.y - a.y * b.x);
}

Material diffuse(const std::string& name, double r) {
    Material m;
    m.name = name;
    m.albedo = Rgbd(r, r, r);
    return m;
}

Scene sceneWithMaterials() {
    Scene s;
    s.materials = {diffuse("floor", 0.2), diffuse("walls", 0.5), diffuse("ceiling", 0.7)};
    Material glass;
    glass.name = "glass";
    glass.type = MaterialType::Glazing;
    glass.transmittance = Rgbd(0.7, 0.7, 0.7);
    s.materials.push_back(glass);
    return s;
}

Room lRoom() {
    Room r;
    r.name = "office";
    r.outline = kL;
    r.floorLevel = 0.5;
    r.height = 2.8;
    r.floorMaterial = "floor";
    r.wallMaterial = "walls";
    r.ceilingMaterial = "ceiling";
    return r;
}

RoomOpening window(int wall, double offset, double sill, double width, double height) {
    RoomOpening o;
    o.type = OpeningType::Window;
    o.wall = wall;
    o.offset = offset;
    o.sill = sill;
    o.width = width;
    o.height = height;
    o.glazing = "glass";
    return o;
}

struct Facet {
    V3d centroid, normal;  // unit normal (the front, SPEC.md)
    double area;
};

std::vector<Facet> facets(const Object& o) {
    std::vector<Facet> out;
    for (const V3i& t : o.worldMesh->triangles) {
        const V3d& a = o.worldMesh->vertices[size_t(t.x)];
        const V3d& b = o.worldMesh->vertices[size_t(t.y)];
        const V3d& c = o.worldMesh->vertices[size_t(t.z)];
        const V3d n = (b - a).cross(c - a);
        out.push_back({(a + b + c) / 3.0, n.normalized(), 0.5 * n.length()});
    }
    return out;
}

double area(const Object& o) {
    double sum = 0;
    for (const Facet& f : facets(o)) sum += f.area;
    return sum;
}

const Object* named(const std::vector<Object>& objects, const std::string& name) {
    for (const Object& o : objects)
        if (o.name == name) return &o;
    return nullptr;
}

std::string roomSceneJson(const std::string& rooms, const std::string& objectExtra = {}) {
    return R"({"lucerna": 1,
 "camera": {"position": [1, 1.6, 1], "target": [3, 1, 3], "fov_y": 50, "resolution": [64, 48]},
 "materials": {"floor": {"type": "diffuse", "albedo": [0.2, 0.2, 0.2]}, "walls": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]},
               "ceiling": {"type": "diffuse", "albedo": [0.7, 0.7, 0.7]}, "glass": {"type": "glazing", "transmittance": [0.7, 0.7, 0.7]}},
 "objects": [{"name": "box", "material": "walls", "mesh": {"quad": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]})" +
           objectExtra + R"(}],
 "rooms": )" + rooms + "}";
}

QString parseError(const std::string& json) {
    try {
        parseScene(json, "rooms.json");
    } catch (const SceneError& e) {
        return QString::fromStdString(e.what());
    }
    return QString();
}

}  // namespace

class TestRoomGeometry : public QObject {
    Q_OBJECT
private slots:
    void outlineChecks() {
        QVERIFY(!outlineProblem(kL));
        QCOMPARE(signedArea(kL), 27.0);
        const PlanPolygon bowTie{{0, 0}, {4, 4}, {4, 0}, {0, 4}};
        QCOMPARE(QString::fromStdString(outlineProblem(bowTie).value_or("")), QString("the outline crosses itself: walls 1 and 3 meet"));
        QVERIFY(outlineProblem(PlanPolygon{{0, 0}, {4, 0}, {4, 0}, {0, 4}})->find("wall 2 has no length") == 0);
        QVERIFY(outlineProblem(PlanPolygon{{0, 0}, {4, 0}})->find("at least 3 corners") != std::string::npos);
        QVERIFY(outlineProblem(PlanPolygon{{0, 0}, {4, 0}, {2, 0}, {2, 3}})->find("double back") != std::string::npos);
        // Two rooms' corners touching: a figure eight is not one room.
        QVERIFY(outlineProblem(PlanPolygon{{0, 0}, {2, 0}, {2, 2}, {4, 2}, {4, 4}, {2, 4}, {2, 2}, {0, 2}}));
        // A corner on a straight wall is allowed (two walls in line).
        QVERIFY(!outlineProblem(PlanPolygon{{0, 0}, {2, 0}, {4, 0}, {4, 3}, {0, 3}}));
        QVERIFY(containsPoint(kL, V2d(1, 5)) && !containsPoint(kL, V2d(5, 5)) && containsPoint(kL, V2d(3, 4.5)));
        QVERIFY(polygonsOverlap(kL, PlanPolygon{{2, 2}, {8, 2}, {8, 8}}));
        QVERIFY(!polygonsOverlap(kL, PlanPolygon{{4, 4}, {8, 4}, {8, 8}, {4, 8}}));
    }

    // Ear clipping covers the polygon exactly, every triangle turning as the polygon does, in
    // either orientation, through reflex corners and corners on straight runs.
    void triangulation_data() {
        QTest::addColumn<QVector<QPointF>>("corners");
        const auto poly = [](std::initializer_list<QPointF> l) { return QVector<QPointF>(l); };
        QTest::newRow("square") << poly({{0, 0}, {4, 0}, {4, 3}, {0, 3}});
        QTest::newRow("L") << poly({{0, 0}, {6, 0}, {6, 3}, {3, 3}, {3, 6}, {0, 6}});
        QTest::newRow("L clockwise") << poly({{0, 6}, {3, 6}, {3, 3}, {6, 3}, {6, 0}, {0, 0}});
        QTest::newRow("U") << poly({{0, 0}, {9, 0}, {9, 6}, {6, 6}, {6, 2}, {3, 2}, {3, 6}, {0, 6}});
        QTest::newRow("comb") << poly({{0, 0}, {10, 0}, {10, 5}, {9, 5}, {9, 1}, {7, 1}, {7, 5}, {5, 5}, {5, 1}, {3, 1}, {3, 5}, {0, 5}});
        QTest::newRow("straight run") << poly({{0, 0}, {2, 0}, {4, 0}, {4, 3}, {2, 3}, {0, 3}});
    }
    void triangulation() {
        QFETCH(QVector<QPointF>, corners);
        PlanPolygon p;
        for (const QPointF& c : corners) p.emplace_back(c.x(), c.y());
        QVERIFY(!outlineProblem(p));
        const auto triangles = triangulate(p);
        const double total = signedArea(p);
        double sum = 0;
        for (const auto& t : triangles) {
            const double a = triangleArea2d(p, t);
            QVERIFY2(a * total > 0, "a triangle turns against the polygon");
            sum += a;
            // Its middle is inside the polygon (no triangle bridges a notch).
            const V2d mid = (p[size_t(t[0])] + p[size_t(t[1])] + p[size_t(t[2])]) / 3.0;
            QVERIFY(containsPoint(p, mid));
        }
        QVERIFY(std::abs(sum - total) < 1e-12 * std::abs(total));
        // n - 2 triangles, none of them flat (a corner on a straight run may be skipped).
        if (QTest::currentDataTag() == QString("straight run")) QVERIFY(int(triangles.size()) <= int(p.size()) - 2);
        else QCOMPARE(int(triangles.size()), int(p.size()) - 2);
    }

    // The L-shaped room: floor and ceiling of the outline's area, walls of perimeter x height,
    // every face turned into the room: a step along its normal from its middle stays inside.
    void lShapedRoomFacesIn() {
        const Scene scene = sceneWithMaterials();
        std::set<std::string> taken;
        const std::vector<Object> surfaces = roomSurfaces(lRoom(), scene, taken);
        QCOMPARE(int(surfaces.size()), 2 + 6);
        const Object* floor = named(surfaces, "office floor");
        const Object* ceiling = named(surfaces, "office ceiling");
        QVERIFY(floor && ceiling && named(surfaces, "office wall 6"));
        QCOMPARE(floor->mesh.kind, MeshSource::Kind::Inline);  // not a rectangle
        QVERIFY(std::abs(area(*floor) - 27) < 1e-9);
        QVERIFY(std::abs(area(*ceiling) - 27) < 1e-9);
        double walls = 0;
        for (const Object& o : surfaces) {
            QCOMPARE(o.room, std::string("office"));
            for (const Facet& f : facets(o)) {
                if (&o == floor) QVERIFY(f.normal.y > 0.999 && std::abs(f.centroid.y - 0.5) < 1e-12);
                else if (&o == ceiling) QVERIFY(f.normal.y < -0.999 && std::abs(f.centroid.y - 3.3) < 1e-12);
                else {
                    QVERIFY(std::abs(f.normal.y) < 1e-12);
                    const V3d in = f.centroid + f.normal * 0.01;
                    QVERIFY2(containsPoint(kL, V2d(in.x, in.z)) && !containsPoint(kL, V2d(in.x - 0.02 * f.normal.x, in.z - 0.02 * f.normal.z)),
                             o.name.c_str());
                    walls += f.area;
                }
            }
        }
        QVERIFY(std::abs(walls - 24 * 2.8) < 1e-9);  // perimeter 24 m
        const RoomAreas areas = roomAreas(lRoom());
        QCOMPARE(areas.floor, 27.0);
        QVERIFY(std::abs(areas.walls - 24 * 2.8) < 1e-9);
        // The same room drawn clockwise faces in just the same.
        Room cw = lRoom();
        std::reverse(cw.outline.begin(), cw.outline.end());
        std::set<std::string> taken2;
        for (const Object& o : roomSurfaces(cw, scene, taken2))
            for (const Facet& f : facets(o))
                if (std::abs(f.normal.y) < 0.5) {
                    const V3d in = f.centroid + f.normal * 0.01;
                    QVERIFY(containsPoint(kL, V2d(in.x, in.z)));
                }
        // A rectangle's surfaces are quads.
        Room box = lRoom();
        box.outline = {{0, 0}, {5, 0}, {5, 4}, {0, 4}};
        std::set<std::string> taken3{"office floor"};  // a name already in use
        const auto rect = roomSurfaces(box, scene, taken3);
        QCOMPARE(rect[0].name, std::string("office floor 2"));
        for (const Object& o : rect) QCOMPARE(o.mesh.kind, MeshSource::Kind::Quad);
        QVERIFY(facets(rect[0])[0].normal.y > 0.999);
    }

    // Openings are holes in their wall: the wall's triangles leave them out; a window has a pane
    // of its glazing in the hole, a door and a plain opening none.
    void openingsCutHoles() {
        const Scene scene = sceneWithMaterials();
        Room room = lRoom();
        room.openings.push_back(window(1, 1, 0.9, 2, 1.2));  // wall 1: (0,0) to (6,0)
        room.openings.push_back(window(1, 3.5, 0.9, 1.5, 1.2));
        RoomOpening door;
        door.type = OpeningType::Door;
        door.wall = 4;  // (3,3) to (3,6), 3 m long
        door.offset = 1;
        door.width = 0.9;
        door.height = 2.1;
        room.openings.push_back(door);
        RoomOpening hatch = window(6, 0.5, 1, 0.6, 0.6);  // wall 6: (0,6) to (0,0)
        hatch.type = OpeningType::Opening;
        hatch.glazing.clear();
        room.openings.push_back(hatch);
        QVERIFY(!roomProblem(room, scene.materials));
        std::set<std::string> taken;
        const std::vector<Object> surfaces = roomSurfaces(room, scene, taken);
        QCOMPARE(int(surfaces.size()), 2 + 6 + 2);  // two panes
        const Object* wall1 = named(surfaces, "office wall 1");
        QCOMPARE(wall1->mesh.kind, MeshSource::Kind::Inline);
        QVERIFY(std::abs(area(*wall1) - (6 * 2.8 - 2 * 1.2 - 1.5 * 1.2)) < 1e-9);
        for (const Facet& f : facets(*wall1)) {
            QVERIFY(f.normal.z > 0.999);  // into the room, +z
            const double s = f.centroid.x, t = f.centroid.y - 0.5;
            const bool inHole = (s > 1 && s < 3 && t > 0.9 && t < 2.1) || (s > 3.5 && s < 5 && t > 0.9 && t < 2.1);
            QVERIFY2(!inHole, "a wall triangle covers a window");
        }
        QVERIFY(std::abs(area(*named(surfaces, "office wall 4")) - (3 * 2.8 - 0.9 * 2.1)) < 1e-9);
        QVERIFY(std::abs(area(*named(surfaces, "office wall 6")) - (6 * 2.8 - 0.36)) < 1e-9);
        const Object* pane = named(surfaces, "office window 2");
        QVERIFY(pane && pane->material == "glass");
        QVERIFY(std::abs(area(*pane) - 1.5 * 1.2) < 1e-12);
        const RoomAreas areas = roomAreas(room);
        QVERIFY(std::abs(areas.openings - (2.4 + 1.8 + 1.89 + 0.36)) < 1e-9);
        QVERIFY(std::abs(areas.walls - (24 * 2.8 - areas.openings)) < 1e-9);
    }

    void openingsThatDoNotFit() {
        const Scene scene = sceneWithMaterials();
        const auto problem = [&](const RoomOpening& o) {
            Room room = lRoom();
            room.openings = {window(2, 0.2, 0.9, 1, 1), o};
            const auto p = roomProblem(room, scene.materials);
            return p ? QString::fromStdString(p->key + ": " + p->problem) : QString();
        };
        QCOMPARE(problem(window(2, 2.5, 0.9, 1, 1)),
                 QString("openings[1]: the window does not fit wall 2, which is 3 long: offset 2.5 + width 1 = 3.5"));
        QCOMPARE(problem(window(1, 0, 2, 1, 1)),
                 QString("openings[1]: the window does not fit under the ceiling: sill 2 + height 1 = 3, above the room's height 2.8"));
        QCOMPARE(problem(window(2, 1, 1.5, 1, 1)), QString("openings[1]: the window overlaps openings[0] on wall 2"));
        QCOMPARE(problem(window(7, 0, 1, 1, 1)), QString("openings[1].wall: the room has walls 1 to 6, got 7"));
        RoomOpening noGlass = window(1, 0, 1, 1, 1);
        noGlass.glazing = "walls";
        QCOMPARE(problem(noGlass), QString("openings[1].glazing: material \"walls\" is not a glazing material"));
        QVERIFY(problem(window(2, 1.2, 0.9, 1, 1)).isEmpty());  // beside the first, touching it
    }

    // The window's edits: a new room added, its height edited (surfaces made again in place),
    // each reverted exactly; the new scene's floor under the room goes with the first.
    void editsApplyAndRevert() {
        Scene scene = sceneWithMaterials();
        Object ground;
        ground.name = "floor";
        ground.material = "floor";
        ground.mesh.kind = MeshSource::Kind::Quad;
        ground.mesh.quad = {V3d(-5, 0.5, -5), V3d(-5, 0.5, 5), V3d(5, 0.5, 5), V3d(5, 0.5, -5)};
        ground.worldMesh = std::make_shared<TriangleMesh>(TriangleMesh{{ground.mesh.quad.begin(), ground.mesh.quad.end()}, {{0, 1, 2}, {0, 2, 3}}});
        Object lamp = ground;
        lamp.name = "lamp";
        lamp.material = "walls";
        scene.objects = {ground, lamp};
        const Scene original = scene;

        Room room = lRoom();
        room.name = "lab";
        room.floorMaterial = room.wallMaterial = room.ceilingMaterial = "";
        std::vector<Material> materials = scene.materials;
        setRoomReflectances(room, materials, {0.3, 0.6, 0.8});
        QCOMPARE(room.wallMaterial, std::string("lab walls"));
        const RoomEdit add = placeRoom(scene, -1, room, materials, size_t(0));
        QVERIFY(add.removedPlaceholderFloor);
        applyRoomEdit(scene, add);
        QCOMPARE(int(scene.rooms.size()), 1);
        QCOMPARE(scene.objects[0].name, std::string("lamp"));
        QCOMPARE(int(scene.objects.size()), 1 + 8);
        // "floor" is still used by nothing: gone; the room's three are there.
        QVERIFY(!scene.findMaterial("floor") && scene.findMaterial("lab ceiling"));
        QCOMPARE(roomReflectances(room, scene.materials)[2].value_or(0), 0.8);
        const Scene added = scene;

        Room taller = scene.rooms[0];
        taller.height = 3.2;
        const RoomEdit edit = placeRoom(scene, 0, taller, scene.materials);
        QVERIFY(!edit.removedPlaceholderFloor);
        applyRoomEdit(scene, edit);
        QCOMPARE(int(scene.objects.size()), 1 + 8);
        QCOMPARE(scene.objects[1].name, std::string("lab floor"));  // in the old surfaces' place
        QVERIFY(std::abs(area(scene.objects[3]) - 6 * 3.2) < 1e-9);  // lab wall 1
        revertRoomEdit(scene, edit);
        QVERIFY(scene == added);
        revertRoomEdit(scene, add);
        QVERIFY(scene == original);
        QCOMPARE(scene.objects[0].worldMesh, original.objects[0].worldMesh);

        // A second room of the same name is refused; a room elsewhere leaves a floor alone.
        applyRoomEdit(scene, add);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, placeRoom(scene, -1, room, scene.materials));
        Room bad = scene.rooms[0];
        bad.outline = {{0, 0}, {4, 4}, {4, 0}, {0, 4}};
        try {
            placeRoom(scene, 0, bad, scene.materials);
            QFAIL("a crossed outline was built");
        } catch (const std::invalid_argument& e) {
            QCOMPARE(QString(e.what()), QString("outline: the outline crosses itself: walls 1 and 3 meet"));
        }
        // Removing the room takes its surfaces and the materials only they used.
        const RoomEdit gone = removeRoom(scene, 0);
        applyRoomEdit(scene, gone);
        QCOMPARE(int(scene.objects.size()), 1);
        QVERIFY(!scene.findMaterial("lab walls") && scene.findMaterial("walls"));
    }

    // Objects that close a shell are marked as a room (tagged, nothing generated); an open set
    // is refused with a count of the open edges.
    void markingAClosedShell() {
        Scene scene = sceneWithMaterials();
        Room box = lRoom();
        box.outline = {{0, 0}, {4, 0}, {4, 3}, {0, 3}};
        std::set<std::string> taken;
        scene.objects = roomSurfaces(box, scene, taken);
        for (Object& o : scene.objects) o.room.clear(), o.name = "imported " + o.name;
        const RoomEdit marked = markRoom(scene, "hall", {0, 1, 2, 3, 4, 5});
        applyRoomEdit(scene, marked);
        QCOMPARE(roomObjects(scene, "hall").size(), size_t(6));
        QVERIFY(!scene.rooms[0].parametric());
        QVERIFY(std::abs(roomFloorArea(scene, scene.rooms[0]) - 12) < 1e-9);  // the shell's bottom
        revertRoomEdit(scene, marked);
        try {
            markRoom(scene, "hall", {0, 2, 3, 4, 5});  // no ceiling
            QFAIL("an open set was marked");
        } catch (const std::invalid_argument& e) {
            QCOMPARE(QString(e.what()), QString("the selected objects do not form a closed shell: 4 edges belong to one face only"));
        }
    }

    // The scene file: the room and its surfaces as ordinary objects tagged with it, read back
    // exactly; a second write is the same text.
    void roundTrip() {
        Scene scene = parseScene(roomSceneJson(R"([{"name": "lobby"}])", R"(, "room": "lobby")"), "rooms.json");
        Room room = lRoom();
        room.openings = {window(1, 1, 0.9, 2, 1.2)};
        RoomOpening door;
        door.type = OpeningType::Door;
        door.wall = 4;
        door.offset = 1;
        door.width = 0.9;
        door.height = 2.1;
        room.openings.push_back(door);
        applyRoomEdit(scene, placeRoom(scene, -1, room, scene.materials));
        const std::string text = saveSceneToString(scene);
        QVERIFY(text.find(R"("rooms": [)") != std::string::npos);
        QVERIFY(text.find(R"({"name": "office floor", "material": "floor", "room": "office",)") != std::string::npos);
        const Scene back = parseScene(text, "rooms.json");
        QVERIFY(back == scene);
        QCOMPARE(saveSceneToString(back), text);
        QCOMPARE(back.rooms[1].openings[1].type, OpeningType::Door);
        // Without the additions the building is all there for a reader of SPEC.md alone.
        Scene plain = back;
        plain.rooms.clear();
        for (Object& o : plain.objects) o.room.clear();
        const std::string spec = saveSceneToString(plain);
        QVERIFY(spec.find("room") == std::string::npos);
        QCOMPARE(parseScene(spec, "plain.json").objects.size(), back.objects.size());
    }

    void parseErrors_data() {
        QTest::addColumn<QString>("rooms");
        QTest::addColumn<QString>("objectExtra");
        QTest::addColumn<QString>("error");
        const QString outline = R"("outline": [[0, 0], [4, 0], [4, 3], [0, 3]], "floor_level": 0, "height": 2.5, )"
                                R"("materials": {"floor": "floor", "walls": "walls", "ceiling": "ceiling"})";
        QTest::newRow("crossing") << R"([{"name": "a", "outline": [[0, 0], [4, 4], [4, 0], [0, 4]], "floor_level": 0, "height": 2.5, "materials": {"floor": "floor", "walls": "walls", "ceiling": "ceiling"}}])"
                                  << "" << "rooms.json: rooms[0].outline: the outline crosses itself: walls 1 and 3 meet";
        QTest::newRow("too wide") << "[{\"name\": \"a\", " + outline + R"(, "openings": [{"type": "door", "wall": 2, "offset": 2.5, "width": 0.9, "height": 2}]}])"
                                  << "" << "rooms.json: rooms[0].openings[0]: the door does not fit wall 2, which is 3 long: offset 2.5 + width 0.9 = 3.4";
        QTest::newRow("door sill") << "[{\"name\": \"a\", " + outline + R"(, "openings": [{"type": "door", "wall": 2, "offset": 0, "sill": 1, "width": 0.9, "height": 1}]}])"
                                   << "" << "rooms.json: rooms[0].openings[0].sill: unknown key for a door (expected one of: type, wall, offset, width, height)";
        QTest::newRow("wall") << "[{\"name\": \"a\", " + outline + R"(, "openings": [{"type": "opening", "wall": 5, "offset": 0, "sill": 1, "width": 0.9, "height": 1}]}])"
                              << "" << "rooms.json: rooms[0].openings[0].wall: the room has walls 1 to 4, got 5";
        QTest::newRow("type") << "[{\"name\": \"a\", " + outline + R"(, "openings": [{"type": "skylight"}]}])"
                              << "" << "rooms.json: rooms[0].openings[0].type: unknown opening type \"skylight\" (expected window, door or opening)";
        QTest::newRow("material") << R"([{"name": "a", "outline": [[0, 0], [4, 0], [4, 3]], "floor_level": 0, "height": 2.5, "materials": {"floor": "floor", "walls": "paint", "ceiling": "ceiling"}}])"
                                  << "" << "rooms.json: rooms[0].materials.walls: unknown material \"paint\"";
        QTest::newRow("height") << R"([{"name": "a", "outline": [[0, 0], [4, 0], [4, 3]], "floor_level": 0, "height": 0, "materials": {"floor": "floor", "walls": "walls", "ceiling": "ceiling"}}])"
                                << "" << "rooms.json: rooms[0].height: a room's height must be positive, got 0";
        QTest::newRow("corner") << R"([{"name": "a", "outline": [[0, 0], [4, 0, 1], [4, 3]]}])"
                                << "" << "rooms.json: rooms[0].outline[1]: expected an array of 2 numbers (x, z), got 3 elements";
        QTest::newRow("twice") << "[{\"name\": \"a\", " + outline + "}, {\"name\": \"a\", " + outline + "}]"
                               << "" << "rooms.json: rooms[1].name: another room is already named \"a\"";
        QTest::newRow("marked with height") << R"([{"name": "a", "height": 3}])" << R"(, "room": "a")"
                                            << "rooms.json: rooms[0].height: only a room with an outline takes this key (a room without one is marked on its objects)";
        QTest::newRow("marked, nothing") << R"([{"name": "a"}])" << ""
                                         << "rooms.json: rooms[0]: room \"a\" has no outline and no object is marked as its (\"room\": \"a\")";
        QTest::newRow("unknown room") << "[{\"name\": \"a\", " + outline + "}]" << R"(, "room": "b")"
                                      << "rooms.json: objects[0].room: unknown room \"b\" (rooms are listed under \"rooms\")";
        QTest::newRow("key") << "[{\"name\": \"a\", \"colour\": 1, " + outline + "}]" << ""
                             << "rooms.json: rooms[0].colour: unknown key (expected one of: name, outline, floor_level, height, materials, openings)";
    }
    void parseErrors() {
        QFETCH(QString, rooms);
        QFETCH(QString, objectExtra);
        QFETCH(QString, error);
        QCOMPARE(parseError(roomSceneJson(rooms.toStdString(), objectExtra.toStdString())), error);
    }
};

QTEST_MAIN(TestRoomGeometry)
#include "test_room_geometry.moc"
