#include "GlTestContext.h"
#include "TestSupport.h"

#include "reference/ReferenceRenderer.h"

#include <QtTest>

using namespace vct;

/** A spot light over a floor: the VCT renderer's direct light across the cone's edge matches the path
 * tracer's. */
class SpotLightTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void coneEdgeFollowsThePathTracer();

private:
    test::GlTestContext m_gl;
};

void SpotLightTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
}

// From the axis through the smooth edge (inner 20, outer 35 degrees, 1.5 m up: 0.55 m and 1.05 m out on the
// floor) to the dark beyond: within 3% of the radiance under the light everywhere on the line.
void SpotLightTest::coneEdgeFollowsThePathTracer()
{
    constexpr int kSize = 96;
    render::Scene scene;
    render::Material floor;
    floor.albedo = glm::vec3(0.5f);
    scene.materials = { floor };
    scene.meshes.push_back(
        test::makeTriangles(test::quad({ -2, 0, 2 }, { 2, 0, 2 }, { 2, 0, -2 }, { -2, 0, -2 }), 0));
    render::PointLight spot;
    spot.position = { 0.0f, 1.5f, 0.0f };
    spot.intensity = glm::vec3(4.0f);
    spot.spotDirection = { 0.0f, -1.0f, 0.0f };
    spot.spotInnerDeg = 20.0f;
    spot.spotOuterDeg = 35.0f;
    scene.pointLights.push_back(spot);
    scene.camera = { { 0.0f, 2.6f, 3.5f }, { 0.0f, 0.0f, 0.0f }, { 0, 1, 0 }, 60.0f, 0.01f };

    render::RenderSettings settings;
    settings.voxelResolution = 64;
    settings.view = render::DebugView::Direct;
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(scene);
    m_gl.renderer->renderFrame(scene.camera, kSize, kSize);
    const render::RadianceImage image = m_gl.renderer->readFrame();
    QVERIFY(m_gl.renderer->takeGlErrors().empty());
    render::ReferenceSettings reference;
    reference.maxBounces = 1;
    render::ReferenceRenderer tracer(scene, scene.camera, kSize, kSize, reference);
    QVERIFY(tracer.render(16));
    const render::RadianceImage truth = tracer.image();

    const glm::ivec2 centre = test::pixelOf(scene.camera, { 0.0f, 0.0f, 0.0f }, kSize);
    const double peak = truth.at(centre.x, centre.y).r;
    QVERIFY(peak > 0.0);
    double worst = 0.0;
    for (int i = 0; i <= 15; ++i) {
        const float x = 0.1f * float(i);
        const glm::ivec2 pixel = test::pixelOf(scene.camera, { x, 0.0f, 0.0f }, kSize);
        const double ours = image.at(pixel.x, pixel.y).r, theirs = truth.at(pixel.x, pixel.y).r;
        worst = std::max(worst, std::abs(ours - theirs) / peak);
        if (x > 1.2f)
            QCOMPARE(ours, 0.0); // beyond the outer angle
    }
    qInfo("largest difference along the line: %.2f%% of the radiance under the light", 100.0 * worst);
    QVERIFY2(worst <= 0.03, qPrintable(QString::number(worst)));
}

QTEST_GUILESS_MAIN(SpotLightTest)
#include "tst_SpotLight.moc"
