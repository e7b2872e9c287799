#include "TestSupport.h"

#include "document/Document.h"
#include "document/SceneLoader.h"

#include <QDir>
#include <QRegularExpression>
#include <QtTest>

#include <cmath>
#include <limits>

using namespace vct;

namespace {

bool near(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-5f)
{
    return glm::length(a - b) <= tolerance * std::max(1.0f, glm::length(b));
}

bool near(float a, float b, float tolerance = 1e-5f)
{
    return std::abs(a - b) <= tolerance * std::max(1.0f, std::abs(b));
}

/**
 * A model in centimetres with a light of every type in its sibling lights file and a camera file: a 200 cm
 * box corner, as the Sponza's files would be laid out.
 */
QString writeCentimetreModel(const QString& name)
{
    const QString dir = test::outputDir() + QStringLiteral("/unit-scale/") + name;
    QDir(dir).removeRecursively();
    test::writeFile(dir + QStringLiteral("/room.obj"),
        "o floor\nv -100 0 -100\nv 100 0 -100\nv 100 0 100\nv -100 0 100\nf 1 3 2\nf 1 4 3\n"
        "o wall\nv -100 0 -100\nv 100 0 -100\nv 100 200 -100\nf 5 6 7\n");
    test::writeFile(dir + QStringLiteral("/room.lights.json"),
        R"({"lights": [
  {"type": "point", "position": [0, 150, 0], "intensity": [3, 3, 3], "radius": 10},
  {"type": "spot", "position": [50, 180, 20], "direction": [0, -1, 0], "intensity": [5, 4, 3],
   "inner_deg": 20, "outer_deg": 35, "radius": 4},
  {"type": "directional", "direction": [0.3, -1, -0.4], "irradiance": [1, 0.9, 0.8], "angular_diameter_deg": 2},
  {"type": "rect", "position": [0, 199, 0], "direction": [0, -1, 0], "size": [50, 30], "rotation_deg": 20,
   "radiance": [12, 11, 9]},
  {"type": "disk", "position": [-90, 100, 0], "direction": [1, 0, 0], "diameter": 30, "radiance": [2, 3, 6]}
]})");
    test::writeFile(dir + QStringLiteral("/room.camera.json"),
        R"({"position": [0, 100, 400], "look_at": [0, 100, 0], "up": [0, 1, 0], "fov_y_deg": 40,
  "width": 64, "height": 48})");
    return dir + QStringLiteral("/room.obj");
}

} // namespace

class tst_UnitScale : public QObject {
    Q_OBJECT

private slots:
    // Lengths scale, the physical units (W/sr, W/m^2, W/(m^2 sr)) and every direction and angle stay.
    void scaledSceneScalesLengthsOnly()
    {
        render::Scene scene;
        scene.meshes.push_back(test::makeTriangles({ { 0, 0, 0 }, { 100, 0, 0 }, { 0, 100, 0 } }));
        scene.meshes.back().transform = glm::translate(glm::mat4(1.0f), glm::vec3(10.0f, 0.0f, 0.0f));
        render::PointLight point;
        point.position = { 1.0f, 200.0f, -3.0f };
        point.intensity = glm::vec3(7.0f);
        point.radius = 5.0f;
        render::PointLight spot = point;
        spot.spotDirection = glm::normalize(glm::vec3(0.2f, -1.0f, 0.0f));
        spot.spotInnerDeg = 15.0f;
        spot.spotOuterDeg = 30.0f;
        scene.pointLights = { point, spot };
        render::DirectionalLight sun;
        sun.direction = { 0.3f, -1.0f, 0.1f };
        sun.irradiance = glm::vec3(2.0f);
        sun.angularDiameterDeg = 0.53f;
        scene.directionalLights = { sun };
        render::SurfaceLight rect;
        rect.centre = { 0.0f, 190.0f, 0.0f };
        rect.width = 40.0f;
        rect.height = 20.0f;
        rect.rotationDeg = 25.0f;
        rect.radiance = glm::vec3(9.0f);
        render::SurfaceLight disk = rect;
        disk.shape = render::SurfaceLight::Shape::Disk;
        disk.direction = { 1.0f, 0.0f, 0.0f };
        scene.surfaceLights = { rect, disk };
        scene.camera.position = { 0.0f, 100.0f, 500.0f };
        scene.camera.lookAt = { 0.0f, 100.0f, 0.0f };
        scene.camera.fovYDeg = 35.0f;
        scene.camera.nearPlane = 0.5f;

        const float s = 0.01f;
        const render::Scene scaled = doc::SceneLoader::scaledScene(scene, s);

        QCOMPARE(scaled.meshes.size(), std::size_t(1));
        QCOMPARE(scaled.meshes[0].positions, scene.meshes[0].positions); // object space stays
        const render::Aabb before = scene.bounds();
        const render::Aabb after = scaled.bounds();
        QVERIFY(near(after.min, before.min * s));
        QVERIFY(near(after.max, before.max * s));

        QCOMPARE(scaled.pointLights.size(), std::size_t(2));
        for (std::size_t i = 0; i < 2; ++i) {
            const render::PointLight& a = scene.pointLights[i];
            const render::PointLight& b = scaled.pointLights[i];
            QVERIFY(near(b.position, a.position * s));
            QVERIFY(near(b.radius, a.radius * s));
            QCOMPARE(b.intensity, a.intensity);
            QCOMPARE(b.spotDirection, a.spotDirection);
            QCOMPARE(b.spotInnerDeg, a.spotInnerDeg);
            QCOMPARE(b.spotOuterDeg, a.spotOuterDeg);
            QCOMPARE(b.castsShadows, a.castsShadows);
        }
        QCOMPARE(scaled.directionalLights.size(), std::size_t(1));
        QCOMPARE(scaled.directionalLights[0].direction, sun.direction);
        QCOMPARE(scaled.directionalLights[0].irradiance, sun.irradiance);
        QCOMPARE(scaled.directionalLights[0].angularDiameterDeg, sun.angularDiameterDeg);
        QCOMPARE(scaled.surfaceLights.size(), std::size_t(2));
        for (std::size_t i = 0; i < 2; ++i) {
            const render::SurfaceLight& a = scene.surfaceLights[i];
            const render::SurfaceLight& b = scaled.surfaceLights[i];
            QCOMPARE(b.shape, a.shape);
            QVERIFY(near(b.centre, a.centre * s));
            QVERIFY(near(b.width, a.width * s));
            QVERIFY(near(b.height, a.height * s));
            QVERIFY(near(b.area(), a.area() * s * s));
            QCOMPARE(b.direction, a.direction);
            QCOMPARE(b.rotationDeg, a.rotationDeg);
            QCOMPARE(b.radiance, a.radiance);
        }
        QVERIFY(near(scaled.camera.position, scene.camera.position * s));
        QVERIFY(near(scaled.camera.lookAt, scene.camera.lookAt * s));
        QCOMPARE(scaled.camera.up, scene.camera.up);
        QCOMPARE(scaled.camera.fovYDeg, scene.camera.fovYDeg);
        QVERIFY(near(scaled.camera.nearPlane, scene.camera.nearPlane * s));
    }

    // The sibling files are in the model's units: loading at 0.01 gives the scene loaded at 1, scaled.
    void loadScalesTheModelAndItsSiblings()
    {
        const QString model = writeCentimetreModel(QStringLiteral("siblings"));
        render::Scene centimetres;
        render::Scene metres;
        QString error;
        doc::SceneLoadInfo info;
        QVERIFY2(doc::SceneLoader::load(model, centimetres, &error), qPrintable(error));
        QVERIFY2(doc::SceneLoader::load(model, metres, &error, &info, 0.01f), qPrintable(error));
        QVERIFY(info.hasCameraFile);
        QCOMPARE(info.width, 64);
        QCOMPARE(info.files.size(), 3);

        QVERIFY(near(metres.bounds().min, glm::vec3(-1.0f, 0.0f, -1.0f)));
        QVERIFY(near(metres.bounds().max, glm::vec3(1.0f, 2.0f, 1.0f)));
        QCOMPARE(metres.pointLights.size(), std::size_t(2));
        QCOMPARE(metres.directionalLights.size(), std::size_t(1));
        QCOMPARE(metres.surfaceLights.size(), std::size_t(2));
        QVERIFY(near(metres.pointLights[0].position, glm::vec3(0.0f, 1.5f, 0.0f)));
        QVERIFY(near(metres.pointLights[0].radius, 0.1f));
        QCOMPARE(metres.pointLights[0].intensity, glm::vec3(3.0f));
        QVERIFY(near(metres.pointLights[1].radius, 0.04f));
        QVERIFY(metres.pointLights[1].isSpot());
        QVERIFY(near(metres.surfaceLights[0].width, 0.5f));
        QVERIFY(near(metres.surfaceLights[0].height, 0.3f));
        QVERIFY(near(metres.surfaceLights[1].width, 0.3f));
        QCOMPARE(metres.surfaceLights[0].radiance, glm::vec3(12.0f, 11.0f, 9.0f));
        QCOMPARE(metres.directionalLights[0].angularDiameterDeg, 2.0f);
        QVERIFY(near(metres.camera.position, glm::vec3(0.0f, 1.0f, 4.0f)));
        QVERIFY(near(metres.camera.lookAt, glm::vec3(0.0f, 1.0f, 0.0f)));
        // The near plane a camera file gets from the bounds, as if the model had been in metres all along.
        QVERIFY(near(metres.camera.nearPlane, doc::SceneLoader::nearPlaneFor(metres.bounds()), 1e-4f));
        QVERIFY(near(metres.camera.nearPlane, centimetres.camera.nearPlane * 0.01f, 1e-4f));
    }

    // Without a camera file the framing camera scales with the model: the same view of a smaller scene.
    void framingCameraScales()
    {
        const QString model = writeCentimetreModel(QStringLiteral("framing"));
        QVERIFY(QFile::remove(QFileInfo(model).dir().filePath(QStringLiteral("room.camera.json"))));
        render::Scene centimetres;
        render::Scene millimetresToMetres;
        QString error;
        QVERIFY2(doc::SceneLoader::load(model, centimetres, &error), qPrintable(error));
        QVERIFY2(
            doc::SceneLoader::load(model, millimetresToMetres, &error, nullptr, 0.001f), qPrintable(error));
        const render::Camera framed = doc::SceneLoader::frameBounds(millimetresToMetres.bounds());
        QVERIFY(near(millimetresToMetres.camera.position, framed.position, 1e-4f));
        QVERIFY(near(millimetresToMetres.camera.nearPlane, framed.nearPlane, 1e-4f));
        QVERIFY(near(millimetresToMetres.camera.position, centimetres.camera.position * 0.001f, 1e-4f));
    }

    void unusableScalesAreRefused_data()
    {
        QTest::addColumn<float>("scale");
        QTest::newRow("zero") << 0.0f;
        QTest::newRow("negative") << -0.01f;
        QTest::newRow("infinite") << std::numeric_limits<float>::infinity();
        QTest::newRow("nan") << std::numeric_limits<float>::quiet_NaN();
    }

    void unusableScalesAreRefused()
    {
        QFETCH(float, scale);
        const QString model = writeCentimetreModel(QStringLiteral("refused"));
        render::Scene scene;
        scene.meshes.resize(3);
        QString error;
        QVERIFY(!doc::SceneLoader::load(model, scene, &error, nullptr, scale));
        QVERIFY2(error.contains(QStringLiteral("room.obj")) && error.contains(QStringLiteral("unit scale")),
            qPrintable(error));
        QCOMPARE(scene.meshes.size(), std::size_t(3)); // untouched
        QVERIFY(!doc::SceneLoader::unitScaleProblem(scale).isEmpty());
    }

    // A scale that overflows a float is refused rather than handing the renderer infinities.
    void overflowingScaleIsRefused()
    {
        const QString model = writeCentimetreModel(QStringLiteral("overflow"));
        render::Scene scene;
        QString error;
        QVERIFY(!doc::SceneLoader::load(model, scene, &error, nullptr, 1e37f));
        QVERIFY2(error.contains(QStringLiteral("beyond the range")), qPrintable(error));
    }

    void builtinScenesAreInMetres()
    {
        render::Scene scene;
        QString error;
        QVERIFY2(doc::SceneLoader::load(QStringLiteral("builtin:cornell"), scene, &error, nullptr, 1.0f),
            qPrintable(error));
        QVERIFY(!doc::SceneLoader::load(QStringLiteral("builtin:cornell"), scene, &error, nullptr, 0.01f));
        QVERIFY2(
            error.contains(QStringLiteral("builtin:cornell")) && error.contains(QStringLiteral("metres")),
            qPrintable(error));
    }

    void parseUnitScale()
    {
        float scale = 1.0f;
        QVERIFY(doc::SceneLoader::parseUnitScale(QStringLiteral("0.0254"), &scale).isEmpty());
        QCOMPARE(scale, 0.0254f);
        QVERIFY(doc::SceneLoader::parseUnitScale(QStringLiteral("1e-3"), &scale).isEmpty());
        QCOMPARE(scale, 0.001f);
        for (const char* bad : { "0", "-1", "cm", "", "inf", "nan" }) {
            scale = 0.5f;
            QVERIFY2(!doc::SceneLoader::parseUnitScale(QLatin1String(bad), &scale).isEmpty(), bad);
            QCOMPARE(scale, 0.5f);
        }
    }

    // One file at two scales is two sources with two geometries, not one cached scene shared by both.
    void documentKeepsEachScaleApart()
    {
        const QString model = writeCentimetreModel(QStringLiteral("document"));
        doc::Document document;
        QString error;
        QVERIFY2(document.newFromScene(model, &error, 0.01f), qPrintable(error));
        QCOMPARE(document.state().sources.size(), std::size_t(1));
        QCOMPARE(document.state().sources[0].unitScale, 0.01f);
        QVERIFY(near(document.buildRenderScene().bounds().max, glm::vec3(1.0f, 2.0f, 1.0f)));
        QVERIFY(near(document.state().lights[0].position, glm::vec3(0.0f, 1.5f, 0.0f)));
        QVERIFY(near(document.state().camera.position, glm::vec3(0.0f, 1.0f, 4.0f)));

        QVERIFY2(document.importModel(model, &error, 0.001f), qPrintable(error));
        QCOMPARE(document.state().sources.size(), std::size_t(2));
        QCOMPARE(document.state().sources[1].unitScale, 0.001f);
        QVERIFY(near(document.sourceScene(0).bounds().max, glm::vec3(1.0f, 2.0f, 1.0f)));
        QVERIFY(near(document.sourceScene(1).bounds().max, glm::vec3(0.1f, 0.2f, 0.1f)));
        QVERIFY(near(document.buildRenderScene().bounds().max, glm::vec3(1.0f, 2.0f, 1.0f)));
        document.undoStack()->undo();
        QCOMPARE(document.state().sources.size(), std::size_t(1));

        QVERIFY(!document.importModel(model, &error, -1.0f));
        QTest::ignoreMessage(
            QtWarningMsg, QRegularExpression(QStringLiteral("addImportedModel: .*unit scale")));
        QVERIFY(!document.addImportedModel(model, render::Scene {}, 0.0f));
        QCOMPARE(document.state().sources.size(), std::size_t(1));
        QVERIFY(!document.newFromScene(QStringLiteral("builtin:cornell"), &error, 0.01f));
        QCOMPARE(document.state().sources[0].unitScale, 0.01f); // the open document stays
    }

    // A Z-up model (CAD, 3ds Max) stands upright: its floor faces +y, its lights and camera turn with it, on
    // the command line's path (SceneLoader) and in the editor (the nodes' placement, which the project
    // keeps).
    void zUpModelStandsUpright()
    {
        const QString dir = test::outputDir() + QStringLiteral("/up-axis");
        QDir(dir).removeRecursively();
        // A 2 x 4 m floor in the xy plane and a wall 3 m up along +z at y = 2.
        const QString model = test::writeFile(dir + QStringLiteral("/zup.obj"),
            "v -1 -2 0\nv 1 -2 0\nv 1 2 0\nv -1 2 0\nf 1 2 3\nf 1 3 4\n"
            "v -1 2 0\nv 1 2 0\nv 1 2 3\nf 5 6 7\n");
        test::writeFile(dir + QStringLiteral("/zup.lights.json"),
            R"({"lights": [{"type": "spot", "position": [0, 0, 2.5], "direction": [0, 0, -1], "intensity": [3, 3, 3],
  "inner_deg": 20, "outer_deg": 30}]})");
        test::writeFile(dir + QStringLiteral("/zup.camera.json"),
            R"({"position": [0, -6, 1.5], "look_at": [0, 0, 1], "up": [0, 0, 1], "fov_y_deg": 40, "width": 32, "height": 32})");

        render::Scene scene;
        QString error;
        QVERIFY2(doc::SceneLoader::load(model, scene, &error), qPrintable(error));
        const render::Scene upright = doc::SceneLoader::uprightScene(scene, doc::SceneLoader::UpAxis::Z);
        const render::Aabb bounds = upright.bounds();
        QVERIFY(near(bounds.min, glm::vec3(-1.0f, 0.0f, -2.0f), 1e-5f));
        QVERIFY(near(bounds.max, glm::vec3(1.0f, 3.0f, 2.0f), 1e-5f));
        const glm::vec3 floorNormal = glm::mat3(upright.meshes[0].transform) * upright.meshes[0].normals[0];
        QVERIFY2(
            near(floorNormal, glm::vec3(0.0f, 1.0f, 0.0f), 1e-5f), qPrintable(test::describe(floorNormal)));
        QVERIFY(near(upright.pointLights[0].position, glm::vec3(0.0f, 2.5f, 0.0f), 1e-5f));
        QVERIFY(near(upright.pointLights[0].spotDirection, glm::vec3(0.0f, -1.0f, 0.0f), 1e-5f));
        QVERIFY(near(upright.camera.up, glm::vec3(0.0f, 1.0f, 0.0f), 1e-5f));
        QVERIFY(near(upright.camera.position, glm::vec3(0.0f, 1.5f, 6.0f), 1e-5f));
        doc::SceneLoader::UpAxis axis = doc::SceneLoader::UpAxis::Y;
        QVERIFY(doc::SceneLoader::parseUpAxis(QStringLiteral("Z"), &axis).isEmpty());
        QVERIFY(axis == doc::SceneLoader::UpAxis::Z);
        QVERIFY(!doc::SceneLoader::parseUpAxis(QStringLiteral("w"), &axis).isEmpty());

        // The editor: the same floor, stood up by the nodes' rotation, which survives a save and reopen.
        doc::Document document;
        QVERIFY2(document.newFromScene(model, &error, 1.0f, doc::SceneLoader::UpAxis::Z), qPrintable(error));
        QCOMPARE(document.state().nodes.front().transform.rotationDeg, glm::vec3(-90.0f, 0.0f, 0.0f));
        const render::Aabb shown = document.sceneBounds();
        QVERIFY(near(shown.min, bounds.min, 1e-5f) && near(shown.max, bounds.max, 1e-5f));
        QVERIFY(near(document.state().lights[0].position, glm::vec3(0.0f, 2.5f, 0.0f), 1e-5f));
        QVERIFY(near(document.state().camera.position, glm::vec3(0.0f, 1.5f, 6.0f), 1e-5f));
        const QString project = dir + QStringLiteral("/zup.vctproj");
        QVERIFY2(document.saveProject(project, &error), qPrintable(error));
        doc::Document reopened;
        QVERIFY2(reopened.openProject(project, &error), qPrintable(error));
        QVERIFY(near(reopened.sceneBounds().max, bounds.max, 1e-5f));
    }
};

QTEST_GUILESS_MAIN(tst_UnitScale)
#include "tst_UnitScale.moc"
