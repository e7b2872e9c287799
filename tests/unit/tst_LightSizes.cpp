#include "TestSupport.h"

#include "document/Document.h"
#include "document/LightsFile.h"
#include "document/ProjectFile.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using namespace vct;

namespace {

QString sizesDir()
{
    return test::outputDir() + QStringLiteral("/light-sizes");
}

doc::LightNode pointNode(doc::LightType type, float radius)
{
    doc::LightNode light;
    light.type = type;
    light.position = { 0.1f, 0.8f, -0.2f };
    light.intensity = 2.0f;
    light.radius = radius;
    if (type == doc::LightType::Spot) {
        light.direction = { 0.0f, -1.0f, 0.25f };
        light.spotInnerDeg = 15.0f;
        light.spotOuterDeg = 35.0f;
    }
    return light;
}

doc::LightNode directionalNode(float angularDiameterDeg)
{
    doc::LightNode light;
    light.type = doc::LightType::Directional;
    light.direction = { -0.3f, -1.0f, -0.2f };
    light.color = { 1.0f, 0.9f, 0.8f };
    light.intensity = 3.0f;
    light.angularDiameterDeg = angularDiameterDeg;
    return light;
}

/** A state of a point light and a directional one, both with a size, as ProjectFile::toJson writes it. */
QJsonObject sizedProject()
{
    doc::DocumentState state;
    doc::LightNode point = pointNode(doc::LightType::Point, 0.05f);
    point.id = 1;
    point.name = QStringLiteral("Point light 1");
    doc::LightNode sun = directionalNode(0.53f);
    sun.id = 2;
    sun.name = QStringLiteral("Directional light 1");
    state.lights = { point, sun };
    state.nextId = 3;
    return QJsonDocument::fromJson(doc::ProjectFile::toJson(state, sizesDir())).object();
}

/** `root` with `key` of lights[`light`] set to `value`, or removed when `value` is undefined. */
QByteArray withLightField(QJsonObject root, int light, const QString& key, const QJsonValue& value)
{
    QJsonArray lights = root.value("lights").toArray();
    QJsonObject object = lights[light].toObject();
    if (value.isUndefined())
        object.remove(key);
    else
        object.insert(key, value);
    lights[light] = object;
    root.insert("lights", lights);
    return QJsonDocument(root).toJson();
}

} // namespace

/**
 * Light sizes for soft shadows (a point or spot light's radius, a directional light's angular diameter): in
 * lights files, project files and the document's render scene, and the errors for impossible sizes.
 */
class LightSizesTest : public QObject {
    Q_OBJECT

private slots:
    void lightsFileReadsSizes();
    void lightsFileRejectsBadSizes_data();
    void lightsFileRejectsBadSizes();
    void documentSendsSizesToTheRenderScene();
    void sceneToDocumentAndBackKeepsSizes();
    void projectFileKeepsSizes();
    void projectFileWithoutSizesLoadsAsBefore();
    void projectFileRejectsBadSizes_data();
    void projectFileRejectsBadSizes();
};

void LightSizesTest::lightsFileReadsSizes()
{
    const QString path = test::writeFile(sizesDir() + QStringLiteral("/read.lights.json"), R"({"lights": [
        {"type": "point", "position": [0, 2, 0], "intensity": [1, 1, 1], "radius": 0.05},
        {"type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0], "intensity": [1, 1, 1],
         "inner_deg": 10, "outer_deg": 20, "radius": 0.25},
        {"type": "point", "position": [1, 2, 0], "intensity": [1, 1, 1]},
        {"type": "directional", "direction": [0, -1, 0], "irradiance": [2, 2, 2], "angular_diameter_deg": 0.53},
        {"type": "directional", "direction": [0, -1, 1], "irradiance": [1, 1, 1]},
        {"type": "directional", "direction": [1, -1, 0], "irradiance": [1, 1, 1], "angular_diameter_deg": 0}]})");
    render::Scene scene;
    QString error;
    QVERIFY2(doc::LightsFile::read(path, scene, &error), qPrintable(error));
    QCOMPARE(scene.pointLights.size(), std::size_t(3));
    QCOMPARE(scene.pointLights[0].radius, 0.05f);
    QVERIFY(scene.pointLights[1].isSpot());
    QCOMPARE(scene.pointLights[1].radius, 0.25f);
    QCOMPARE(scene.pointLights[2].radius, 0.0f); // optional: a point, as before
    QCOMPARE(scene.directionalLights.size(), std::size_t(3));
    QCOMPARE(scene.directionalLights[0].angularDiameterDeg, 0.53f);
    QCOMPARE(scene.directionalLights[1].angularDiameterDeg, 0.0f);
    QCOMPARE(scene.directionalLights[2].angularDiameterDeg, 0.0f);
}

void LightSizesTest::lightsFileRejectsBadSizes_data()
{
    QTest::addColumn<QByteArray>("light");
    QTest::addColumn<QString>("field");
    const QByteArray point = R"("type": "point", "position": [0, 2, 0], "intensity": [1, 1, 1], )";
    const QByteArray spot = R"("type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0],
        "intensity": [1, 1, 1], "inner_deg": 10, "outer_deg": 20, )";
    const QByteArray sun = R"("type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1], )";
    // JSON has no infinity or NaN (Qt refuses 1e999); 1e39 is a finite double a float cannot hold.
    QTest::newRow("point, negative radius") << point + R"("radius": -0.1)"
                                            << "lights[1].radius";
    QTest::newRow("point, radius too large") << point + R"("radius": 1e39)"
                                             << "lights[1].radius";
    QTest::newRow("point, radius as text") << point + R"("radius": "0.1")"
                                           << "lights[1].radius";
    QTest::newRow("spot, negative radius") << spot + R"("radius": -1)"
                                           << "lights[1].radius";
    QTest::newRow("directional, negative diameter") << sun + R"("angular_diameter_deg": -0.5)"
                                                    << "lights[1].angular_diameter_deg";
    QTest::newRow("directional, diameter 90") << sun + R"("angular_diameter_deg": 90)"
                                              << "lights[1].angular_diameter_deg";
    QTest::newRow("directional, diameter beyond 90") << sun + R"("angular_diameter_deg": 120)"
                                                     << "lights[1].angular_diameter_deg";
    QTest::newRow("directional, diameter too large") << sun + R"("angular_diameter_deg": 1e39)"
                                                     << "lights[1].angular_diameter_deg";
    QTest::newRow("directional, diameter as null") << sun + R"("angular_diameter_deg": null)"
                                                   << "lights[1].angular_diameter_deg";
}

void LightSizesTest::lightsFileRejectsBadSizes()
{
    QFETCH(QByteArray, light);
    QFETCH(QString, field);
    // A good sized light first: nothing of a file is kept when a later light is refused.
    const QString path = test::writeFile(sizesDir() + QStringLiteral("/bad.lights.json"),
        R"({"lights": [{"type": "point", "position": [0, 1, 0], "intensity": [1, 1, 1], "radius": 0.1}, {)"
            + light + "}]}");
    render::Scene scene;
    scene.pointLights.push_back({});
    scene.directionalLights.push_back({});
    QString error;
    QVERIFY(!doc::LightsFile::read(path, scene, &error));
    QVERIFY2(error.contains(QStringLiteral("'%1'").arg(field))
            && error.contains(QStringLiteral("bad.lights.json")),
        qPrintable(error));
    QCOMPARE(scene.pointLights.size(), std::size_t(1)); // the scene is untouched
    QCOMPARE(scene.pointLights[0].radius, 0.0f);
    QCOMPARE(scene.directionalLights.size(), std::size_t(1));
}

void LightSizesTest::documentSendsSizesToTheRenderScene()
{
    doc::Document document;
    QString error;
    QVERIFY2(document.newFromScene(QStringLiteral("builtin:cornell"), &error), qPrintable(error));
    const render::Scene before = document.buildRenderScene();
    document.addLight(pointNode(doc::LightType::Point, 0.05f));
    document.addLight(pointNode(doc::LightType::Spot, 0.125f));
    document.addLight(directionalNode(0.53f));

    const render::Scene scene = document.buildRenderScene();
    QCOMPARE(scene.pointLights.size(), before.pointLights.size() + 2);
    QCOMPARE(scene.pointLights[scene.pointLights.size() - 2].radius, 0.05f);
    const render::PointLight& spot = scene.pointLights.back();
    QVERIFY(spot.isSpot());
    QCOMPARE(spot.radius, 0.125f);
    QCOMPARE(scene.directionalLights.size(), before.directionalLights.size() + 1);
    QCOMPARE(scene.directionalLights.back().angularDiameterDeg, 0.53f);
    QCOMPARE(scene.directionalLights.back().irradiance, directionalNode(0.0f).color * 3.0f);
    // The builtin scene's lights have no size: they render as before.
    for (std::size_t i = 0; i < before.pointLights.size(); ++i)
        QCOMPARE(scene.pointLights[i].radius, 0.0f);

    // An edit of the size reaches the renderer; its undo takes it back.
    doc::LightNode edited = document.state().lights.back();
    edited.angularDiameterDeg = 2.0f;
    document.setLight(int(document.state().lights.size()) - 1, edited);
    QCOMPARE(document.buildRenderScene().directionalLights.back().angularDiameterDeg, 2.0f);
    document.undoStack()->undo();
    QCOMPARE(document.buildRenderScene().directionalLights.back().angularDiameterDeg, 0.53f);
}

void LightSizesTest::sceneToDocumentAndBackKeepsSizes()
{
    const QString dir = sizesDir() + QStringLiteral("/model");
    const QString model = test::writeFile(
        dir + QStringLiteral("/lit.obj"), "o Floor\nv -1 0 -1\nv 1 0 -1\nv 1 0 1\nf 1 3 2\n");
    test::writeFile(dir + QStringLiteral("/lit.lights.json"), R"({"lights": [
        {"type": "point", "position": [0, 1, 0], "intensity": [1, 1, 1], "radius": 0.075},
        {"type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0], "intensity": [4, 4, 4],
         "inner_deg": 10, "outer_deg": 20, "radius": 0.3},
        {"type": "directional", "direction": [0, -1, 0], "irradiance": [2, 2, 2], "angular_diameter_deg": 0.53}]})");
    doc::Document document;
    QString error;
    QVERIFY2(document.newFromScene(model, &error), qPrintable(error));
    const std::vector<doc::LightNode>& lights = document.state().lights;
    QCOMPARE(lights.size(), std::size_t(3));
    QCOMPARE(lights[0].radius, 0.075f);
    QCOMPARE(lights[1].type, doc::LightType::Spot);
    QCOMPARE(lights[1].radius, 0.3f);
    QCOMPARE(lights[2].angularDiameterDeg, 0.53f);

    const render::Scene scene = document.buildRenderScene();
    QCOMPARE(scene.pointLights[0].radius, 0.075f);
    QCOMPARE(scene.pointLights[1].radius, 0.3f);
    QCOMPARE(scene.directionalLights[0].angularDiameterDeg, 0.53f);
}

void LightSizesTest::projectFileKeepsSizes()
{
    doc::Document document;
    QString error;
    QVERIFY2(document.newFromScene(QStringLiteral("builtin:cornell"), &error), qPrintable(error));
    document.addLight(pointNode(doc::LightType::Point, 0.05f));
    document.addLight(pointNode(doc::LightType::Spot, 0.125f));
    document.addLight(directionalNode(0.53f));
    document.addLight(directionalNode(0.0f));
    QDir().mkpath(sizesDir());
    const QString path = sizesDir() + QStringLiteral("/sizes.vctproj");
    QVERIFY2(document.saveProject(path, &error), qPrintable(error));

    doc::Document reopened;
    QVERIFY2(reopened.openProject(path, &error), qPrintable(error));
    QCOMPARE(reopened.state().lights.size(), document.state().lights.size());
    for (std::size_t i = 0; i < document.state().lights.size(); ++i)
        QVERIFY2(reopened.state().lights[i] == document.state().lights[i], qPrintable(QString::number(i)));
    const render::Scene scene = reopened.buildRenderScene();
    QCOMPARE(scene.pointLights[scene.pointLights.size() - 2].radius, 0.05f);
    QCOMPARE(scene.pointLights.back().radius, 0.125f);
    QCOMPARE(scene.directionalLights[scene.directionalLights.size() - 2].angularDiameterDeg, 0.53f);

    // The file names them as lights files do, on the lights they belong to only.
    const QJsonArray lights = QJsonDocument::fromJson(doc::ProjectFile::toJson(document.state(), sizesDir()))
                                  .object()["lights"]
                                  .toArray();
    const qsizetype n = lights.size();
    QCOMPARE(lights[n - 4].toObject().value("radius").toDouble(), double(0.05f));
    QCOMPARE(lights[n - 3].toObject().value("radius").toDouble(), double(0.125f));
    QCOMPARE(lights[n - 2].toObject().value("angular_diameter_deg").toDouble(), double(0.53f));
    QVERIFY(!lights[n - 2].toObject().contains("radius"));
    QVERIFY(!lights[n - 4].toObject().contains("angular_diameter_deg"));
}

void LightSizesTest::projectFileWithoutSizesLoadsAsBefore()
{
    // The project in the repository was saved before lights had a size.
    doc::Document document;
    QString error;
    QVERIFY2(
        document.openProject(test::sourceDir() + QStringLiteral("/tests/data/cornell_point.vctproj"), &error),
        qPrintable(error));
    QVERIFY(!document.state().lights.empty());
    for (const doc::LightNode& light : document.state().lights)
        QVERIFY(light.radius == 0.0f && light.angularDiameterDeg == 0.0f);
    for (const render::PointLight& light : document.buildRenderScene().pointLights)
        QCOMPARE(light.radius, 0.0f);

    // Without the keys, the rest of each light reads as written.
    const QByteArray json = withLightField(
        QJsonDocument::fromJson(
            withLightField(sizedProject(), 0, QStringLiteral("radius"), QJsonValue::Undefined))
            .object(),
        1, QStringLiteral("angular_diameter_deg"), QJsonValue::Undefined);
    QVERIFY(!json.contains("radius") && !json.contains("angular_diameter_deg"));
    doc::DocumentState read;
    QVERIFY2(doc::ProjectFile::fromJson(json, sizesDir(), QStringLiteral("old.vctproj"), &read, &error),
        qPrintable(error));
    QCOMPARE(read.lights.size(), std::size_t(2));
    doc::LightNode point = pointNode(doc::LightType::Point, 0.0f);
    point.id = 1;
    point.name = QStringLiteral("Point light 1");
    QVERIFY(read.lights[0] == point);
    doc::LightNode sun = directionalNode(0.0f);
    sun.id = 2;
    sun.name = QStringLiteral("Directional light 1");
    QVERIFY(read.lights[1] == sun);
}

void LightSizesTest::projectFileRejectsBadSizes_data()
{
    QTest::addColumn<int>("light");
    QTest::addColumn<QString>("key");
    QTest::addColumn<QJsonValue>("value");
    QTest::addColumn<QString>("field");
    QTest::newRow("negative radius") << 0 << "radius" << QJsonValue(-0.5) << "lights[0].radius";
    QTest::newRow("radius too large") << 0 << "radius" << QJsonValue(1e39) << "lights[0].radius";
    QTest::newRow("radius as text") << 0 << "radius" << QJsonValue("0.1") << "lights[0].radius";
    QTest::newRow("negative diameter")
        << 1 << "angular_diameter_deg" << QJsonValue(-1) << "lights[1].angular_diameter_deg";
    QTest::newRow("diameter 90") << 1 << "angular_diameter_deg" << QJsonValue(90)
                                 << "lights[1].angular_diameter_deg";
    QTest::newRow("diameter beyond 90")
        << 1 << "angular_diameter_deg" << QJsonValue(180.5) << "lights[1].angular_diameter_deg";
    QTest::newRow("diameter too large")
        << 1 << "angular_diameter_deg" << QJsonValue(1e39) << "lights[1].angular_diameter_deg";
}

void LightSizesTest::projectFileRejectsBadSizes()
{
    QFETCH(int, light);
    QFETCH(QString, key);
    QFETCH(QJsonValue, value);
    QFETCH(QString, field);
    doc::DocumentState read;
    QString error;
    QVERIFY(!doc::ProjectFile::fromJson(withLightField(sizedProject(), light, key, value), sizesDir(),
        QStringLiteral("bad.vctproj"), &read, &error));
    QVERIFY2(
        error.contains(QStringLiteral("'%1'").arg(field)) && error.contains(QStringLiteral("bad.vctproj")),
        qPrintable(error));
    QVERIFY(read.lights.empty()); // untouched
}

QTEST_GUILESS_MAIN(LightSizesTest)
#include "tst_LightSizes.moc"
