#include "core/ConeMath.h"
#include "core/ConeSet.h"
#include "core/VoxelGridFrame.h"
#include "scene/RenderSettings.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <QtTest>

#include <cmath>

using namespace vct::render;

class ConeMathTest : public QObject {
    Q_OBJECT

private slots:
    void weightsSumToOne_data();
    void weightsSumToOne();
    void weightsMatchIndependentQuadrature_data();
    void weightsMatchIndependentQuadrature();
    void ringSetsIntegrateTheLobesMoments_data();
    void ringSetsIntegrateTheLobesMoments();
    void fiveConesAreNormalPlusFourAt50Degrees();
    void coneFootprintAndMipLevel();
    void stepLengthFollowsDiameter();
    void opacityCorrectionComposesOverSteps();
    void dominantAxisPicksLargestComponent();
    void gridFitContainsBoundsWithMargin();
    void gridFitSurvivesDegenerateBounds();
    void settingsParseAndReject();
};

void ConeMathTest::weightsSumToOne_data()
{
    QTest::addColumn<int>("count");
    for (int n : { 1, 3, 5, 9, 16, 32 })
        QTest::newRow(qPrintable(QString::number(n))) << n;
}

void ConeMathTest::weightsSumToOne()
{
    QFETCH(int, count);
    const ConeSet cones = ConeSet::diffuse(count);
    QCOMPARE(cones.size(), count);
    double sum = 0.0;
    for (int i = 0; i < count; ++i) {
        const glm::vec3 d = cones.directions()[std::size_t(i)];
        QVERIFY(std::abs(glm::length(d) - 1.0f) < 1e-5f);
        QVERIFY(d.z > 0.0f); // inside the hemisphere
        QVERIFY(cones.weights()[std::size_t(i)] > 0.0f);
        sum += cones.weights()[std::size_t(i)];
    }
    QVERIFY2(std::abs(sum - 1.0) < 1e-3, qPrintable(QString("sum %1").arg(sum)));
}

void ConeMathTest::weightsMatchIndependentQuadrature_data()
{
    QTest::addColumn<int>("count");
    for (int n : { 1, 2, 3, 16, 32 }) // the sets that split the lobe by region
        QTest::newRow(qPrintable(QString::number(n))) << n;
}

// Integrates cos(theta)/pi over each cone's region with a midpoint rule in (theta, phi), a different
// quadrature from the one ConeSet uses, so a mistake in either shows up.
void ConeMathTest::weightsMatchIndependentQuadrature()
{
    QFETCH(int, count);
    const ConeSet cones = ConeSet::diffuse(count);
    std::vector<double> integral(std::size_t(count), 0.0);
    const int nt = 600, np = 1200;
    const double dt = glm::half_pi<double>() / nt, dp = glm::two_pi<double>() / np;
    for (int i = 0; i < nt; ++i) {
        const double theta = (i + 0.5) * dt;
        for (int j = 0; j < np; ++j) {
            const double phi = (j + 0.5) * dp;
            const glm::vec3 w(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                float(std::cos(theta)));
            int best = 0;
            for (int c = 1; c < count; ++c)
                if (glm::dot(w, cones.directions()[std::size_t(c)])
                    > glm::dot(w, cones.directions()[std::size_t(best)]))
                    best = c;
            integral[std::size_t(best)] += std::cos(theta) * std::sin(theta) * dt * dp / glm::pi<double>();
        }
    }
    double total = 0.0;
    for (int c = 0; c < count; ++c) {
        total += integral[std::size_t(c)];
        QVERIFY2(std::abs(integral[std::size_t(c)] - cones.weights()[std::size_t(c)]) < 1e-3,
            qPrintable(QString("cone %1: %2 vs %3")
                           .arg(c)
                           .arg(integral[std::size_t(c)])
                           .arg(cones.weights()[std::size_t(c)])));
    }
    QVERIFY(std::abs(total - 1.0) < 1e-3); // the cosine lobe integrates to one
}

void ConeMathTest::ringSetsIntegrateTheLobesMoments_data()
{
    QTest::addColumn<int>("count");
    for (int n : { 4, 5, 7, 9 })
        QTest::newRow(qPrintable(QString::number(n))) << n;
}

// A normal and a ring of three or more weigh so that the estimate is exact for light constant over the
// hemisphere and for light varying as cos(theta): the weights sum to one and their mean cosine is the lobe's,
// (1/pi) * integral of cos^2(theta) = 2/3. Checked against a midpoint rule of that integral, not the closed
// form alone.
void ConeMathTest::ringSetsIntegrateTheLobesMoments()
{
    QFETCH(int, count);
    const ConeSet cones = ConeSet::diffuse(count);
    double lobeMeanCosine = 0.0;
    const int nt = 20000;
    const double dt = glm::half_pi<double>() / nt;
    for (int i = 0; i < nt; ++i) {
        const double theta = (i + 0.5) * dt;
        lobeMeanCosine += 2.0 * std::cos(theta) * std::cos(theta) * std::sin(theta) * dt;
    }
    double sum = 0.0, meanCosine = 0.0;
    for (int i = 0; i < count; ++i) {
        sum += cones.weights()[std::size_t(i)];
        meanCosine += cones.weights()[std::size_t(i)] * cones.directions()[std::size_t(i)].z;
    }
    QVERIFY2(std::abs(sum - 1.0) < 1e-5, qPrintable(QString::number(sum)));
    QVERIFY2(std::abs(meanCosine - lobeMeanCosine) < 1e-4,
        qPrintable(QString("%1 against %2").arg(meanCosine).arg(lobeMeanCosine)));
}

void ConeMathTest::fiveConesAreNormalPlusFourAt50Degrees()
{
    const ConeSet cones = ConeSet::diffuse(5);
    QCOMPARE(cones.directions()[0], glm::vec3(0, 0, 1));
    for (int i = 1; i < 5; ++i)
        QVERIFY(std::abs(std::acos(cones.directions()[std::size_t(i)].z) - glm::radians(50.0f)) < 1e-5f);
    // Symmetry: the four tilted cones weigh the same.
    for (int i = 2; i < 5; ++i)
        QVERIFY(std::abs(cones.weights()[std::size_t(i)] - cones.weights()[1]) < 1e-3f);
}

void ConeMathTest::coneFootprintAndMipLevel()
{
    using namespace conemath;
    const float tan30 = std::tan(glm::radians(30.0f));
    QVERIFY(std::abs(coneDiameter(3.0f, tan30) - 6.0f * tan30) < 1e-6f);
    const float voxel = 0.25f;
    QCOMPARE(coneMipLevel(0.1f, voxel, 7.0f), 0.0f); // below a voxel: finest level
    QCOMPARE(coneMipLevel(voxel, voxel, 7.0f), 0.0f);
    QVERIFY(std::abs(coneMipLevel(4.0f * voxel, voxel, 7.0f) - 2.0f) < 1e-6f);
    QVERIFY(std::abs(coneMipLevel(3.0f * voxel, voxel, 7.0f) - std::log2(3.0f)) < 1e-6f);
    QCOMPARE(coneMipLevel(1000.0f, voxel, 7.0f), 7.0f); // clamped to the coarsest level
}

void ConeMathTest::stepLengthFollowsDiameter()
{
    using namespace conemath;
    QVERIFY(std::abs(coneStepLength(2.0f, 0.5f, 0.5f) - 1.0f) < 1e-6f);
    QVERIFY(std::abs(coneStepLength(0.1f, 0.5f, 1.0f) - 0.5f) < 1e-6f); // never below a voxel
}

void ConeMathTest::opacityCorrectionComposesOverSteps()
{
    using namespace conemath;
    QVERIFY(std::abs(correctOpacity(0.3f, 1.0f, 1.0f) - 0.3f) < 1e-6f);
    // Two half steps must occlude exactly as much as one full step.
    const float half = correctOpacity(0.3f, 0.5f, 1.0f);
    QVERIFY(std::abs((1.0f - (1.0f - half) * (1.0f - half)) - 0.3f) < 1e-6f);
    QCOMPARE(correctOpacity(1.0f, 0.25f, 1.0f), 1.0f);
    QCOMPARE(correctOpacity(0.0f, 3.0f, 1.0f), 0.0f);
}

void ConeMathTest::dominantAxisPicksLargestComponent()
{
    using namespace conemath;
    QCOMPARE(dominantAxis(glm::vec3(0.9f, 0.1f, -0.2f)), 0);
    QCOMPARE(dominantAxis(glm::vec3(0.1f, -0.8f, 0.3f)), 1);
    QCOMPARE(dominantAxis(glm::vec3(0.1f, 0.2f, -0.95f)), 2);
    QCOMPARE(dominantAxis(glm::vec3(-3.0f, 1.0f, 2.0f)), 0);
}

void ConeMathTest::gridFitContainsBoundsWithMargin()
{
    Aabb bounds;
    bounds.extend(glm::vec3(-1.0f, 2.0f, 0.0f));
    bounds.extend(glm::vec3(3.0f, 3.0f, 1.0f));
    const VoxelGridFrame frame = VoxelGridFrame::fit(bounds, 64);
    QCOMPARE(frame.resolution, 64);
    QCOMPARE(frame.levelCount(), 7);
    // The largest extent (4) plus one cell each side.
    QVERIFY(std::abs(frame.extent - 4.0f - 2.0f * frame.voxelSize()) < 1e-4f);
    for (int axis = 0; axis < 3; ++axis) {
        QVERIFY(frame.origin[axis] + frame.voxelSize() <= bounds.min[axis] + 1e-4f);
        QVERIFY(frame.origin[axis] + frame.extent - frame.voxelSize() >= bounds.max[axis] - 1e-4f);
        QVERIFY(std::abs(frame.origin[axis] + 0.5f * frame.extent - bounds.center()[axis]) < 1e-4f);
    }
    const glm::vec3 g = frame.toGrid(bounds.min);
    QVERIFY(g.x >= 1.0f - 1e-3f);
}

void ConeMathTest::gridFitSurvivesDegenerateBounds()
{
    Aabb flat;
    flat.extend(glm::vec3(0.0f));
    const VoxelGridFrame frame = VoxelGridFrame::fit(flat, 32);
    QVERIFY(frame.extent > 0.0f && std::isfinite(frame.extent));
    const VoxelGridFrame empty = VoxelGridFrame::fit(Aabb {}, 32);
    QVERIFY(empty.extent > 0.0f && std::isfinite(empty.origin.x));
}

void ConeMathTest::settingsParseAndReject()
{
    RenderSettings s;
    QVERIFY(s.set("voxel_res", "64").empty());
    QCOMPARE(s.voxelResolution, 64);
    QVERIFY(s.set("step", "0.5").empty());
    QCOMPARE(s.stepFactor, 0.5f);
    QVERIFY(s.set("indirect_specular", "off").empty());
    QVERIFY(!s.indirectSpecular);
    QVERIFY(s.set("view", "ao").empty());
    QCOMPARE(s.view, DebugView::AmbientOcclusion);
    QVERIFY(!s.set("voxel_res", "100").empty()); // not a power of two
    QVERIFY(!s.set("voxel_res", "1024").empty());
    QVERIFY(!s.set("diffuse_aperture", "180").empty());
    QVERIFY(!s.set("step", "nan").empty());
    QVERIFY(s.set("bounce_step", "1.5").empty());
    QCOMPARE(s.bounceStepScale, 1.5f);
    QVERIFY(!s.set("bounce_step", "0").empty());
    QVERIFY(!s.set("bounce_step", "9").empty());
    QVERIFY(!s.set("bounce_step", "nan").empty());
    QCOMPARE(s.bounceStepScale, 1.5f);
    QVERIFY(!s.set("no_such_key", "1").empty());
    QCOMPARE(s.voxelResolution, 64); // a rejected value leaves the settings as they were
    // The higher bounces' cells: a size of their own, never finer than the bounce cells'.
    QVERIFY(s.set("higher_bounce_cell", "16").empty());
    QVERIFY(!s.set("higher_bounce_cell", "3").empty());
    QVERIFY(s.set("bounce_cell", "8").empty());
    const std::string finer = s.set("higher_bounce_cell", "4");
    QVERIFY2(finer.find("bounce_cell (8)") != std::string::npos, finer.c_str());
    QCOMPARE(s.higherBounceCellSize, 16);
}

QTEST_GUILESS_MAIN(ConeMathTest)
#include "tst_ConeMath.moc"
