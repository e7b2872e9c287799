#include "GlTestContext.h"
#include "TestSupport.h"

#include "document/SceneLoader.h"
#include "imageio/ImageFile.h"
#include "imageio/ImageMetrics.h"

#include <QtTest>

#include <cmath>

using namespace vct;

/**
 * Whole-image checks at 64x64. The golden is re-blessed only through scripts/bless-goldens (VCT_BLESS=1);
 * on a mismatch the actual image and an error heatmap are written to the test output folder.
 */
class CornellImageTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cornellIsFiniteAndMatchesGolden();
    void floorNextToRedWallIsRedder();
    void referenceRelativeMse_data();
    void referenceRelativeMse();
    void gatheredLightIsSmoothAcrossAnAskewFace();

private:
    render::RadianceImage renderScene(const QString& spec, int width, int height, int voxelResolution);
    render::RadianceImage renderReferenceScene(const QString& name, const render::RenderSettings& settings);
    test::GlTestContext m_gl;
};

void CornellImageTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
}

render::RadianceImage CornellImageTest::renderScene(
    const QString& spec, int width, int height, int voxelResolution)
{
    render::Scene scene;
    QString error;
    if (!doc::SceneLoader::load(spec, scene, &error))
        qFatal("cannot load %s: %s", qPrintable(spec), qPrintable(error));
    render::RenderSettings settings;
    settings.voxelResolution = voxelResolution;
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(scene);
    m_gl.renderer->renderFrame(scene.camera, width, height);
    const auto errors = m_gl.renderer->takeGlErrors();
    if (!errors.empty())
        qFatal("GL error rendering %s: %s", qPrintable(spec), errors.front().c_str());
    return m_gl.renderer->readFrame();
}

// The path a user takes: the model file through the importer with its camera and lights files, at the
// reference's own size.
render::RadianceImage CornellImageTest::renderReferenceScene(
    const QString& name, const render::RenderSettings& settings)
{
    const QString model = test::referenceDir() + QLatin1Char('/') + name + QStringLiteral(".obj");
    if (!QFile::exists(model))
        qFatal("missing reference scene %s (tests/data/reference)", qPrintable(model));
    doc::SceneLoadInfo info;
    render::Scene scene;
    QString error;
    if (!doc::SceneLoader::load(model, scene, &error, &info))
        qFatal("cannot load %s: %s", qPrintable(model), qPrintable(error));
    if (!info.hasCameraFile)
        qFatal("%s has no camera file beside it", qPrintable(model));
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(scene);
    m_gl.renderer->renderFrame(scene.camera, info.width, info.height);
    return m_gl.renderer->readFrame();
}

void CornellImageTest::cornellIsFiniteAndMatchesGolden()
{
    const render::RadianceImage image = renderScene(QStringLiteral("builtin:cornell"), 64, 64, 64);
    QCOMPARE(io::ImageMetrics::nonFiniteCount(image), std::size_t(0));
    const std::string golden
        = (test::sourceDir() + QStringLiteral("/tests/golden/cornell_64.pfm")).toStdString();
    if (qEnvironmentVariableIsSet("VCT_BLESS")) {
        std::string error;
        QVERIFY2(io::ImageFile::write(golden, image, 1.0f, &error), error.c_str());
        qInfo("blessed %s", golden.c_str());
        return;
    }
    std::string error;
    const auto expected = io::ImageFile::read(golden, &error);
    QVERIFY2(expected, error.c_str());
    QCOMPARE(expected->width, image.width);
    QCOMPARE(expected->height, image.height);
    // Float atomics add voxel fragments in a varying order, so voxels differ in the last bits run to run.
    // Tolerance: per channel |a - b| <= 0.01 + 2% of b on at least 99.5% of pixels, and no pixel off by more
    // than 0.1 + 10%.
    int outliers = 0;
    double worst = 0.0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double a = image.pixels[i][c], b = expected->pixels[i][c];
            const double excess = std::abs(a - b) - (0.01 + 0.02 * std::abs(b));
            outliers += excess > 0.0 ? 1 : 0;
            worst = std::max(worst, std::abs(a - b) - (0.1 + 0.1 * std::abs(b)));
        }
    const bool ok = outliers <= int(0.005 * double(image.pixels.size())) && worst <= 0.0;
    if (!ok) {
        const std::string out = test::outputDir().toStdString();
        io::ImageFile::write(out + "/cornell_64.actual.pfm", image);
        io::ImageFile::write(out + "/cornell_64.diff.png", io::ImageMetrics::errorHeatmap(image, *expected),
            io::ToneMapper(1.0f, io::ToneMapper::Curve::Clamp));
    }
    QVERIFY2(ok,
        qPrintable(QString("%1 channel values outside tolerance; worst excess %2; see %3")
                       .arg(outliers)
                       .arg(worst)
                       .arg(test::outputDir())));
}

// The box lit by a point light (the emitter version puts a blue emissive block on the left floor, which
// would swamp the effect): light bouncing off the red wall must tint the floor beside it.
void CornellImageTest::floorNextToRedWallIsRedder()
{
    const render::RadianceImage image = renderScene(QStringLiteral("builtin:cornell_point"), 64, 64, 64);
    QCOMPARE(io::ImageMetrics::nonFiniteCount(image), std::size_t(0));
    auto mean = [&](int x0, int x1, int y0, int y1) {
        glm::dvec3 sum(0.0);
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x)
                sum += glm::dvec3(image.at(x, y));
        return sum / double((x1 - x0) * (y1 - y0));
    };
    const glm::dvec3 nearRed = mean(6, 11, 54, 60); // floor, front left, beside the red wall
    const glm::dvec3 nearGreen = mean(53, 58, 54, 60); // the mirror-image patch beside the green wall
    const double redness = nearRed.r / nearRed.g, greenRedness = nearGreen.r / nearGreen.g;
    qInfo("floor r/g beside red wall %.3f, beside green wall %.3f", redness, greenRedness);
    QVERIFY(nearRed.g > 0.0 && nearGreen.g > 0.0);
    QVERIFY2(redness > 1.2 * greenRedness, qPrintable(QString("%1 vs %2").arg(redness).arg(greenRedness)));
}

void CornellImageTest::referenceRelativeMse_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<double>("bound");
    // The light-transport targets (docs/ACCURACY.md): the box lit by its emitters within relative MSE 0.05,
    // the point-lit box within 0.03 (it measures 0.0273 since 2026-12-04; the bound was 0.04 while it read
    // 0.033).
    QTest::newRow("cornell") << QStringLiteral("cornell") << 0.05;
    QTest::newRow("cornell_point") << QStringLiteral("cornell_point") << 0.03;
}

// The default settings against Cycles at 1024 spp. Both the relative MSE and the mean (a robust measure the
// few brightest pixels cannot rule) must hold.
void CornellImageTest::referenceRelativeMse()
{
    QFETCH(QString, name);
    QFETCH(double, bound);
    const render::RadianceImage image = renderReferenceScene(name, render::RenderSettings {});
    std::string readError;
    const auto reference = io::ImageFile::read(
        (test::referenceDir() + QLatin1Char('/') + name + QStringLiteral("_1024spp.pfm")).toStdString(),
        &readError);
    QVERIFY2(reference, readError.c_str());
    const double relMse = io::ImageMetrics::relativeMse(image, *reference);
    const double meanRatio
        = io::ImageMetrics::meanLuminance(image) / io::ImageMetrics::meanLuminance(*reference);
    const glm::vec3 mean = io::ImageMetrics::meanRadiance(image),
                    refMean = io::ImageMetrics::meanRadiance(*reference);
    qInfo("%s: relative MSE %.4f (bound %.2f), mean luminance %.3f of the reference; mean radiance %.4f %.4f "
          "%.4f vs "
          "%.4f %.4f %.4f",
        qPrintable(name), relMse, bound, meanRatio, mean.r, mean.g, mean.b, refMean.r, refMean.g, refMean.b);
    QVERIFY(std::isfinite(relMse));
    QVERIFY2(relMse <= bound, qPrintable(QString::number(relMse)));
    QVERIFY2(std::abs(meanRatio - 1.0) <= 0.05, qPrintable(QString::number(meanRatio)));
}

// The short box of the point-lit Cornell box stands askew to the voxel grid, and its front face, in the point
// light's shade, shows gathered light only. Where a cone's last sample before the grid's face fell just
// inside or just past it, the light gathered across that face jumped by a third between neighbouring pixels
// (0.115 to 0.072 at 512 pixels), where the path tracer's falls smoothly from left to right. Measured as the
// largest second difference along rows of the face, over the row's mean: 0.017-0.061 with that edge,
// 0.003-0.006 once it was gone, 0.010 since oblique cones multiply their chains' transmittances. And the
// face's top rows against those just below.
void CornellImageTest::gatheredLightIsSmoothAcrossAnAskewFace()
{
    render::RenderSettings settings;
    settings.view = render::DebugView::IndirectDiffuse;
    const render::RadianceImage image = renderReferenceScene(QStringLiteral("cornell_point"), settings);
    QCOMPARE(image.width, 256);
    QCOMPARE(io::ImageMetrics::nonFiniteCount(image), std::size_t(0));
    const int firstX = 132, lastX = 180; // inside the face's left and right edges on rows 180-204
    double worst = 0.0;
    for (int y = 180; y <= 204; y += 4) {
        const auto at = [&](int x) {
            const glm::vec3 p = image.at(x, y);
            return double(p.r + p.g + p.b) / 3.0;
        };
        double mean = 0.0;
        for (int x = firstX; x <= lastX; ++x)
            mean += at(x);
        mean /= double(lastX - firstX + 1);
        QVERIFY2(mean > 0.005, qPrintable(QStringLiteral("row %1 of the face gathers nothing").arg(y)));
        for (int x = firstX + 1; x < lastX; ++x)
            worst = std::max(worst, std::abs(at(x + 1) - 2.0 * at(x) + at(x - 1)) / mean);
    }
    qInfo("largest second difference across the short box's face: %.4f of the row's mean", worst);
    QVERIFY2(worst < 0.015, qPrintable(QString::number(worst)));

    // Just under the face's top edge (rows 174-176), as a few rows lower (178-180): cells on the edge hold
    // both faces, and while they passed for either face with their normal between the two, a row of blobs
    // along the edge read twice the light below it (2.06 of it; 0.95 since a cell's normal is its voxels'
    // mean).
    const auto rowsMean = [&](int firstY, int lastY) {
        double sum = 0.0;
        for (int y = firstY; y <= lastY; ++y)
            for (int x = firstX; x <= lastX; ++x) {
                const glm::vec3 p = image.at(x, y);
                sum += double(p.r + p.g + p.b) / 3.0;
            }
        return sum / double((lastY - firstY + 1) * (lastX - firstX + 1));
    };
    const double edgeRatio = rowsMean(174, 176) / rowsMean(178, 180);
    qInfo("light just under the short box's top edge: %.3f of a few rows lower", edgeRatio);
    QVERIFY2(edgeRatio > 0.8 && edgeRatio < 1.2, qPrintable(QString::number(edgeRatio)));
}

QTEST_GUILESS_MAIN(CornellImageTest)
#include "tst_CornellImage.moc"
