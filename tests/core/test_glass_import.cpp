// Glass on import (core/mesh/model_import.h): a see-through material on an open sheet becomes a
// `glazing` pane, on a closed mesh a `dielectric` (core/mesh/mesh_edges.h tells them apart), and the
// report says which.

#include "core/mesh/mesh_edges.h"
#include "core/scene/scene_io.h"
#include "import_test_helpers.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace lucerna;
using namespace lucerna::test;

namespace {
// One see-through material (OBJ `d` and `Tf`) on a pane (an open quad) and on a block (a closed
// cube whose corners are repeated per face, as exporters do where normals differ).
const char* kGlassObj = R"(mtllib glass.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
vn 0 0 -1
vn 0 0 1
vn -1 0 0
vn 1 0 0
vn 0 -1 0
vn 0 1 0
o Pane
usemtl Glass
f 1 4 3 2
o Block
usemtl Glass
f 1//1 4//1 3//1 2//1
f 5//2 6//2 7//2 8//2
f 1//3 5//3 8//3 4//3
f 2//4 3//4 7//4 6//4
f 1//5 2//5 6//5 5//5
f 4//6 8//6 7//6 3//6
)";
const char* kGlassMtl = R"(newmtl Glass
Kd 0.8 0.8 0.8
d 0.1
Tf 0.9 1 0.9
)";

}  // namespace

class TestGlassImport : public QObject {
    Q_OBJECT
private slots:
    void meshEdgesTellSheetsFromSolids();
    void glassSheetsBecomeGlazing();

private:
    QTemporaryDir dir_;
};

void TestGlassImport::meshEdgesTellSheetsFromSolids() {
    // A quad: two triangles sharing the diagonal, four edges on the boundary.
    TriangleMesh quad{{V3d(0, 0, 0), V3d(1, 0, 0), V3d(1, 1, 0), V3d(0, 1, 0)}, {V3i(0, 1, 2), V3i(0, 2, 3)}};
    QCOMPARE(boundaryEdgeCount(quad), size_t(4));
    // A cube whose corners are repeated per face: welded by position, every edge has two sides.
    const V3d corner[8] = {V3d(0, 0, 0), V3d(1, 0, 0), V3d(1, 1, 0), V3d(0, 1, 0),
                           V3d(0, 0, 1), V3d(1, 0, 1), V3d(1, 1, 1), V3d(0, 1, 1)};
    const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 7, 6, 2}};
    TriangleMesh cube;
    for (const auto& f : faces) {
        const int base = int(cube.vertices.size());
        for (int k = 0; k < 4; ++k) cube.vertices.push_back(corner[f[k]]);
        cube.triangles.push_back(V3i(base, base + 1, base + 2));
        cube.triangles.push_back(V3i(base, base + 2, base + 3));
    }
    QCOMPARE(boundaryEdgeCount(cube), size_t(0));
    // Without its top it is open: the four edges around the hole.
    TriangleMesh box = cube;
    box.triangles.erase(box.triangles.begin() + 10, box.triangles.end());
    QCOMPARE(boundaryEdgeCount(box), size_t(4));
    // A triangle with two corners in one place adds no edge.
    quad.triangles.push_back(V3i(1, 1, 2));
    QCOMPARE(boundaryEdgeCount(quad), size_t(4));
}

void TestGlassImport::glassSheetsBecomeGlazing() {
    writeFile(dir_.filePath("glass.obj"), kGlassObj);
    writeFile(dir_.filePath("glass.mtl"), kGlassMtl);
    const ModelImport m = importModel(dir_.filePath("glass.obj").toStdString(), {});
    const QString report = joined(m.report);
    QCOMPARE(m.objects.size(), size_t(2));
    const Object* pane = objectNamed(m, "Pane");
    const Object* block = objectNamed(m, "Block");
    QVERIFY2(pane && block, qPrintable(report));
    QCOMPARE(pane->mesh.inlineMesh.triangles.size(), size_t(2));
    QCOMPARE(block->mesh.inlineMesh.triangles.size(), size_t(12));
    // One material, mapped both ways: glazing on the pane (1 - d, tinted by Tf), a clear
    // dielectric on the block.
    QCOMPARE(m.materials.size(), size_t(2));
    const Material* paneGlass = materialNamed(m, pane->material);
    const Material* blockGlass = materialNamed(m, block->material);
    QVERIFY(paneGlass && blockGlass && paneGlass != blockGlass);
    QCOMPARE(paneGlass->type, MaterialType::Glazing);
    QVERIFY2(near(paneGlass->transmittance, Rgbd(0.81, 0.9, 0.81)), qPrintable(report));
    QCOMPARE(blockGlass->type, MaterialType::Dielectric);
    QCOMPARE(blockGlass->ior, 1.5);
    // The report says which object became what.
    QVERIFY2(reportHas(m.report, "object 'Pane'", "open sheet (4 boundary edges) -> glazing '" + pane->material + "'"),
             qPrintable(report));
    QVERIFY2(reportHas(m.report, "object 'Block'", "closed mesh -> dielectric '" + block->material + "'"), qPrintable(report));
    QVERIFY2(reportHas(m.report, "material 'Glass'", "glazing, transmittance [0.81, 0.9, 0.81] = 1 - opacity 0.1"),
             qPrintable(report));
    QVERIFY2(reportHas(m.report, "material 'Glass'", "opacity 0.1 -> dielectric"), qPrintable(report));
    // The scene they make reads back (glazing is a SPEC.md material).
    Scene scene;
    scene.camera.position = V3d(0, 1, 5);
    scene.camera.target = V3d(0.5, 0.5, 0.5);
    scene.materials = m.materials;
    scene.objects = m.objects;
    QVERIFY(parseScene(saveSceneToString(scene), dir_.filePath("glass.json").toStdString()) == scene);
}

QTEST_GUILESS_MAIN(TestGlassImport)
#include "test_glass_import.moc"
