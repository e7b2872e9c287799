#include "GlTestContext.h"

#include "debug/TrilinearRateProbe.h"

#include <QtTest>

#include <cmath>

using namespace vct;

/** The peak-rate probe of vct-bench perf: it times the whole draw, so its cost grows with the pixels. */
class TrilinearRateProbeTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void reportsWhatItDrew();
    void timeGrowsWithPixels();

private:
    test::GlTestContext m_gl;
};

void TrilinearRateProbeTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
}

void TrilinearRateProbeTest::reportsWhatItDrew()
{
    render::TrilinearRateProbe probe;
    const render::TrilinearRate rate = probe.measure(40, 24, 16, 3, 2, 5);
    QCOMPARE(rate.width, 40);
    QCOMPARE(rate.height, 24);
    QCOMPARE(rate.volumeSize, 16);
    QCOMPARE(rate.samplesPerPixel, 10);
    QCOMPARE(rate.samplesPerDraw, std::uint64_t(40 * 24 * 10));
    QVERIFY(rate.medianMs > 0.0);
    QVERIFY(std::isfinite(rate.samplesPerSecond) && rate.samplesPerSecond > 0.0);
    QVERIFY(m_gl.renderer->takeGlErrors().empty());
}

void TrilinearRateProbeTest::timeGrowsWithPixels()
{
    // llvmpipe stamps time per 64x64 tile: a start stamp batched with the draw times one tile only, and 16
    // times the pixels would then cost about the same. Timed right, it costs several times more.
    render::TrilinearRateProbe probe;
    const render::TrilinearRate small = probe.measure(64, 64, 32);
    const render::TrilinearRate large = probe.measure(256, 256, 32);
    qInfo("64x64: %.2f ms, 256x256: %.2f ms (%.0f and %.0f Msamples/s)", small.medianMs, large.medianMs,
        small.samplesPerSecond * 1e-6, large.samplesPerSecond * 1e-6);
    QVERIFY2(
        large.medianMs > 4.0 * small.medianMs, qPrintable(QString::number(large.medianMs / small.medianMs)));
    QVERIFY(m_gl.renderer->takeGlErrors().empty());
}

QTEST_GUILESS_MAIN(TrilinearRateProbeTest)
#include "tst_TrilinearRateProbe.moc"
