#include "TestSupport.h"

#include "document/NewLight.h"

#include <glm/gtc/constants.hpp>

#include <QtTest>

using namespace vct;

/** A light added from the Light panel is as strong as the scene's own lights, whatever the scene's size. */
class tst_NewLight : public QObject {
    Q_OBJECT

private slots:
    void matchesTheIrradianceOfTheExistingLights_data()
    {
        QTest::addColumn<double>("metres");
        QTest::newRow("a 2 m room") << 2.0;
        QTest::newRow("a 40 m courtyard") << 40.0;
        QTest::newRow("a 2 cm model") << 0.02;
    }

    void matchesTheIrradianceOfTheExistingLights()
    {
        QFETCH(double, metres);
        const float size = float(metres);
        const render::Aabb bounds = test::box(glm::vec3(-0.5f * size), glm::vec3(0.5f * size));
        const glm::vec3 lookAt(0.0f);
        const float distance = 0.25f * glm::length(bounds.size());

        doc::LightNode sun;
        sun.type = doc::LightType::Directional;
        sun.intensity = 10.0f;
        sun.color = glm::vec3(1.0f, 0.9f, 0.8f);
        doc::LightNode lamp;
        lamp.position = glm::vec3(0.0f, 0.3f * size, 0.0f);
        lamp.intensity = 2.0f * (0.3f * size) * (0.3f * size); // 2 W/m² at lookAt
        const std::vector<doc::LightNode> lights { sun, lamp };
        const float wanted = 0.5f * (10.0f + 2.0f);

        for (doc::LightType type : { doc::LightType::Point, doc::LightType::Spot, doc::LightType::Directional,
                 doc::LightType::Rect, doc::LightType::Disk }) {
            const doc::LightNode light = doc::NewLight::make(type, bounds, lookAt, lights);
            QCOMPARE(light.type, type);
            // At a quarter of the diagonal, along the way it shines (two significant digits: within 5%).
            glm::vec3 probe = light.position + glm::vec3(0.0f, -distance, 0.0f);
            if (type == doc::LightType::Spot)
                probe = light.position + distance * glm::normalize(light.direction);
            const float got = doc::NewLight::irradianceAt(light, probe);
            QVERIFY2(std::abs(got / wanted - 1.0f) <= 0.05f,
                qPrintable(
                    QStringLiteral("type %1: %2 W/m² against %3").arg(int(type)).arg(got).arg(wanted)));
        }
    }

    void withoutLightsAWhiteWallReadsOne()
    {
        const render::Aabb bounds = test::box(glm::vec3(-1.0f), glm::vec3(1.0f));
        const doc::LightNode light
            = doc::NewLight::make(doc::LightType::Directional, bounds, glm::vec3(0.0f), {});
        QVERIFY(std::abs(light.intensity - glm::pi<float>()) < 0.05f);
        const doc::LightNode point = doc::NewLight::make(doc::LightType::Point, {}, glm::vec3(0.0f), {});
        QVERIFY(std::isfinite(point.intensity) && point.intensity > 0.0f);
    }

    // On a disk's axis: E = π L r² / (d² + r²).
    void diskIrradianceOnItsAxis()
    {
        doc::LightNode disk;
        disk.type = doc::LightType::Disk;
        disk.areaWidth = 2.0f; // r = 1
        disk.intensity = 3.0f;
        disk.position = glm::vec3(0.0f);
        disk.direction = glm::vec3(0.0f, -1.0f, 0.0f);
        const float expected = glm::pi<float>() * 3.0f * 1.0f / (4.0f + 1.0f);
        QVERIFY(std::abs(doc::NewLight::irradianceAt(disk, glm::vec3(0.0f, -2.0f, 0.0f)) - expected) < 1e-4f);
        QCOMPARE(doc::NewLight::irradianceAt(disk, glm::vec3(0.0f, 2.0f, 0.0f)), 0.0f); // one-sided
    }
};

QTEST_GUILESS_MAIN(tst_NewLight)
#include "tst_NewLight.moc"
