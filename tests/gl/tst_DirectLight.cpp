#include "GlTestContext.h"
#include "TestSupport.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <QtTest>

#include <tuple>

using namespace vct;

/**
 * The composite's direct light against its closed form, on a Lambertian floor seen from straight above: a
 * point light gives L = rho / pi * I cos(theta) / d^2, a directional light L = rho / pi * E cos(theta), both
 * lights add, and a blocker's shadow takes each away. The composite is specialised by light counts, so each
 * mix of light kinds runs its own shader.
 */
class DirectLightTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void matchesClosedForm_data();
    void matchesClosedForm();

private:
    render::RadianceImage renderDirect(const render::Scene& scene);
    /** Where the ray through the centre of image pixel @p p meets the floor: the point that pixel shades. */
    glm::vec3 floorPointOf(glm::ivec2 p) const;
    test::GlTestContext m_gl;
    // Straight down onto the floor (y = 0): the view direction does not enter a Lambertian term.
    const render::Camera m_camera { { 8.0f, 12.0f, 8.001f }, { 8.0f, 0.0f, 8.0f }, { 0, 0, -1 }, 60.0f,
        0.05f };
    static constexpr int kSize = 64;
    static constexpr float kAlbedo = 0.6f;
};

void DirectLightTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
}

render::RadianceImage DirectLightTest::renderDirect(const render::Scene& scene)
{
    render::RenderSettings settings;
    settings.voxelResolution = 32;
    settings.view = render::DebugView::Direct;
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(scene);
    m_gl.renderer->setGridBounds(test::box(glm::vec3(0.5f, -0.5f, 0.5f), glm::vec3(15.5f, 6.0f, 15.5f)));
    m_gl.renderer->renderFrame(m_camera, kSize, kSize);
    return m_gl.renderer->readFrame();
}

glm::vec3 DirectLightTest::floorPointOf(glm::ivec2 p) const
{
    const glm::mat4 view = glm::lookAt(m_camera.position, m_camera.lookAt, m_camera.up);
    const glm::mat4 projection = glm::perspective(glm::radians(m_camera.fovYDeg), 1.0f, 0.05f, 100.0f);
    const glm::vec3 window(float(p.x) + 0.5f, float(kSize - 1 - p.y) + 0.5f, 0.5f);
    const glm::vec3 onRay = glm::unProject(window, view, projection, glm::vec4(0, 0, kSize, kSize));
    const glm::vec3 dir = onRay - m_camera.position;
    return m_camera.position + dir * (-m_camera.position.y / dir.y);
}

void DirectLightTest::matchesClosedForm_data()
{
    QTest::addColumn<bool>("point");
    QTest::addColumn<bool>("directional");
    QTest::newRow("point light") << true << false;
    QTest::newRow("directional light") << false << true;
    QTest::newRow("both") << true << true;
}

void DirectLightTest::matchesClosedForm()
{
    QFETCH(bool, point);
    QFETCH(bool, directional);
    render::Scene scene;
    render::Material floor, blocker;
    floor.albedo = glm::vec3(kAlbedo);
    blocker.albedo = glm::vec3(0.2f);
    scene.materials = { floor, blocker };
    scene.meshes.push_back(
        test::makeTriangles(test::quad({ 1, 0, 15 }, { 15, 0, 15 }, { 15, 0, 1 }, { 1, 0, 1 }), 0));
    // A small roof at y = 2 over x in [7, 8], z in [9, 10], facing up, to cast one shadow of each light on
    // the floor where the camera sees it.
    scene.meshes.push_back(
        test::makeTriangles(test::quad({ 7, 2, 10 }, { 8, 2, 10 }, { 8, 2, 9 }, { 7, 2, 9 }), 1));
    const glm::vec3 lightPosition(5.0f, 5.0f, 8.0f);
    const glm::vec3 intensity(30.0f);
    const glm::vec3 sunDirection(-1.0f, -1.0f, 0.0f); // travel direction, 45 degrees from the zenith
    const glm::vec3 sunIrradiance(2.0f);
    if (point)
        scene.pointLights.push_back({ lightPosition, intensity, true });
    if (directional)
        scene.directionalLights.push_back({ sunDirection, sunIrradiance, true });
    const render::RadianceImage image = renderDirect(scene);

    const auto pointTerm = [&](const glm::vec3& at) {
        const glm::vec3 d = lightPosition - at;
        const float distance2 = glm::dot(d, d);
        return kAlbedo / glm::pi<float>() * intensity.x * (d.y / std::sqrt(distance2)) / distance2;
    };
    const float sunTerm = kAlbedo / glm::pi<float>() * sunIrradiance.x * std::sqrt(0.5f);
    // Lit by both; in the roof's shadow from the point light (the shadow spans x 8.3..10, z 9.7..11.3) but
    // not from the sun; in its shadow from the sun (x 5..6, z 9..10) but not from the point light.
    const glm::vec3 lit(11.0f, 0.0f, 12.0f), pointShadow(9.2f, 0.0f, 10.5f), sunShadow(5.5f, 0.0f, 9.5f);
    const float fromSun = directional ? sunTerm : 0.0f;
    for (const auto& [name, at, pointLit, sunLit] : { std::tuple { "lit", lit, true, true },
             std::tuple { "below the light", glm::vec3(5.0f, 0.0f, 8.0f), true, true },
             std::tuple { "in the point light's shadow", pointShadow, false, true },
             std::tuple { "in the sun's shadow", sunShadow, true, false } }) {
        const glm::ivec2 p = test::pixelOf(m_camera, at, kSize);
        QVERIFY(p.x >= 0 && p.y >= 0 && p.x < kSize && p.y < kSize);
        const float expected
            = (point && pointLit ? pointTerm(floorPointOf(p)) : 0.0f) + (sunLit ? fromSun : 0.0f);
        const float got = image.at(p.x, p.y).r;
        qInfo("%s: %.4f, closed form %.4f", name, double(got), double(expected));
        QVERIFY2(std::abs(got - expected) <= 0.01f * std::max(expected, 0.05f),
            qPrintable(QString("%1: %2, expected %3").arg(name).arg(got).arg(expected)));
    }
    QVERIFY(m_gl.renderer->takeGlErrors().empty());
}

QTEST_GUILESS_MAIN(DirectLightTest)
#include "tst_DirectLight.moc"
