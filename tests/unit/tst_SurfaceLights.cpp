#include "TestSupport.h"

#include "document/Document.h"
#include "document/LightsFile.h"
#include "document/ProjectFile.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include <limits>

using namespace vct;

namespace {

/** (b - a) x (c - a) of each triangle: its normal, as long as twice its area. */
std::vector<glm::vec3> crossProducts(const std::vector<glm::vec3>& corners)
{
    std::vector<glm::vec3> crosses;
    for (std::size_t i = 0; i + 2 < corners.size(); i += 3)
        crosses.push_back(glm::cross(corners[i + 1] - corners[i], corners[i + 2] - corners[i]));
    return crosses;
}

double totalArea(const std::vector<glm::vec3>& corners)
{
    double area = 0.0;
    for (const glm::vec3& c : crossProducts(corners))
        area += 0.5 * double(glm::length(c));
    return area;
}

/** How far the corners spread along `axis`. */
float spread(const std::vector<glm::vec3>& corners, const glm::vec3& axis)
{
    float lo = std::numeric_limits<float>::max(), hi = -lo;
    for (const glm::vec3& c : corners) {
        lo = std::min(lo, glm::dot(c, axis));
        hi = std::max(hi, glm::dot(c, axis));
    }
    return hi - lo;
}

doc::LightNode rectNode()
{
    doc::LightNode rect;
    rect.type = doc::LightType::Rect;
    rect.position = { 0.1f, 0.7f, -0.2f };
    rect.direction = { 0.0f, -2.0f, 0.5f };
    rect.areaWidth = 0.4f;
    rect.areaHeight = 0.25f;
    rect.areaRotationDeg = 30.0f;
    rect.color = { 1.0f, 0.8f, 0.5f };
    rect.intensity = 12.0f;
    rect.castsShadows = false;
    return rect;
}

doc::LightNode diskNode()
{
    doc::LightNode disk;
    disk.type = doc::LightType::Disk;
    disk.position = { -0.3f, 0.5f, 0.0f };
    disk.direction = { 1.0f, 0.0f, 0.0f };
    disk.areaWidth = 0.3f;
    disk.color = { 0.5f, 1.0f, 1.0f };
    disk.intensity = 4.0f;
    return disk;
}

void compareSurface(const render::SurfaceLight& actual, const render::SurfaceLight& expected)
{
    QCOMPARE(int(actual.shape), int(expected.shape));
    QCOMPARE(actual.centre, expected.centre);
    QCOMPARE(actual.direction, expected.direction);
    QCOMPARE(actual.width, expected.width);
    QCOMPARE(actual.height, expected.height);
    QCOMPARE(actual.rotationDeg, expected.rotationDeg);
    // Split into colour and intensity and multiplied back, a channel may move by a rounding.
    for (int c = 0; c < 3; ++c)
        QCOMPARE(actual.radiance[c], expected.radiance[c]);
    QCOMPARE(actual.castsShadows, expected.castsShadows);
}

} // namespace

/**
 * Rect and disk lights: their triangles, their lights-file and project-file forms and the errors for
 * impossible ones, and how the document hands them to the renderers.
 */
class SurfaceLightsTest : public QObject {
    Q_OBJECT

private slots:
    void rectIsTwoTrianglesFacingItsDirection();
    void diskIsTwelveTrianglesWithTheDiskArea();
    void rotationBy90SwapsWidthAndHeight();
    void unusableLightsHaveNoTriangles_data();
    void unusableLightsHaveNoTriangles();
    void lightsFileReadsRectsAndDisks();
    void lightsFileRejectsImpossibleSurfaces_data();
    void lightsFileRejectsImpossibleSurfaces();
    void documentSendsThemToSurfaceLights();
    void sceneToDocumentAndBackIsLossless();
    void projectFileKeepsRectsAndDisks();
    void projectFileRejectsImpossibleSurfaces_data();
    void projectFileRejectsImpossibleSurfaces();
};

void SurfaceLightsTest::rectIsTwoTrianglesFacingItsDirection()
{
    for (const glm::vec3 direction :
        { glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(1.0f, 2.0f, -3.0f) }) {
        render::SurfaceLight rect;
        rect.centre = { 0.5f, 2.0f, -1.0f };
        rect.direction = direction;
        rect.width = 2.0f;
        rect.height = 0.5f;
        rect.rotationDeg = 20.0f;
        const std::vector<glm::vec3> corners = rect.triangles();
        QCOMPARE(corners.size(), std::size_t(6));
        QVERIFY(std::abs(totalArea(corners) - 1.0) < 1e-5);
        QVERIFY(std::abs(rect.area() - 1.0f) < 1e-6f);
        for (const glm::vec3& cross : crossProducts(corners))
            QVERIFY2(glm::dot(glm::normalize(cross), glm::normalize(direction)) > 0.9999f,
                "a triangle does not face the light's direction");
        glm::vec3 middle(0.0f);
        for (const glm::vec3& c : corners)
            middle += c;
        QVERIFY(glm::length(middle / 6.0f - rect.centre) < 1e-5f);
    }
}

void SurfaceLightsTest::diskIsTwelveTrianglesWithTheDiskArea()
{
    render::SurfaceLight disk;
    disk.shape = render::SurfaceLight::Shape::Disk;
    disk.centre = { 0.0f, 1.0f, 0.0f };
    disk.direction = { 0.3f, -1.0f, 0.2f };
    disk.width = 0.7f;
    disk.height = 5.0f; // unused by disks
    const std::vector<glm::vec3> corners = disk.triangles();
    QCOMPARE(corners.size(), std::size_t(3 * 12));
    const double expected = glm::pi<double>() * 0.7 * 0.7 / 4.0;
    QVERIFY2(std::abs(totalArea(corners) - expected) <= 1e-5 * expected,
        qPrintable(QString::number(totalArea(corners))));
    QVERIFY(std::abs(double(disk.area()) - expected) <= 1e-5 * expected);
    const glm::vec3 front = glm::normalize(disk.direction);
    for (const glm::vec3& cross : crossProducts(corners))
        QVERIFY2(glm::dot(glm::normalize(cross), front) > 0.9999f,
            "a triangle is not counter-clockwise from the front");
}

void SurfaceLightsTest::rotationBy90SwapsWidthAndHeight()
{
    render::SurfaceLight rect;
    rect.direction = { 0.0f, -1.0f, 0.0f };
    rect.width = 2.0f;
    rect.height = 0.5f;
    glm::vec3 u0, v0, front0;
    QVERIFY(rect.axes(u0, v0, front0));
    // Facing straight down, the width runs along world x at 0 degrees.
    QVERIFY(std::abs(std::abs(u0.x) - 1.0f) < 1e-6f);
    QVERIFY(std::abs(spread(rect.triangles(), u0) - 2.0f) < 1e-5f);
    QVERIFY(std::abs(spread(rect.triangles(), v0) - 0.5f) < 1e-5f);

    rect.rotationDeg = 90.0f;
    glm::vec3 u90, v90, front90;
    QVERIFY(rect.axes(u90, v90, front90));
    QVERIFY(std::abs(std::abs(glm::dot(u90, v0)) - 1.0f) < 1e-6f);
    QVERIFY(std::abs(std::abs(glm::dot(v90, u0)) - 1.0f) < 1e-6f);
    QVERIFY(glm::length(front90 - front0) < 1e-6f);
    QVERIFY(std::abs(spread(rect.triangles(), u0) - 0.5f) < 1e-5f);
    QVERIFY(std::abs(spread(rect.triangles(), v0) - 2.0f) < 1e-5f);
}

void SurfaceLightsTest::unusableLightsHaveNoTriangles_data()
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    QTest::addColumn<bool>("disk");
    QTest::addColumn<glm::vec3>("direction");
    QTest::addColumn<float>("width");
    QTest::addColumn<float>("height");
    for (const bool disk : { false, true }) {
        const char* shape = disk ? "disk" : "rect";
        QTest::addRow("%s, zero direction", shape) << disk << glm::vec3(0.0f) << 1.0f << 1.0f;
        QTest::addRow("%s, NaN direction", shape) << disk << glm::vec3(0.0f, nan, 0.0f) << 1.0f << 1.0f;
        QTest::addRow("%s, zero width", shape) << disk << glm::vec3(0.0f, -1.0f, 0.0f) << 0.0f << 1.0f;
        QTest::addRow("%s, negative width", shape) << disk << glm::vec3(0.0f, -1.0f, 0.0f) << -1.0f << 1.0f;
        QTest::addRow("%s, NaN width", shape) << disk << glm::vec3(0.0f, -1.0f, 0.0f) << nan << 1.0f;
    }
    QTest::addRow("rect, zero height") << false << glm::vec3(0.0f, -1.0f, 0.0f) << 1.0f << 0.0f;
    QTest::addRow("rect, NaN height") << false << glm::vec3(0.0f, -1.0f, 0.0f) << 1.0f << nan;
}

void SurfaceLightsTest::unusableLightsHaveNoTriangles()
{
    QFETCH(bool, disk);
    QFETCH(glm::vec3, direction);
    QFETCH(float, width);
    QFETCH(float, height);
    render::SurfaceLight light;
    light.shape = disk ? render::SurfaceLight::Shape::Disk : render::SurfaceLight::Shape::Rectangle;
    light.direction = direction;
    light.width = width;
    light.height = height;
    QVERIFY(light.triangles().empty());
}

void SurfaceLightsTest::lightsFileReadsRectsAndDisks()
{
    const QString path = test::writeFile(test::outputDir() + QStringLiteral("/surface/read.lights.json"),
        R"({"shadows": false, "lights": [
        {"type": "rect", "position": [0, 2, 0], "direction": [0, -2, 0], "size": [1.5, 0.5],
         "rotation_deg": 30, "radiance": [10, 8, 6], "shadows": true},
        {"type": "rect", "position": [1, 2, 0], "direction": [0, -1, 0], "size": [1, 1], "radiance": [1, 1, 1]},
        {"type": "disk", "position": [0, 1, 3], "direction": [0, 0, -1], "diameter": 0.4, "radiance": [5, 5, 5]}]})");
    render::Scene scene;
    QString error;
    QVERIFY2(doc::LightsFile::read(path, scene, &error), qPrintable(error));
    QVERIFY(scene.pointLights.empty() && scene.directionalLights.empty());
    QCOMPARE(scene.surfaceLights.size(), std::size_t(3));

    render::SurfaceLight rect;
    rect.centre = { 0.0f, 2.0f, 0.0f };
    rect.direction = { 0.0f, -2.0f, 0.0f };
    rect.width = 1.5f;
    rect.height = 0.5f;
    rect.rotationDeg = 30.0f;
    rect.radiance = { 10.0f, 8.0f, 6.0f };
    rect.castsShadows = true;
    compareSurface(scene.surfaceLights[0], rect);
    QCOMPARE(scene.surfaceLights[1].rotationDeg, 0.0f); // optional
    QVERIFY(!scene.surfaceLights[1].castsShadows); // the file's default
    render::SurfaceLight disk;
    disk.shape = render::SurfaceLight::Shape::Disk;
    disk.centre = { 0.0f, 1.0f, 3.0f };
    disk.direction = { 0.0f, 0.0f, -1.0f };
    disk.width = 0.4f;
    disk.radiance = glm::vec3(5.0f);
    disk.castsShadows = false;
    compareSurface(scene.surfaceLights[2], disk);
}

void SurfaceLightsTest::lightsFileRejectsImpossibleSurfaces_data()
{
    QTest::addColumn<QByteArray>("light");
    QTest::addColumn<QString>("field");
    const QByteArray rect = R"("type": "rect", "position": [0, 2, 0], "radiance": [1, 1, 1], )";
    const QByteArray disk = R"("type": "disk", "position": [0, 2, 0], "radiance": [1, 1, 1], )";
    const QByteArray down = R"("direction": [0, -1, 0], )";
    // JSON has no infinity or NaN (Qt refuses 1e999); 1e39 is a finite double a float cannot hold.
    QTest::newRow("rect, zero width") << rect + down + R"("size": [0, 1])"
                                      << "lights[1].size";
    QTest::newRow("rect, negative height") << rect + down + R"("size": [1, -0.5])"
                                           << "lights[1].size";
    QTest::newRow("rect, width too large") << rect + down + R"("size": [1e39, 1])"
                                           << "lights[1].size";
    QTest::newRow("rect, one size") << rect + down + R"("size": [1])"
                                    << "lights[1].size";
    QTest::newRow("rect, size as text") << rect + down + R"("size": [1, "2"])"
                                        << "lights[1].size";
    QTest::newRow("rect, no size") << rect + down + R"("diameter": 1)"
                                   << "lights[1].size";
    QTest::newRow("rect, zero direction") << rect + R"("direction": [0, 0, 0], "size": [1, 1])"
                                          << "lights[1].direction";
    QTest::newRow("rect, direction too large") << rect + R"("direction": [0, -1e39, 0], "size": [1, 1])"
                                               << "lights[1].direction";
    QTest::newRow("rect, rotation too large") << rect + down + R"("size": [1, 1], "rotation_deg": -1e39)"
                                              << "lights[1].rotation_deg";
    QTest::newRow("rect, rotation as text") << rect + down + R"("size": [1, 1], "rotation_deg": "90")"
                                            << "lights[1].rotation_deg";
    QTest::newRow("rect, negative radiance")
        << QByteArray(R"("type": "rect", "position": [0, 2, 0], "radiance": [1, -1, 1], )") + down
            + R"("size": [1, 1])"
        << "lights[1].radiance";
    QTest::newRow("rect, position too large")
        << QByteArray(R"("type": "rect", "position": [0, 1e39, 0], "radiance": [1, 1, 1], )") + down
            + R"("size": [1, 1])"
        << "lights[1].position";
    QTest::newRow("disk, zero diameter") << disk + down + R"("diameter": 0)"
                                         << "lights[1].diameter";
    QTest::newRow("disk, negative diameter") << disk + down + R"("diameter": -1)"
                                             << "lights[1].diameter";
    QTest::newRow("disk, diameter too large") << disk + down + R"("diameter": 1e39)"
                                              << "lights[1].diameter";
    QTest::newRow("disk, no diameter") << disk + down + R"("size": [1, 1])"
                                       << "lights[1].diameter";
    QTest::newRow("disk, zero direction") << disk + R"("direction": [0, 0, 0], "diameter": 1)"
                                          << "lights[1].direction";
    QTest::newRow("disk, negative radiance")
        << QByteArray(R"("type": "disk", "position": [0, 2, 0], "radiance": [-1, 1, 1], )") + down
            + R"("diameter": 1)"
        << "lights[1].radiance";
    QTest::newRow("disk, no radiance")
        << QByteArray(R"("type": "disk", "position": [0, 2, 0], )") + down + R"("diameter": 1)"
        << "lights[1].radiance";
}

void SurfaceLightsTest::lightsFileRejectsImpossibleSurfaces()
{
    QFETCH(QByteArray, light);
    QFETCH(QString, field);
    const QString path = test::writeFile(test::outputDir() + QStringLiteral("/surface/bad.lights.json"),
        R"({"lights": [{"type": "point", "position": [0, 1, 0], "intensity": [1, 1, 1]}, {)" + light + "}]}");
    render::Scene scene;
    scene.surfaceLights.push_back({});
    QString error;
    QVERIFY(!doc::LightsFile::read(path, scene, &error));
    QVERIFY2(error.contains(QStringLiteral("'%1'").arg(field))
            && error.contains(QStringLiteral("bad.lights.json")),
        qPrintable(error));
    QCOMPARE(scene.surfaceLights.size(), std::size_t(1)); // the scene is untouched
    QVERIFY(scene.pointLights.empty());
}

void SurfaceLightsTest::documentSendsThemToSurfaceLights()
{
    doc::Document document;
    QString error;
    QVERIFY2(document.newFromScene(QStringLiteral("builtin:cornell_point"), &error), qPrintable(error));
    const render::Scene before = document.buildRenderScene();
    QVERIFY(!before.pointLights.empty());
    document.addLight(rectNode());
    document.addLight(diskNode());
    QCOMPARE(
        document.state().lights[document.state().lights.size() - 2].name, QStringLiteral("Rect light 1"));
    QCOMPARE(document.state().lights.back().name, QStringLiteral("Disk light 1"));

    const render::Scene scene = document.buildRenderScene();
    QCOMPARE(scene.pointLights.size(), before.pointLights.size());
    QCOMPARE(scene.directionalLights.size(), before.directionalLights.size());
    QCOMPARE(scene.surfaceLights.size(), before.surfaceLights.size() + 2);
    const doc::LightNode rect = rectNode();
    render::SurfaceLight expected;
    expected.centre = rect.position;
    expected.direction = rect.direction;
    expected.width = rect.areaWidth;
    expected.height = rect.areaHeight;
    expected.rotationDeg = rect.areaRotationDeg;
    expected.radiance = rect.color * rect.intensity;
    expected.castsShadows = rect.castsShadows;
    compareSurface(scene.surfaceLights[scene.surfaceLights.size() - 2], expected);
    const render::SurfaceLight& disk = scene.surfaceLights.back();
    QCOMPARE(int(disk.shape), int(render::SurfaceLight::Shape::Disk));
    QCOMPARE(disk.width, diskNode().areaWidth);
    QCOMPARE(disk.radiance, diskNode().color * diskNode().intensity);
    QVERIFY(!rect.isPointLike() && !diskNode().isPointLike());
    QVERIFY(rect.isSurface() && diskNode().isSurface());

    document.undoStack()->undo();
    document.undoStack()->undo();
    QCOMPARE(document.buildRenderScene().surfaceLights.size(), before.surfaceLights.size());
}

void SurfaceLightsTest::sceneToDocumentAndBackIsLossless()
{
    const QString dir = test::outputDir() + QStringLiteral("/surface/model");
    const QString model = test::writeFile(
        dir + QStringLiteral("/lit.obj"), "o Floor\nv -1 0 -1\nv 1 0 -1\nv 1 0 1\nf 1 3 2\n");
    const QString lights = test::writeFile(dir + QStringLiteral("/lit.lights.json"),
        R"({"lights": [
        {"type": "rect", "position": [0, 2, 0.5], "direction": [0.1, -3, 0], "size": [1.5, 0.25],
         "rotation_deg": -40, "radiance": [10, 7.5, 0.5], "shadows": false},
        {"type": "disk", "position": [0, 1, 3], "direction": [0, 0, -1], "diameter": 0.4, "radiance": [0.2, 0.3, 0.1]},
        {"type": "point", "position": [0, 1, 0], "intensity": [1, 1, 1]}]})");
    render::Scene fromFile;
    QString error;
    QVERIFY2(doc::LightsFile::read(lights, fromFile, &error), qPrintable(error));

    doc::Document document;
    QVERIFY2(document.newFromScene(model, &error), qPrintable(error));
    const std::vector<doc::LightNode>& nodes = document.state().lights;
    QCOMPARE(nodes.size(), std::size_t(3));
    QCOMPARE(nodes[1].name, QStringLiteral("Rect light 1"));
    QCOMPARE(nodes[1].type, doc::LightType::Rect);
    QCOMPARE(nodes[1].areaRotationDeg, -40.0f);
    QCOMPARE(nodes[2].name, QStringLiteral("Disk light 1"));
    QCOMPARE(nodes[2].type, doc::LightType::Disk);
    QCOMPARE(nodes[2].color, glm::vec3(0.2f, 0.3f, 0.1f) / 0.3f); // the brightest channel is 1
    QCOMPARE(nodes[2].intensity, 0.3f);

    const render::Scene scene = document.buildRenderScene();
    QCOMPARE(scene.pointLights.size(), std::size_t(1));
    QCOMPARE(scene.surfaceLights.size(), std::size_t(2));
    for (std::size_t i = 0; i < 2; ++i)
        compareSurface(scene.surfaceLights[i], fromFile.surfaceLights[i]);

    // Importing again numbers on from the lights already there.
    QVERIFY2(document.importModel(model, &error), qPrintable(error));
    QCOMPARE(document.state().lights.size(), std::size_t(6));
    QCOMPARE(document.state().lights[4].name, QStringLiteral("Rect light 2"));
    QCOMPARE(document.state().lights[5].name, QStringLiteral("Disk light 2"));
}

void SurfaceLightsTest::projectFileKeepsRectsAndDisks()
{
    doc::Document document;
    QString error;
    QVERIFY2(document.newFromScene(QStringLiteral("builtin:cornell"), &error), qPrintable(error));
    document.addLight(rectNode());
    doc::LightNode disk = diskNode();
    disk.name = QStringLiteral("Round");
    document.addLight(disk);
    const QString dir = test::outputDir() + QStringLiteral("/surface/project");
    QDir().mkpath(dir);
    const QString path = dir + QStringLiteral("/surfaces.vctproj");
    QVERIFY2(document.saveProject(path, &error), qPrintable(error));

    doc::Document reopened;
    QVERIFY2(reopened.openProject(path, &error), qPrintable(error));
    QCOMPARE(reopened.state().lights.size(), document.state().lights.size());
    for (std::size_t i = 0; i < document.state().lights.size(); ++i)
        QVERIFY2(reopened.state().lights[i] == document.state().lights[i], qPrintable(QString::number(i)));
    QCOMPARE(reopened.state().lights.back().name, QStringLiteral("Round"));

    // The file names them as lights files do.
    const QJsonObject root
        = QJsonDocument::fromJson(doc::ProjectFile::toJson(document.state(), dir)).object();
    const QJsonArray lights = root.value("lights").toArray();
    const QJsonObject rect = lights[lights.size() - 2].toObject();
    QCOMPARE(rect.value("type").toString(), QStringLiteral("rect"));
    QCOMPARE(rect.value("size").toArray().size(), 2);
    QCOMPARE(rect.value("rotation_deg").toDouble(), 30.0);
    const QJsonObject round = lights[lights.size() - 1].toObject();
    QCOMPARE(round.value("type").toString(), QStringLiteral("disk"));
    QCOMPARE(round.value("diameter").toDouble(), double(0.3f));
}

void SurfaceLightsTest::projectFileRejectsImpossibleSurfaces_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<QJsonValue>("value");
    QTest::addColumn<bool>("disk");
    QTest::addColumn<QString>("field");
    QTest::newRow("rect, zero width")
        << "size" << QJsonValue(QJsonArray { 0, 1 }) << false << "lights[1].size";
    QTest::newRow("rect, negative height")
        << "size" << QJsonValue(QJsonArray { 1, -1 }) << false << "lights[1].size";
    QTest::newRow("rect, width too large")
        << "size" << QJsonValue(QJsonArray { 1e39, 1 }) << false << "lights[1].size";
    QTest::newRow("rect, three sizes")
        << "size" << QJsonValue(QJsonArray { 1, 1, 1 }) << false << "lights[1].size";
    QTest::newRow("rect, no size") << "size" << QJsonValue(QJsonValue::Undefined) << false
                                   << "lights[1].size";
    QTest::newRow("rect, rotation as text")
        << "rotation_deg" << QJsonValue("90") << false << "lights[1].rotation_deg";
    QTest::newRow("rect, zero direction")
        << "direction" << QJsonValue(QJsonArray { 0, 0, 0 }) << false << "lights[1].direction";
    QTest::newRow("disk, zero diameter") << "diameter" << QJsonValue(0) << true << "lights[1].diameter";
    QTest::newRow("disk, negative diameter")
        << "diameter" << QJsonValue(-0.5) << true << "lights[1].diameter";
    QTest::newRow("disk, diameter too large")
        << "diameter" << QJsonValue(1e39) << true << "lights[1].diameter";
    QTest::newRow("disk, no diameter")
        << "diameter" << QJsonValue(QJsonValue::Undefined) << true << "lights[1].diameter";
    QTest::newRow("disk, zero direction")
        << "direction" << QJsonValue(QJsonArray { 0, 0, 0 }) << true << "lights[1].direction";
    QTest::newRow("disk, negative radiance")
        << "intensity" << QJsonValue(-1) << true << "lights[1].intensity";
}

void SurfaceLightsTest::projectFileRejectsImpossibleSurfaces()
{
    QFETCH(QString, key);
    QFETCH(QJsonValue, value);
    QFETCH(bool, disk);
    QFETCH(QString, field);
    doc::DocumentState state;
    doc::LightNode point;
    point.id = 1;
    point.name = QStringLiteral("Point light 1");
    state.lights.push_back(point);
    doc::LightNode surface = disk ? diskNode() : rectNode();
    surface.id = 2;
    surface.name = QStringLiteral("Surface");
    state.lights.push_back(surface);
    state.nextId = 3;
    const QString dir = test::outputDir();
    QJsonObject root = QJsonDocument::fromJson(doc::ProjectFile::toJson(state, dir)).object();
    QJsonArray lights = root.value("lights").toArray();
    QJsonObject light = lights[1].toObject();
    if (value.isUndefined())
        light.remove(key);
    else
        light.insert(key, value);
    lights[1] = light;
    root.insert("lights", lights);

    doc::DocumentState read;
    QString error;
    QVERIFY(!doc::ProjectFile::fromJson(
        QJsonDocument(root).toJson(), dir, QStringLiteral("bad.vctproj"), &read, &error));
    QVERIFY2(
        error.contains(QStringLiteral("'%1'").arg(field)) && error.contains(QStringLiteral("bad.vctproj")),
        qPrintable(error));
    QVERIFY(read.lights.empty()); // untouched
}

QTEST_GUILESS_MAIN(SurfaceLightsTest)
#include "tst_SurfaceLights.moc"
