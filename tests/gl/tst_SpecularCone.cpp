#include "GlTestContext.h"
#include "TestSupport.h"


#include <QtTest>

using namespace vct;

/** The specular cone: glossy surfaces reflect what lies along the mirror direction, others get none. */
class SpecularConeTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void glossyFloorMirrorsEmitter();
    void matteFloorHasNoSpecularTerm();
    void reducedResolutionStaysCloseToFull();

private:
    render::RadianceImage renderSpecular(bool glossy, int divisor = 8, int size = kSize);
    test::GlTestContext m_gl;
    const render::Camera m_camera{{8.0f, 4.0f, 14.0f}, {8.0f, 0.5f, 6.0f}, {0, 1, 0}, 70.0f, 0.01f};
    static constexpr int kSize = 48;
};

void SpecularConeTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
}

render::RadianceImage SpecularConeTest::renderSpecular(bool glossy, int divisor, int size)
{
    render::Scene scene;
    render::Material floor;
    floor.albedo = glm::vec3(0.0f);
    floor.specular = glm::vec3(glossy ? 0.5f : 0.0f);
    floor.shininess = glossy ? 200.0f : 0.0f;
    render::Material emitter;
    emitter.albedo = glm::vec3(0.0f);
    emitter.emission = glm::vec3(5.0f);
    scene.materials = {floor, emitter};
    scene.meshes.push_back(test::makeTriangles(test::quad({1, 0.5f, 15}, {15, 0.5f, 15}, {15, 0.5f, 1}, {1, 0.5f, 1}), 0));
    // A wall of light at z = 2 facing the camera (+z).
    scene.meshes.push_back(test::makeTriangles(test::quad({4, 1, 2}, {12, 1, 2}, {12, 8, 2}, {4, 8, 2}), 1));
    render::RenderSettings settings;
    settings.voxelResolution = 32;
    settings.view = render::DebugView::IndirectSpecular;
    settings.specularDivisor = divisor;
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(scene);
    m_gl.renderer->setGridBounds(test::box(glm::vec3(0.5f), glm::vec3(15.5f)));
    m_gl.renderer->renderFrame(m_camera, size, size);
    return m_gl.renderer->readFrame();
}

void SpecularConeTest::glossyFloorMirrorsEmitter()
{
    const render::RadianceImage image = renderSpecular(true);
    // The mirror ray from (8, 0.5, 6) meets the wall at (8, 2.25, 2): it sees the light. From (13, 0.5, 7)
    // it meets the wall's plane at x = 16.6, well beside the light (x in [4, 12]), and sees nothing.
    const glm::ivec2 hit = test::pixelOf(m_camera, {8.0f, 0.5f, 6.0f}, kSize);
    const glm::ivec2 miss = test::pixelOf(m_camera, {13.0f, 0.5f, 7.0f}, kSize);
    for (const glm::ivec2& p : {hit, miss})
        QVERIFY(p.x >= 0 && p.y >= 0 && p.x < kSize && p.y < kSize);
    const float lit = image.at(hit.x, hit.y).r, dark = image.at(miss.x, miss.y).r;
    qInfo("specular term where the mirror sees the light %.3f, where it does not %.3f", lit, dark);
    // At most Ks * Ke = 2.5, and a clear share of it where the cone meets the emitter head-on.
    QVERIFY2(lit > 0.5f && lit <= 2.5f * 1.05f, qPrintable(QString::number(lit)));
    QVERIFY2(dark < 0.1f * lit, qPrintable(QString::number(dark)));
    QVERIFY(m_gl.renderer->takeGlErrors().empty());
}

void SpecularConeTest::matteFloorHasNoSpecularTerm()
{
    const render::RadianceImage image = renderSpecular(false);
    for (const glm::vec3& p : image.pixels)
        QCOMPARE(p, glm::vec3(0.0f));
}

// The specular cone is traced on its own coarser grid (specular_res, 8 by default) and upsampled. Reflections
// blur anyway (the cone is never narrower than 15 degrees), so the image stays close to tracing every pixel,
// except along an edge that the reflection itself draws sharply: here the emitter's lower edge seen in the
// floor right in front of it, a row the upsampling smears over a few pixels at any reduced resolution.
void SpecularConeTest::reducedResolutionStaysCloseToFull()
{
    constexpr int kLarge = 96;
    const render::RadianceImage full = renderSpecular(true, 1, kLarge);
    float brightest = 0.0f;
    double fullSum = 0.0;
    for (const glm::vec3& p : full.pixels) {
        brightest = std::max(brightest, p.r);
        fullSum += p.r;
    }
    QVERIFY(brightest > 0.5f);
    for (const int divisor : {2, 4, 8}) {
        const render::RadianceImage reduced = renderSpecular(true, divisor, kLarge);
        double reducedSum = 0.0, absoluteError = 0.0;
        std::size_t far = 0;
        for (std::size_t i = 0; i < full.pixels.size(); ++i) {
            const float difference = std::abs(reduced.pixels[i].r - full.pixels[i].r);
            reducedSum += reduced.pixels[i].r;
            absoluteError += difference;
            far += difference > 0.25f * brightest ? 1 : 0;
        }
        const double meanRatio = reducedSum / fullSum, meanError = absoluteError / fullSum;
        const double farShare = double(far) / double(full.pixels.size());
        qInfo("specular at 1/%d resolution: mean %.3f of every pixel traced, mean error %.3f of the mean, %.2f%% of "
              "pixels off by more than a quarter of the brightest reflection",
            divisor, meanRatio, meanError, 100.0 * farShare);
        QVERIFY2(std::abs(meanRatio - 1.0) < 0.08, qPrintable(QString::number(meanRatio)));
        QVERIFY2(meanError < 0.2, qPrintable(QString::number(meanError)));
        QVERIFY2(farShare < 0.02, qPrintable(QString::number(farShare)));
    }
    QVERIFY(m_gl.renderer->takeGlErrors().empty());
}

QTEST_GUILESS_MAIN(SpecularConeTest)
#include "tst_SpecularCone.moc"
