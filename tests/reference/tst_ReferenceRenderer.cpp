#include "TestSupport.h"

#include "document/SceneLoader.h"
#include "reference/ReferenceRenderer.h"

#include <QtTest>

#include <chrono>
#include <cstring>
#include <stop_token>

using namespace vct;

/**
 * How the reference renderer runs rather than what it computes: reproducible images whatever the threads,
 * progressive passes that continue the sample sequence, progress reports and cancellation.
 */
class ReferenceRendererTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void sameSeedSameImageOnAnyThreadCount();
    void passesAccumulate();
    void progressReachesOne();
    void cancellationStopsEarly();

private:
    render::RadianceImage render(std::uint64_t seed, int threads, int tileSize, int spp) const;

    render::Scene m_scene;
};

namespace {

constexpr int kSize = 48;

bool identical(const render::RadianceImage& a, const render::RadianceImage& b)
{
    return a.width == b.width && a.height == b.height
        && std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)) == 0;
}

double maxRelativeDifference(const render::RadianceImage& a, const render::RadianceImage& b)
{
    double worst = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst,
                std::abs(double(a.pixels[i][c]) - double(b.pixels[i][c]))
                    / std::max(1e-3, double(b.pixels[i][c])));
    return worst;
}

} // namespace

void ReferenceRendererTest::initTestCase()
{
    QString error;
    QVERIFY2(doc::SceneLoader::load(QStringLiteral("builtin:cornell"), m_scene, &error), qPrintable(error));
}

render::RadianceImage ReferenceRendererTest::render(
    std::uint64_t seed, int threads, int tileSize, int spp) const
{
    render::ReferenceSettings settings;
    settings.seed = seed;
    settings.threads = threads;
    settings.tileSize = tileSize;
    render::ReferenceRenderer renderer(m_scene, m_scene.camera, kSize, kSize, settings);
    renderer.render(spp);
    return renderer.image();
}

void ReferenceRendererTest::sameSeedSameImageOnAnyThreadCount()
{
    const render::RadianceImage one = render(7, 1, 16, 4);
    QVERIFY(identical(one, render(7, 2, 16, 4)));
    // Three threads on small tiles finish tiles in yet another order.
    QVERIFY(identical(one, render(7, 3, 5, 4)));
    QVERIFY(!identical(one, render(8, 2, 16, 4)));
}

// A second pass draws new samples: two passes of 4 equal one pass of 8 (up to summation order), not one of 4.
void ReferenceRendererTest::passesAccumulate()
{
    render::ReferenceSettings settings;
    settings.seed = 3;
    render::ReferenceRenderer renderer(m_scene, m_scene.camera, kSize, kSize, settings);
    QCOMPARE(renderer.samplesPerPixel(), 0);
    QVERIFY(renderer.render(4));
    const render::RadianceImage first = renderer.image();
    QVERIFY(renderer.render(4));
    QCOMPARE(renderer.samplesPerPixel(), 8);
    QCOMPARE(renderer.stats().samples, std::uint64_t(8 * kSize * kSize));
    const render::RadianceImage both = renderer.image();
    const render::RadianceImage once = render(3, 2, 16, 8);
    QVERIFY2(maxRelativeDifference(both, once) < 1e-5,
        qPrintable(QString::number(maxRelativeDifference(both, once))));
    QVERIFY(maxRelativeDifference(both, first) > 0.1);
}

void ReferenceRendererTest::progressReachesOne()
{
    render::ReferenceSettings settings;
    settings.threads = 2;
    settings.tileSize = 8;
    render::ReferenceRenderer renderer(m_scene, m_scene.camera, kSize, kSize, settings);
    std::vector<double> reported;
    QVERIFY(renderer.render(2, [&](double fraction) { reported.push_back(fraction); }));
    QCOMPARE(int(reported.size()), (kSize / 8) * (kSize / 8)); // one report per tile
    QVERIFY(std::is_sorted(reported.begin(), reported.end()));
    QVERIFY(reported.front() > 0.0);
    QCOMPARE(reported.back(), 1.0);
}

// A stop request part-way drops the unfinished pass and returns long before the pass would have finished.
void ReferenceRendererTest::cancellationStopsEarly()
{
    render::ReferenceSettings settings;
    settings.threads = 2;
    settings.tileSize = 4;
    render::ReferenceRenderer renderer(m_scene, m_scene.camera, kSize, kSize, settings);
    QVERIFY(renderer.render(1));
    const render::RadianceImage before = renderer.image();

    // 144 tiles at 16384 spp take about a minute on two cores; stopping after the first tile about a second.
    std::stop_source stop;
    double lastFraction = 0.0;
    const auto start = std::chrono::steady_clock::now();
    const bool finished = renderer.render(
        16384,
        [&](double fraction) {
            lastFraction = fraction;
            stop.request_stop();
        },
        stop.get_token());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    qInfo("stopped after %.2f s at %.0f%% of the pass", seconds, 100.0 * lastFraction);
    QVERIFY(!finished);
    QVERIFY(lastFraction < 0.2);
    QVERIFY2(seconds < 10.0, qPrintable(QString::number(seconds)));
    QCOMPARE(renderer.samplesPerPixel(), 1);
    QVERIFY(identical(renderer.image(), before));

    // Asked to stop before it starts, it does no work at all.
    std::stop_source stopped;
    stopped.request_stop();
    QVERIFY(!renderer.render(16, {}, stopped.get_token()));
    QCOMPARE(renderer.samplesPerPixel(), 1);
}

QTEST_GUILESS_MAIN(ReferenceRendererTest)
#include "tst_ReferenceRenderer.moc"
