#include "GlTestContext.h"
#include "TestSupport.h"

#include "core/ConeMath.h"

#include <QtTest>

#include <cmath>

using namespace vct;

/**
 * The cone pass's COUNT_SAMPLES variant (vct-bench perf): it counts exactly the fetches the cone loop makes,
 * and counting does not change the image. A camera looking straight down at a floor, one diffuse cone per
 * pixel and a cone length shorter than the distance to any wall make the count known in advance: every
 * traced pixel takes the same steps, computed here with the shader's own cone arithmetic.
 */
class ConeSampleCountTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void countMatchesTheConeLoop_data();
    void countMatchesTheConeLoop();

private:
    test::GlTestContext m_gl;
    static constexpr int kSize = 32;
};

void ConeSampleCountTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
}

void ConeSampleCountTest::countMatchesTheConeLoop_data()
{
    QTest::addColumn<bool>("anisotropic");
    QTest::newRow("box mips") << false;
    QTest::newRow("anisotropic mips") << true;
}

void ConeSampleCountTest::countMatchesTheConeLoop()
{
    QFETCH(bool, anisotropic);
    render::Renderer& renderer = *m_gl.renderer;
    render::Scene scene;
    scene.materials.push_back(render::Material {});
    scene.meshes.push_back(
        test::makeTriangles(test::quad({ -8, 0, 8 }, { 8, 0, 8 }, { 8, 0, -8 }, { -8, 0, -8 }), 0));
    render::PointLight light;
    light.position = { 0.0f, 4.0f, 0.0f };
    scene.pointLights.push_back(light);
    const render::Camera camera { { 0.0f, 6.0f, 0.0f }, { 0.0f, 0.0f, 0.0f }, { 0.0f, 0.0f, -1.0f }, 40.0f,
        0.01f };
    render::RenderSettings settings;
    settings.irradianceCache = false; // every traced pixel runs the cone loop this test counts
    settings.voxelResolution = 32;
    settings.diffuseConeCount = 1;
    settings.indirectSpecular = false;
    settings.anisotropicMips = anisotropic;
    settings.indirectDivisor = 2;
    renderer.setSettings(settings);
    renderer.setScene(scene);
    renderer.setGridBounds(test::box({ -8.0f, -1.0f, -8.0f }, { 8.0f, 7.0f, 8.0f }));
    renderer.renderFrame(camera, kSize, kSize);

    // The cone loop of shaders/common/ConeTracing.glsl without its exits on opacity and on leaving the grid,
    // which this scene never reaches: the cone length ends it.
    const float voxel = renderer.voxelSize();
    const float tanHalf = std::tan(glm::radians(settings.diffuseApertureDeg * 0.5f));
    std::vector<float> t { voxel };
    for (int i = 0; i < 8; ++i) {
        const float d = render::conemath::coneDiameter(t.back(), tanHalf);
        t.push_back(t.back() + render::conemath::coneStepLength(d, voxel, settings.stepFactor));
    }
    const int steps = 7; // enough to reach footprints over two voxels
    // The cone (straight up from the floor at y = 0) must end by its length: its last sample inside the grid.
    const float gridTop = renderer.gridOrigin().y + voxel * float(renderer.voxelResolution());
    QVERIFY2(settings.coneOffsetVoxels * voxel + t[steps - 1] < gridTop - voxel,
        qPrintable(QString::number(gridTop)));
    settings.maxDistance = 0.5f * (t[steps - 1] + t[steps]); // halfway, so float rounding cannot add a step
    // Box-filtered mips take one fetch a step. Anisotropic ones take what the step's footprint needs
    // (shaders/common/ConeTracing.glsl, the march's phases): level 0 alone within a voxel, level 0 and the
    // three chains the direction weighs between one and two voxels, the three chains alone beyond. The cone
    // points along the normal, so its clearance (the footprint's cap near the surface) is the offset plus t,
    // over 1.5.
    std::uint64_t fetchesPerPixel = 0;
    int phasesSeen = 0;
    for (int i = 0; i < steps; ++i) {
        const float footprint = std::min(render::conemath::coneDiameter(t[std::size_t(i)], tanHalf),
            std::max((settings.coneOffsetVoxels * voxel + t[std::size_t(i)]) / 1.5f, voxel));
        const float level = render::conemath::coneMipLevel(footprint, voxel, 16.0f);
        const int fetches = !anisotropic ? 1 : level <= 0.0f ? 1 : level < 1.0f ? 4 : 3;
        phasesSeen |= 1 << fetches;
        fetchesPerPixel += std::uint64_t(fetches);
    }
    // The scene is made so that the count covers every phase the loop has.
    QCOMPARE(phasesSeen, anisotropic ? (1 << 1) | (1 << 4) | (1 << 3) : 1 << 1);
    renderer.setSettings(settings);

    renderer.renderFrame(camera, kSize, kSize);
    QCOMPARE(renderer.coneSampleCount(), std::uint64_t(0)); // not counting
    const render::RadianceImage plain = renderer.readFrame();

    renderer.setConeSampleCounting(true);
    renderer.renderFrame(camera, kSize, kSize);
    const std::uint64_t counted = renderer.coneSampleCount();
    const render::RadianceImage whileCounting = renderer.readFrame();
    renderer.setConeSampleCounting(false);

    const int traced = kSize / settings.indirectDivisor;
    const std::uint64_t expected = std::uint64_t(traced * traced) * fetchesPerPixel;
    qInfo("%llu fetches counted, %llu expected (%d traced pixels x %llu)", (unsigned long long)counted,
        (unsigned long long)expected, traced * traced, (unsigned long long)fetchesPerPixel);
    QCOMPARE(counted, expected);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            QVERIFY2(plain.at(x, y) == whileCounting.at(x, y),
                qPrintable(QStringLiteral("pixel %1, %2").arg(x).arg(y)));
    renderer.renderFrame(camera, kSize, kSize);
    QCOMPARE(renderer.coneSampleCount(), std::uint64_t(0));
    QVERIFY(renderer.takeGlErrors().empty());
}

QTEST_GUILESS_MAIN(ConeSampleCountTest)
#include "tst_ConeSampleCount.moc"
