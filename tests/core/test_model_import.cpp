// Model import through Assimp (core/mesh/model_import.h) on files the test writes: an OBJ with its MTL
// (usemtl groups become objects with their Kd), a glTF 2.0 file with an embedded buffer (node
// transforms, metallic-roughness, transmission and emissive materials, KHR_lights_punctual), a
// COLLADA file in centimetres, bad files (glass on open sheets and closed meshes:
// test_glass_import.cpp). `lucerna import` and File > Import Model in the window:
// test_model_import_window.cpp.

#include "core/mesh/model_import.h"
#include "core/scene/scene_io.h"
#include "file_helpers.h"
#include "gltf_test_model.h"
#include "import_test_helpers.h"
#include "window_test_helpers.h"

#include <QBuffer>
#include <QImage>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>


using namespace lucerna;
using namespace lucerna::test;

// Declared before the files' raw strings, which moc's tokenizer does not follow.
class TestModelImport : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void objWithMtl();
    void gltfMaterialsLightsAndTransforms();
    void colladaUnit();
    void colladaLights();
    void fbxUnit();
    void texturesAveraged();
    void directionalLightOnly();
    void badFiles();

private:
    QTemporaryDir dir_;
};

namespace {



const char* kObj = R"(mtllib two.mtl
o Panels
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 2 0 0
v 3 0 0
v 3 1 0
usemtl Red
f 1 2 3 4
usemtl Blue
f 5 6 7
)";
const char* kMtl = R"(newmtl Red
Kd 0.8 0.1 0.1
Ks 0.5 0.5 0.5
newmtl Blue
Kd 0.1 0.2 0.9
)";

// One triangle 100 x 100 centimetres, translated 50 cm along x.
const char* kDae = R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="centimeter" meter="0.01"/><up_axis>Y_UP</up_axis></asset>
  <library_effects>
    <effect id="orange-fx"><profile_COMMON><technique sid="common"><lambert>
      <diffuse><color>0.9 0.5 0.1 1</color></diffuse>
    </lambert></technique></profile_COMMON></effect>
  </library_effects>
  <library_materials><material id="orange" name="Orange"><instance_effect url="#orange-fx"/></material></library_materials>
  <library_geometries>
    <geometry id="tri" name="Tri"><mesh>
      <source id="tri-pos"><float_array id="tri-pos-array" count="9">0 0 0 100 0 0 0 100 0</float_array>
        <technique_common><accessor source="#tri-pos-array" count="3" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common></source>
      <vertices id="tri-vtx"><input semantic="POSITION" source="#tri-pos"/></vertices>
      <triangles material="mat" count="1"><input semantic="VERTEX" source="#tri-vtx" offset="0"/><p>0 1 2</p></triangles>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="scene"><node id="n" name="TriNode"><translate>50 0 0</translate>
      <instance_geometry url="#tri"><bind_material><technique_common>
        <instance_material symbol="mat" target="#orange"/></technique_common></bind_material></instance_geometry>
    </node></visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)";
// The triangle's file with a point light (colour 50) 2 m up and a spot (colour 80, a 60 degree
// cone across) 3 m up and 1 m along x pointing down, both placed by their nodes in centimetres.
std::string daeWithLights() {
    std::string dae = kDae;
    const std::string lights = R"(  <library_lights>
    <light id="bulb-light" name="Bulb"><technique_common><point><color>50 50 50</color>
      <constant_attenuation>1</constant_attenuation></point></technique_common></light>
    <light id="spot-light" name="Spot"><technique_common><spot><color>80 80 80</color>
      <falloff_angle>60</falloff_angle></spot></technique_common></light>
  </library_lights>
)";
    dae.insert(dae.find("  <library_visual_scenes>"), lights);
    const std::string nodes = R"(<node id="bulb" name="Bulb"><translate>0 200 0</translate><instance_light url="#bulb-light"/></node>
      <node id="spot" name="Spot"><translate>100 300 0</translate><rotate>1 0 0 -90</rotate><instance_light url="#spot-light"/></node>
    )";
    dae.insert(dae.find("</visual_scene>"), nodes);
    return dae;
}

// FBX 7.4 ASCII: one triangle 100 x 100 units in inches (UnitScaleFactor 2.54 cm), its model
// translated 10 units along x, a Phong material.
const char* kFbx = R"(; FBX 7.4.0 project file
FBXHeaderExtension:  {
	FBXHeaderVersion: 1003
	FBXVersion: 7400
}
GlobalSettings:  {
	Version: 1000
	Properties70:  {
		P: "UpAxis", "int", "Integer", "",1
		P: "UpAxisSign", "int", "Integer", "",1
		P: "FrontAxis", "int", "Integer", "",2
		P: "FrontAxisSign", "int", "Integer", "",1
		P: "CoordAxis", "int", "Integer", "",0
		P: "CoordAxisSign", "int", "Integer", "",1
		P: "UnitScaleFactor", "double", "Number", "",2.54
	}
}
Objects:  {
	Geometry: 1000, "Geometry::Tri", "Mesh" {
		Vertices: *9 {
			a: 0,0,0,100,0,0,0,100,0
		}
		PolygonVertexIndex: *3 {
			a: 0,1,-3
		}
		GeometryVersion: 124
		LayerElementMaterial: 0 {
			Version: 101
			MappingInformationType: "AllSame"
			ReferenceInformationType: "IndexToDirect"
			Materials: *1 {
				a: 0
			}
		}
		Layer: 0 {
			Version: 100
			LayerElement:  {
				Type: "LayerElementMaterial"
				TypedIndex: 0
			}
		}
	}
	Model: 2000, "Model::TriModel", "Mesh" {
		Version: 232
		Properties70:  {
			P: "Lcl Translation", "Lcl Translation", "", "A",10,0,0
		}
	}
	Material: 3000, "Material::Wood", "" {
		Version: 102
		ShadingModel: "phong"
		Properties70:  {
			P: "DiffuseColor", "Color", "", "A",0.6,0.4,0.2
		}
	}
}
Connections:  {
	C: "OO",2000,0
	C: "OO",1000,2000
	C: "OO",3000,2000
}
)";
}  // namespace


void TestModelImport::initTestCase() {
    useTestSettings("test_model_import");
    QVERIFY(dir_.isValid());
}

void TestModelImport::objWithMtl() {
    writeFile(dir_.filePath("two.obj"), kObj);
    writeFile(dir_.filePath("two.mtl"), kMtl);
    ImportOptions options;
    options.sceneMetersPerUnit = 0.001;  // a millimetre scene; OBJ is taken as metres
    const ModelImport m = importModel(dir_.filePath("two.obj").toStdString(), options);
    QCOMPARE(m.objects.size(), size_t(2));
    QCOMPARE(m.materials.size(), size_t(2));
    QCOMPARE(m.lights.size(), size_t(0));
    QCOMPARE(m.triangles, size_t(3));
    const Material* red = materialNamed(m, "Red");
    const Material* blue = materialNamed(m, "Blue");
    QVERIFY(red && blue);
    QCOMPARE(red->type, MaterialType::Diffuse);
    QVERIFY(near(red->albedo, Rgbd(0.8, 0.1, 0.1)));
    QVERIFY(near(blue->albedo, Rgbd(0.1, 0.2, 0.9)));
    // Each group is an object with its material; the quad is two triangles.
    for (const Object& o : m.objects) {
        QCOMPARE(o.mesh.kind, MeshSource::Kind::Inline);
        QVERIFY(!o.transform);
        if (o.material == "Red") {
            QCOMPARE(o.mesh.inlineMesh.triangles.size(), size_t(2));
            double xmax = 0;
            for (const V3d& v : o.mesh.inlineMesh.vertices) xmax = std::max(xmax, v.x);
            QVERIFY(near(xmax, 1000.0));  // 1 m in millimetres
        } else {
            QCOMPARE(o.material, std::string("Blue"));
            QCOMPARE(o.mesh.inlineMesh.triangles.size(), size_t(1));
        }
    }
    QVERIFY(m.objects[0].name != m.objects[1].name);
    QVERIFY2(reportHas(m.report, "Red", "specular"), qPrintable(joined(m.report)));
    QVERIFY2(reportHas(m.report, "no unit", "metres"), qPrintable(joined(m.report)));
    QVERIFY2(reportHas(m.report, "2 object(s), 3 triangles"), qPrintable(joined(m.report)));

    // Names already in the scene are avoided: objects and lights together, materials apart.
    Scene scene;
    scene.materials.push_back(Material{.name = "Red"});
    Object taken;
    taken.name = m.objects[0].name;
    scene.objects.push_back(taken);
    options.into = &scene;
    const ModelImport again = importModel(dir_.filePath("two.obj").toStdString(), options);
    QVERIFY(!materialNamed(again, "Red") && materialNamed(again, "Red-2") && materialNamed(again, "Blue"));
    QVERIFY(!objectNamed(again, taken.name));
    for (const Object& o : again.objects) QVERIFY(materialNamed(again, o.material));
}

void TestModelImport::gltfMaterialsLightsAndTransforms() {
    ImportOptions options;
    options.sceneMetersPerUnit = 0.001;
    const ModelImport m = importModel(gltfModelPath(dir_).toStdString(), options);
    const QString report = joined(m.report);
    QCOMPARE(m.objects.size(), size_t(5));
    QCOMPARE(m.triangles, size_t(10));
    QCOMPARE(m.lights.size(), size_t(2));

    // Node transforms (translation and scale) and the unit: the Plain square spans
    // (0.1, 0.05, 0.03) to (0.25, 0.2, 0.03) m, in millimetres.
    const Object* plain = objectNamed(m, "Plain");
    QVERIFY2(plain, qPrintable(report));
    V3d lo(1e30), hi(-1e30);
    for (const V3d& v : plain->mesh.inlineMesh.vertices) {
        lo = V3d(std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z));
        hi = V3d(std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z));
    }
    QVERIFY2(near(lo, V3d(100, 50, 30), 1e-4) && near(hi, V3d(250, 200, 30), 1e-4),
             qPrintable(QString("%1 %2 %3 .. %4 %5 %6").arg(lo.x).arg(lo.y).arg(lo.z).arg(hi.x).arg(hi.y).arg(hi.z)));
    // The winding is kept: the square faces -z, toward a camera in front of it.
    const TriangleMesh& pm = plain->mesh.inlineMesh;
    const V3i t = pm.triangles[0];
    const V3d n = (pm.vertices[t.y] - pm.vertices[t.x]).cross(pm.vertices[t.z] - pm.vertices[t.x]);
    QVERIFY(n.z < 0);

    const auto material = [&](const std::string& object) {
        const Object* o = objectNamed(m, object);
        return o ? materialNamed(m, o->material) : nullptr;
    };
    const Material* diffuse = material("Plain");
    QVERIFY(diffuse && diffuse->type == MaterialType::Diffuse);
    QVERIFY(near(diffuse->albedo, Rgbd(0.2, 0.8, 0.3)));
    const Material* mirror = material("Chrome");
    QVERIFY(mirror && mirror->type == MaterialType::Mirror);
    QVERIFY(near(mirror->reflectance, Rgbd(0.9, 0.8, 0.7)));
    // The glass square is an open sheet: a pane of glazing, its transmission 1 times the white
    // base colour times a clear slab's (1 - R0) / (1 + R0) at ior 1.5, R0 = 0.04.
    const Material* glass = material("Glass");
    QVERIFY(glass && glass->type == MaterialType::Glazing);
    QVERIFY2(near(glass->transmittance, Rgbd(0.96 / 1.04, 0.96 / 1.04, 0.96 / 1.04)), qPrintable(report));
    const Material* lamp = material("Lamp");
    QVERIFY(lamp && lamp->type == MaterialType::Emitter);
    // emissiveFactor x KHR_materials_emissive_strength, taken as cd/m^2: luminance 683 Y(radiance).
    const double strength = lamp->radiance.x * 683.0;
    QVERIFY2(near(strength, 100.0, 1e-4) || near(strength, 1.0, 1e-4), qPrintable(QString::number(strength)));
    QVERIFY(near(lamp->radiance, Rgbd(1, 0.5, 0.25) * (strength / 683.0)));
    const Material* satin = material("Satin");
    QVERIFY(satin && satin->type == MaterialType::Glossy);
    QVERIFY(near(satin->albedo, Rgbd(0.5, 0.5, 0.5)));
    QVERIFY(near(satin->specular, Rgbd(0.04, 0.04, 0.04)));
    QVERIFY(near(satin->roughness, 0.16));

    // Lights follow their nodes; glTF intensities are candela.
    const Light* bulb = lightNamed(m, "Bulb");
    QVERIFY2(bulb, qPrintable(report));
    QCOMPARE(bulb->type, LightType::Point);
    QVERIFY(near(bulb->position, V3d(278, 400, 250), 1e-4));
    QVERIFY(bulb->photometric && bulb->photometric->quantity == PhotometricSpec::Quantity::Candela);
    QVERIFY(near(bulb->photometric->value, 100.0));
    QVERIFY(near(bulb->intensity, Rgbd(100, 100, 100) / 683.0));
    const Light* spot = lightNamed(m, "Spot");
    QVERIFY(spot);
    QCOMPARE(spot->type, LightType::Spot);
    QVERIFY(near(spot->position, V3d(200, 500, 250), 1e-4));
    QVERIFY2(near(spot->direction.normalized(), V3d(0, -1, 0), 1e-4),
             qPrintable(QString("%1 %2 %3").arg(spot->direction.x).arg(spot->direction.y).arg(spot->direction.z)));
    QVERIFY(near(spot->coneAngleDeg, 0.6 * 180 / M_PI, 1e-4));
    QVERIFY(spot->falloffStartDeg && near(*spot->falloffStartDeg, 0.3 * 180 / M_PI, 1e-4));
    // Colour x intensity is the radiometric intensity x 683: the candela are its luminance.
    QVERIFY(near(spot->intensity, Rgbd(50, 25, 25) / 683.0, 1e-4));
    QVERIFY(near(spot->photometric->value, luminance(Rgbd(50, 25, 25)), 1e-4));

    // The report says what was approximated.
    QVERIFY2(reportHas(m.report, "5 object(s), 10 triangles", "2 light(s)"), qPrintable(report));
    QVERIFY2(reportHas(m.report, "material 'Glass'", "on an open sheet -> glazing"), qPrintable(report));
    QVERIFY2(reportHas(m.report, "object 'Glass'", "open sheet (4 boundary edges) -> glazing 'Glass'"), qPrintable(report));
    QVERIFY2(reportHas(m.report, "'Chrome'", "mirror"), qPrintable(report));
    QVERIFY2(reportHas(m.report, "'Satin'", "glossy"), qPrintable(report));
    QVERIFY2(reportHas(m.report, "'Lamp'", "emitter"), qPrintable(report));
    QVERIFY2(reportHas(m.report, "'Bulb'", "100 cd"), qPrintable(report));
    QVERIFY2(reportHas(m.report, "'Spot'", "cone"), qPrintable(report));
    QVERIFY2(reportHas(m.report, "camera", "ignored"), qPrintable(report));
}

void TestModelImport::colladaUnit() {
    const QString path = dir_.filePath("tri.dae");
    writeFile(path, kDae);
    const ModelImport m = importModel(path.toStdString(), {});
    const QString report = joined(m.report);
    QCOMPARE(m.objects.size(), size_t(1));
    QCOMPARE(m.triangles, size_t(1));
    // Centimetres to metres, the node's translation too: (0.5, 0, 0), (1.5, 0, 0), (0.5, 1, 0).
    std::vector<V3d> v = m.objects[0].mesh.inlineMesh.vertices;
    QCOMPARE(v.size(), size_t(3));
    std::sort(v.begin(), v.end(), [](const V3d& a, const V3d& b) { return a.x + 10 * a.y < b.x + 10 * b.y; });
    QVERIFY2(near(v[0], V3d(0.5, 0, 0), 1e-5) && near(v[1], V3d(1.5, 0, 0), 1e-5) && near(v[2], V3d(0.5, 1, 0), 1e-5),
             qPrintable(QString("%1 %2 %3 / %4 %5 %6 / %7 %8 %9 (%10)").arg(v[0].x).arg(v[0].y).arg(v[0].z)
                            .arg(v[1].x).arg(v[1].y).arg(v[1].z).arg(v[2].x).arg(v[2].y).arg(v[2].z).arg(report)));
    QCOMPARE(m.materials.size(), size_t(1));
    QCOMPARE(m.materials[0].type, MaterialType::Diffuse);
    QVERIFY(near(m.materials[0].albedo, Rgbd(0.9, 0.5, 0.1)));
    QVERIFY2(reportHas(m.report, "COLLADA", "unit"), qPrintable(report));
}

// COLLADA lights: placed and aimed by their nodes (centimetres to metres), intensities read as
// candela since the format states no photometric unit, and the report says so.
void TestModelImport::colladaLights() {
    const QString path = dir_.filePath("lights.dae");
    writeFile(path, QByteArray::fromStdString(daeWithLights()));
    const ModelImport m = importModel(path.toStdString(), {});
    const QString report = joined(m.report);
    QCOMPARE(m.lights.size(), size_t(2));
    const auto byName = [&](const std::string& prefix) -> const Light* {
        for (const Light& l : m.lights)
            if (l.name.rfind(prefix, 0) == 0) return &l;
        return nullptr;
    };
    const Light* bulb = byName("bulb");  // named after their nodes' ids
    const Light* spot = byName("spot");
    QVERIFY2(bulb && spot, qPrintable(report));
    QCOMPARE(bulb->type, LightType::Point);
    QVERIFY2(near(bulb->position, V3d(0, 2, 0), 1e-5), qPrintable(report));
    QVERIFY(bulb->photometric && bulb->photometric->quantity == PhotometricSpec::Quantity::Candela);
    QVERIFY(std::abs(bulb->photometric->value - 50) < 1e-4);
    QCOMPARE(spot->type, LightType::Spot);
    QVERIFY2(near(spot->position, V3d(1, 3, 0), 1e-5), qPrintable(report));
    // COLLADA lights shine along their node's -z; the node turns -z to -y.
    QVERIFY2(near(spot->direction, V3d(0, -1, 0), 1e-5),
             qPrintable(QString("%1 %2 %3").arg(spot->direction.x).arg(spot->direction.y).arg(spot->direction.z)));
    // falloff_angle is the whole cone: a 30 degree half-angle, with the format's hard edge.
    QVERIFY2(std::abs(spot->coneAngleDeg - 30) < 1e-3, qPrintable(QString::number(spot->coneAngleDeg)));
    QVERIFY(!spot->falloffStartDeg);
    QVERIFY(spot->photometric && std::abs(spot->photometric->value - 80) < 1e-4);
    QVERIFY2(reportHas(m.report, "'bulb'", "50 cd") && reportHas(m.report, "'bulb'", "assumed"), qPrintable(report));
    QVERIFY2(reportHas(m.report, "'spot'", "cone 30 deg"), qPrintable(report));
}

void TestModelImport::fbxUnit() {
    const QString path = dir_.filePath("tri.fbx");
    writeFile(path, kFbx);
    ImportOptions options;
    options.sceneMetersPerUnit = 0.01;  // a centimetre scene
    const ModelImport m = importModel(path.toStdString(), options);
    const QString report = joined(m.report);
    QCOMPARE(m.objects.size(), size_t(1));
    std::vector<V3d> v = m.objects[0].mesh.inlineMesh.vertices;
    QCOMPARE(v.size(), size_t(3));
    std::sort(v.begin(), v.end(), [](const V3d& a, const V3d& b) { return a.x + 10 * a.y < b.x + 10 * b.y; });
    // 10 and 110 inches along x, 100 inches up: in centimetres.
    QVERIFY2(near(v[0], V3d(25.4, 0, 0), 1e-4) && near(v[1], V3d(279.4, 0, 0), 1e-4) && near(v[2], V3d(25.4, 254, 0), 1e-4),
             qPrintable(QString("%1 %2 / %3 %4 / %5 %6 (%7)").arg(v[0].x).arg(v[0].y).arg(v[1].x).arg(v[1].y).arg(v[2].x)
                            .arg(v[2].y).arg(report)));
    QCOMPARE(m.materials.size(), size_t(1));
    QCOMPARE(m.materials[0].name, std::string("Wood"));
    QVERIFY(near(m.materials[0].albedo, Rgbd(0.6, 0.4, 0.2)));
    QVERIFY2(reportHas(m.report, "FBX unit: 2.54 cm"), qPrintable(report));

    // The same file declared z up with -y forward (as Blender writes): turned to y up, the
    // triangle's +y edge (forward) now points along -z.
    QByteArray zUp(kFbx);
    zUp.replace(R"("UpAxis", "int", "Integer", "",1)", R"("UpAxis", "int", "Integer", "",2)");
    zUp.replace(R"("FrontAxis", "int", "Integer", "",2)", R"("FrontAxis", "int", "Integer", "",1)");
    zUp.replace(R"("FrontAxisSign", "int", "Integer", "",1)", R"("FrontAxisSign", "int", "Integer", "",-1)");
    const QString zPath = dir_.filePath("tri-z.fbx");
    writeFile(zPath, zUp);
    const ModelImport z = importModel(zPath.toStdString(), options);
    QCOMPARE(z.objects.size(), size_t(1));
    bool found = false;
    for (const V3d& p : z.objects[0].mesh.inlineMesh.vertices) found |= near(p, V3d(25.4, 0, -254), 1e-4);
    QVERIFY2(found && reportHas(z.report, "axes", "y up"), qPrintable(joined(z.report)));
}

// A 2 x 2 texture of red, blue, white and black: its linear mean is (0.5, 0.25, 0.5).
QByteArray texturePng() {
    QImage image(2, 2, QImage::Format_RGB888);
    image.setPixelColor(0, 0, QColor(255, 0, 0));
    image.setPixelColor(1, 0, QColor(0, 0, 255));
    image.setPixelColor(0, 1, QColor(255, 255, 255));
    image.setPixelColor(1, 1, QColor(0, 0, 0));
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    image.save(&buffer, "PNG");
    return png;
}

// Base colour textures become their average colour times the factor: an OBJ's map_Kd file next
// to it, and a glTF image embedded as a data URI.
void TestModelImport::texturesAveraged() {
    const QByteArray png = texturePng();
    QVERIFY(!png.isEmpty());
    writeFile(dir_.filePath("tex.png"), png);
    writeFile(dir_.filePath("textured.obj"), "mtllib textured.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl Wood\nf 1 2 3\n");
    writeFile(dir_.filePath("textured.mtl"), "newmtl Wood\nKd 0.5 1 1\nmap_Kd tex.png\n");
    const ModelImport obj = importModel(dir_.filePath("textured.obj").toStdString(), {});
    QCOMPARE(obj.materials.size(), size_t(1));
    QVERIFY2(near(obj.materials[0].albedo, Rgbd(0.25, 0.25, 0.5), 1e-3), qPrintable(joined(obj.report)));
    QVERIFY2(reportHas(obj.report, "'Wood'", "averaged"), qPrintable(joined(obj.report)));

    const QByteArray gltf = R"({
  "asset": {"version": "2.0"},
  "scenes": [{"nodes": [0]}],
  "nodes": [{"name": "Board", "mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
  "materials": [{"name": "Wood", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 1, 1, 1], "metallicFactor": 0,
                 "roughnessFactor": 1, "baseColorTexture": {"index": 0}}}],
  "textures": [{"source": 0}],
  "images": [{"uri": "data:image/png;base64,)" + png.toBase64() + R"("}],
  "buffers": [{"byteLength": 60, "uri": "data:application/octet-stream;base64,)" + squareBuffer().toBase64() + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
    {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}]
})";
    writeFile(dir_.filePath("textured.gltf"), gltf);
    const ModelImport g = importModel(dir_.filePath("textured.gltf").toStdString(), {});
    QCOMPARE(g.materials.size(), size_t(1));
    QCOMPARE(g.materials[0].type, MaterialType::Diffuse);
    QVERIFY2(near(g.materials[0].albedo, Rgbd(0.25, 0.25, 0.5), 1e-3),
             qPrintable(QString("%1 %2 %3: %4").arg(g.materials[0].albedo.x).arg(g.materials[0].albedo.y).arg(g.materials[0].albedo.z).arg(joined(g.report))));
    QVERIFY2(reportHas(g.report, "'Wood'", "baseColorTexture averaged"), qPrintable(joined(g.report)));
}

// A file with only a sun: glTF's directional intensity is lux, and the light travels along its
// node's -z (here turned to point straight down).
void TestModelImport::directionalLightOnly() {
    writeFile(dir_.filePath("sun.gltf"), R"({
  "asset": {"version": "2.0"},
  "extensionsUsed": ["KHR_lights_punctual"],
  "extensions": {"KHR_lights_punctual": {"lights": [{"name": "Sun", "type": "directional", "intensity": 683}]}},
  "scenes": [{"nodes": [0]}],
  "nodes": [{"name": "Sun", "rotation": [-0.5, -0.5, -0.5, 0.5], "extensions": {"KHR_lights_punctual": {"light": 0}}}]
})");
    const ModelImport m = importModel(dir_.filePath("sun.gltf").toStdString(), {});
    QCOMPARE(m.objects.size(), size_t(0));
    QCOMPARE(m.lights.size(), size_t(1));
    const Light& sun = m.lights[0];
    QCOMPARE(sun.type, LightType::Directional);
    QVERIFY(near(sun.irradiance, Rgbd(1, 1, 1), 1e-5));  // 683 lx = 1 W/m^2 at luminance 1
    // R(-z) is minus the third column of the quaternion's rotation matrix, written out here.
    const double x = -0.5, y = -0.5, z = -0.5, w = 0.5;
    const V3d thirdColumn(2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y));
    QVERIFY2(near(sun.direction.normalized(), -thirdColumn, 1e-5),
             qPrintable(QString("%1 %2 %3").arg(sun.direction.x).arg(sun.direction.y).arg(sun.direction.z)));
    QVERIFY2(reportHas(m.report, "'Sun'", "683 lx"), qPrintable(joined(m.report)));
}

void TestModelImport::badFiles() {
    const QString bad = dir_.filePath("broken.gltf");
    writeFile(bad, "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [ this is not json");
    for (const QString& path : {bad, dir_.filePath("missing.obj")}) {
        try {
            importModel(path.toStdString(), {});
            QFAIL("no error");
        } catch (const std::runtime_error& e) {
            const std::string what = e.what();
            QVERIFY2(what.find(QFileInfo(path).fileName().toStdString()) != std::string::npos, e.what());
            QVERIFY2(what.find('\n') == std::string::npos, e.what());
        }
    }
}

// `lucerna import`: a scene SPEC.md's loader reads back, with the model's objects, materials and
// lights and a camera that sees the model; a bad file is exit status 2 with one line and no file.
QTEST_MAIN(TestModelImport)
#include "test_model_import.moc"
