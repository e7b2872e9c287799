#include "GlTestContext.h"
#include "TestSupport.h"

#include "scene/PhongLobe.h"

#include <QtTest>

using namespace vct;

namespace {

/** A black floor, glossy or matte, and a wall of light at z = 2 facing the camera (+z). */
render::Scene floorAndLight(bool glossy, float shininess = 200.0f)
{
    render::Scene scene;
    render::Material floor;
    floor.albedo = glm::vec3(0.0f);
    floor.specular = glm::vec3(glossy ? 0.5f : 0.0f);
    floor.shininess = glossy ? shininess : 0.0f;
    render::Material emitter;
    emitter.albedo = glm::vec3(0.0f);
    emitter.emission = glm::vec3(5.0f);
    scene.materials = { floor, emitter };
    scene.meshes.push_back(test::makeTriangles(
        test::quad({ 1, 0.5f, 15 }, { 15, 0.5f, 15 }, { 15, 0.5f, 1 }, { 1, 0.5f, 1 }), 0));
    scene.meshes.push_back(
        test::makeTriangles(test::quad({ 4, 1, 2 }, { 12, 1, 2 }, { 12, 8, 2 }, { 4, 8, 2 }), 1));
    return scene;
}

/**
 * Radiance the glossy floor of floorAndLight reflects at floor point @p p toward @p eye from its wall of
 * light, by brute force: the lobe (scene/PhongLobe, in the frame of the floor and the viewer) summed over a
 * fine grid of the light's area, independent of the fitted cosines the renderer integrates.
 */
double glossyFloorRadiance(const glm::dvec3& p, const glm::dvec3& eye, double shininess)
{
    const glm::dvec3 normal { 0, 1, 0 };
    const glm::dvec3 toEye = glm::normalize(eye - p);
    const double cosView = glm::dot(toEye, normal);
    const glm::dvec3 tangent = glm::normalize(toEye - normal * cosView);
    const glm::dvec3 across = glm::cross(normal, tangent);
    const render::PhongLobe lobe(cosView, shininess);
    constexpr int kColumns = 1600, kRows = 1400; // 5 mm cells over the 8 x 7 m light
    const double cellArea = (8.0 / kColumns) * (7.0 / kRows);
    double sum = 0.0;
    for (int i = 0; i < kColumns; ++i)
        for (int j = 0; j < kRows; ++j) {
            const glm::dvec3 onLight { 4.0 + 8.0 * (i + 0.5) / kColumns, 1.0 + 7.0 * (j + 0.5) / kRows, 2.0 };
            const glm::dvec3 d = onLight - p;
            const double distance2 = glm::dot(d, d);
            const glm::dvec3 w = d / std::sqrt(distance2);
            const glm::dvec3 local { glm::dot(w, tangent), glm::dot(w, across), glm::dot(w, normal) };
            sum += lobe.value(local) * std::abs(w.z) / distance2 * cellArea; // the light faces +z
        }
    return 0.5 * 5.0 * sum; // Ks * L
}

} // namespace

/** The specular cone: glossy surfaces reflect what lies along the mirror direction, others get none. */
class SpecularConeTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void glossyFloorMirrorsEmitter();
    void matteFloorHasNoSpecularTerm();
    void reducedResolutionStaysCloseToFull();
    void glossyFloorReflectsAreaLight();
    void glossyLobeOfAreaLightMatchesQuadrature_data();
    void glossyLobeOfAreaLightMatchesQuadrature();

private:
    render::RadianceImage renderSpecular(bool glossy, int divisor = 8, int size = kSize);
    test::GlTestContext m_gl;
    const render::Camera m_camera { { 8.0f, 4.0f, 14.0f }, { 8.0f, 0.5f, 6.0f }, { 0, 1, 0 }, 70.0f, 0.01f };
    static constexpr int kSize = 48;
};

void SpecularConeTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
}

render::RadianceImage SpecularConeTest::renderSpecular(bool glossy, int divisor, int size)
{
    const render::Scene scene = floorAndLight(glossy);
    render::RenderSettings settings;
    settings.voxelResolution = 32;
    settings.view = render::DebugView::IndirectSpecular;
    settings.specularDivisor = divisor;
    // With direct light on, the emitter would light the floor as an area light, and its reflection would be
    // part of the direct term (glossyFloorReflectsAreaLight); off, its light is in the voxels for the cone.
    settings.direct = false;
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
    const glm::ivec2 hit = test::pixelOf(m_camera, { 8.0f, 0.5f, 6.0f }, kSize);
    const glm::ivec2 miss = test::pixelOf(m_camera, { 13.0f, 0.5f, 7.0f }, kSize);
    for (const glm::ivec2& p : { hit, miss })
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
    for (const int divisor : { 2, 4, 8 }) {
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
        qInfo("specular at 1/%d resolution: mean %.3f of every pixel traced, mean error %.3f of the mean, "
              "%.2f%% of "
              "pixels off by more than a quarter of the brightest reflection",
            divisor, meanRatio, meanError, 100.0 * farShare);
        QVERIFY2(std::abs(meanRatio - 1.0) < 0.08, qPrintable(QString::number(meanRatio)));
        QVERIFY2(meanError < 0.2, qPrintable(QString::number(meanError)));
        QVERIFY2(farShare < 0.02, qPrintable(QString::number(farShare)));
    }
    QVERIFY(m_gl.renderer->takeGlErrors().empty());
}

// With direct light on, the emitter is an area light: its reflection on the glossy floor comes with the
// direct term, and where the mirror ray meets the light it is close to Ks * Ke * cos(theta) (the lobe lies
// inside the light), while beside the light it is dark. The specular cone no longer sees the emitter, so it
// is not counted twice.
void SpecularConeTest::glossyFloorReflectsAreaLight()
{
    const render::Scene scene = floorAndLight(true);
    render::RenderSettings settings;
    settings.voxelResolution = 32;
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(scene);
    m_gl.renderer->setGridBounds(test::box(glm::vec3(0.5f), glm::vec3(15.5f)));
    const glm::ivec2 hit = test::pixelOf(m_camera, { 8.0f, 0.5f, 6.0f }, kSize);
    const glm::ivec2 miss = test::pixelOf(m_camera, { 13.0f, 0.5f, 7.0f }, kSize);
    for (const render::DebugView view : { render::DebugView::Direct, render::DebugView::IndirectSpecular }) {
        settings.view = view;
        m_gl.renderer->setSettings(settings);
        m_gl.renderer->renderFrame(m_camera, kSize, kSize);
        const render::RadianceImage image = m_gl.renderer->readFrame();
        const float lit = image.at(hit.x, hit.y).r, dark = image.at(miss.x, miss.y).r;
        qInfo("%s where the mirror sees the light %.3f, where it does not %.3f",
            view == render::DebugView::Direct ? "direct" : "specular cone", lit, dark);
        if (view == render::DebugView::Direct) {
            // The mirror direction from (8, 0.5, 6) to (8, 2.25, 2): cos(theta) = 1.75 / |(0, 1.75, -4)|.
            const float expected = 0.5f * 5.0f * 1.75f / std::sqrt(1.75f * 1.75f + 16.0f);
            QVERIFY2(std::abs(lit - expected) <= 0.1f * expected,
                qPrintable(QString("%1, expected %2").arg(lit).arg(expected)));
            QVERIFY2(dark < 0.1f * lit, qPrintable(QString::number(dark)));
        } else {
            QVERIFY2(lit < 0.05f, qPrintable(QString::number(lit))); // not seen a second time
        }
    }
    QVERIFY(m_gl.renderer->takeGlErrors().empty());
}

void SpecularConeTest::glossyLobeOfAreaLightMatchesQuadrature_data()
{
    QTest::addColumn<float>("shininess");
    QTest::newRow("shininess 20") << 20.0f;
    QTest::newRow("shininess 200") << 200.0f;
    QTest::newRow("shininess 2000") << 2000.0f;
}

// The glossy lobe's light from an area light is the fitted cosines' exact integral over the light (Heitz et
// al. 2016; scene/PhongLtcFitter): at floor points whose mirror ray meets the light, beside it and near its
// edge, the direct term (the floor's albedo is 0, so it is all lobe) against brute-force quadrature of the
// lobe itself.
void SpecularConeTest::glossyLobeOfAreaLightMatchesQuadrature()
{
    QFETCH(float, shininess);
    render::RenderSettings settings;
    settings.voxelResolution = 32;
    settings.view = render::DebugView::Direct;
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(floorAndLight(true, shininess));
    m_gl.renderer->setGridBounds(test::box(glm::vec3(0.5f), glm::vec3(15.5f)));
    m_gl.renderer->renderFrame(m_camera, kSize, kSize);
    const render::RadianceImage image = m_gl.renderer->readFrame();
    for (const glm::vec3 target : { glm::vec3(8, 0.5f, 6), glm::vec3(6, 0.5f, 9), glm::vec3(11.5f, 0.5f, 5),
             glm::vec3(12.5f, 0.5f, 7), glm::vec3(9, 0.5f, 10) }) {
        const glm::ivec2 pixel = test::pixelOf(m_camera, target, kSize);
        QVERIFY(pixel.x >= 0 && pixel.y >= 0 && pixel.x < kSize && pixel.y < kSize);
        const glm::vec3 p = test::floorPointOf(m_camera, pixel, kSize, 0.5f);
        const double expected = glossyFloorRadiance(p, m_camera.position, shininess);
        const double rendered = image.at(pixel.x, pixel.y).r;
        qInfo("shininess %.0f at (%.2f, %.2f): rendered %.4f, quadrature %.4f", shininess, p.x, p.z, rendered,
            expected);
        // Within 10% where the lobe meets the light; beside it, the fitted cosines' tails (heavier than
        // cos^n's) leave a faint halo, held below 1% of the lobe's peak, Ks * L = 2.5.
        QVERIFY2(std::abs(rendered - expected) <= 0.1 * expected + 0.025,
            qPrintable(QString("%1 against %2").arg(rendered).arg(expected)));
    }
    QVERIFY(m_gl.renderer->takeGlErrors().empty());
}

QTEST_GUILESS_MAIN(SpecularConeTest)
#include "tst_SpecularCone.moc"
