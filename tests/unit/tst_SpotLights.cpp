#include "TestSupport.h"

#include "document/DocumentState.h"
#include "document/LightsFile.h"
#include "document/ProjectFile.h"

#include <glm/trigonometric.hpp>

#include <QtTest>

using namespace vct;

/** Spot lights: their falloff, their lights-file and project-file forms, and the errors for bad cones. */
class SpotLightsTest : public QObject {
    Q_OBJECT

private slots:
    void falloffIsFullInsideNoneOutsideSmoothBetween();
    void lightsFileReadsSpots();
    void lightsFileRejectsImpossibleCones_data();
    void lightsFileRejectsImpossibleCones();
    void projectFileKeepsSpots();

private:
    QString writeLights(const QByteArray& json);
};

QString SpotLightsTest::writeLights(const QByteArray& json)
{
    const QString path = test::outputDir() + QStringLiteral("/spot.lights.json");
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(json) != json.size())
        qFatal("cannot write %s", qPrintable(path));
    return path;
}

void SpotLightsTest::falloffIsFullInsideNoneOutsideSmoothBetween()
{
    render::PointLight spot;
    spot.spotDirection = { 0.0f, -1.0f, 0.0f };
    spot.spotInnerDeg = 20.0f;
    spot.spotOuterDeg = 40.0f;
    const auto at = [](float deg) {
        return glm::vec3(std::sin(glm::radians(deg)), -std::cos(glm::radians(deg)), 0.0f);
    };
    QCOMPARE(spot.spotFactor(at(0.0f)), 1.0f);
    QCOMPARE(spot.spotFactor(at(19.0f)), 1.0f);
    QCOMPARE(spot.spotFactor(at(41.0f)), 0.0f);
    QCOMPARE(spot.spotFactor(-at(0.0f)), 0.0f);
    const float mid = spot.spotFactor(at(30.0f));
    QVERIFY(mid > 0.2f && mid < 0.8f);
    QVERIFY(spot.spotFactor(at(25.0f)) > mid && spot.spotFactor(at(35.0f)) < mid);
    const render::PointLight point; // isotropic: everywhere
    QCOMPARE(point.spotFactor(at(170.0f)), 1.0f);
}

void SpotLightsTest::lightsFileReadsSpots()
{
    const QString path
        = writeLights(R"({"lights": [{"type": "spot", "position": [0, 2, 0], "direction": [0, -2, 0],
        "intensity": [3, 3, 3], "inner_deg": 15, "outer_deg": 30}]})");
    render::Scene scene;
    QString error;
    QVERIFY2(doc::LightsFile::read(path, scene, &error), qPrintable(error));
    QCOMPARE(scene.pointLights.size(), std::size_t(1));
    const render::PointLight& spot = scene.pointLights[0];
    QVERIFY(spot.isSpot());
    QCOMPARE(spot.spotDirection, glm::vec3(0.0f, -1.0f, 0.0f));
    QCOMPARE(spot.spotInnerDeg, 15.0f);
    QCOMPARE(spot.spotOuterDeg, 30.0f);
    QCOMPARE(spot.intensity, glm::vec3(3.0f));
}

void SpotLightsTest::lightsFileRejectsImpossibleCones_data()
{
    QTest::addColumn<QByteArray>("light");
    QTest::addColumn<QString>("field");
    QTest::newRow("inner beyond outer")
        << QByteArray(R"("inner_deg": 40, "outer_deg": 30)") << QStringLiteral("outer_deg");
    QTest::newRow("outer beyond 90") << QByteArray(R"("inner_deg": 10, "outer_deg": 120)")
                                     << QStringLiteral("outer_deg");
    QTest::newRow("no outer angle") << QByteArray(R"("inner_deg": 10)") << QStringLiteral("outer_deg");
}

void SpotLightsTest::lightsFileRejectsImpossibleCones()
{
    QFETCH(QByteArray, light);
    QFETCH(QString, field);
    const QString path
        = writeLights(R"({"lights": [{"type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0],
        "intensity": [1, 1, 1], )"
            + light + "}]}");
    render::Scene scene;
    scene.pointLights.push_back({});
    QString error;
    QVERIFY(!doc::LightsFile::read(path, scene, &error));
    QVERIFY2(error.contains(field) && error.contains(QStringLiteral("spot.lights.json")), qPrintable(error));
    QCOMPARE(scene.pointLights.size(), std::size_t(1)); // the scene is untouched
}

void SpotLightsTest::projectFileKeepsSpots()
{
    doc::DocumentState state;
    doc::LightNode spot;
    spot.id = 1;
    spot.name = QStringLiteral("Spot light 1");
    spot.type = doc::LightType::Spot;
    spot.position = { 1.0f, 2.0f, 3.0f };
    spot.direction = { 0.0f, -1.0f, 0.5f };
    spot.spotInnerDeg = 12.5f;
    spot.spotOuterDeg = 33.0f;
    state.lights.push_back(spot);
    state.nextId = 2;
    const QByteArray json = doc::ProjectFile::toJson(state, test::outputDir());
    doc::DocumentState read;
    QString error;
    QVERIFY2(
        doc::ProjectFile::fromJson(json, test::outputDir(), QStringLiteral("spot.vctproj"), &read, &error),
        qPrintable(error));
    QCOMPARE(read.lights.size(), std::size_t(1));
    QVERIFY(read.lights[0] == spot);
    const render::PointLight light = read.lights[0].pointLight();
    QVERIFY(light.isSpot());
    QCOMPARE(light.spotOuterDeg, 33.0f);
}

QTEST_GUILESS_MAIN(SpotLightsTest)
#include "tst_SpotLights.moc"
