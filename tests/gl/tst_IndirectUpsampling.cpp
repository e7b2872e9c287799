#include "GlTestContext.h"
#include "TestSupport.h"

#include "document/SceneLoader.h"
#include "imageio/ImageMetrics.h"

#include <QtTest>

using namespace vct;

/** Indirect light traced at reduced resolution and upsampled stays close to tracing every pixel. */
class IndirectUpsamplingTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void reducedResolutionStaysCloseToFull();

private:
    render::RadianceImage renderWith(int divisor);
    test::GlTestContext m_gl;
    render::Scene m_scene;
};

void IndirectUpsamplingTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
    QString error;
    QVERIFY2(
        doc::SceneLoader::load(QStringLiteral("builtin:cornell_point"), m_scene, &error), qPrintable(error));
    m_gl.renderer->setScene(m_scene);
}

render::RadianceImage IndirectUpsamplingTest::renderWith(int divisor)
{
    render::RenderSettings settings;
    settings.voxelResolution = 64;
    settings.indirectDivisor = divisor;
    settings.view = render::DebugView::IndirectDiffuse; // the term the upsampling touches, alone
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->renderFrame(m_scene.camera, 128, 128);
    return m_gl.renderer->readFrame();
}

void IndirectUpsamplingTest::reducedResolutionStaysCloseToFull()
{
    const render::RadianceImage full = renderWith(1);
    QVERIFY(io::ImageMetrics::meanLuminance(full) > 0.0);
    for (int divisor : { 2, 4 }) {
        const render::RadianceImage reduced = renderWith(divisor);
        QCOMPARE(io::ImageMetrics::nonFiniteCount(reduced), std::size_t(0));
        const double error = io::ImageMetrics::relativeMse(reduced, full);
        qInfo("indirect diffuse at 1/%d resolution: relative MSE %.5f against every pixel traced", divisor,
            error);
        // Against the reference the whole renderer is off by ~0.2; the upsampling must add far less.
        QVERIFY2(error < 0.005 * divisor, qPrintable(QString::number(error)));
    }
    QVERIFY(m_gl.renderer->takeGlErrors().empty());
}

QTEST_GUILESS_MAIN(IndirectUpsamplingTest)
#include "tst_IndirectUpsampling.moc"
