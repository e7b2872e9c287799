#include "GlTestContext.h"
#include "TestSupport.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include <QtTest>

using namespace vct;

/**
 * The bounce solve's reinjection (bounce/ReinjectBounce.comp) against its definition, computed here from what
 * the GPU read back: each occupied voxel's light after one iteration (`bounces=2`) is its first-bounce light
 * plus its albedo times the bounce cells' gather looked up as common/IrradianceLookup.glsl defines it (the
 * eight cells around it, weighted by position and by how well each cell's surface faces the voxel's, else its
 * own cell). The reinjection runs by blocks of 2^3 voxels and shares the cells' fetches between a block's
 * voxels where the cells allow it; the rows cover cells that do (4^3, 8^3) and cells that do not (2^3), dense
 * and sparse.
 */
class BounceReinjectionTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void voxelsTakeTheirLookedUpGather_data();
    void voxelsTakeTheirLookedUpGather();
    void noGlErrors();

private:
    test::GlTestContext m_gl;
};

namespace {

constexpr int kResolution = 32;

/** A room's corner under a point light: a floor, two walls, a thin slab (two-sided cells) and a tilted plate.
 */
render::Scene cornerScene()
{
    render::Scene scene;
    render::Material white;
    white.albedo = { 0.7f, 0.6f, 0.5f };
    render::Material red;
    red.albedo = { 0.8f, 0.2f, 0.1f };
    scene.materials = { white, red };
    scene.meshes.push_back(
        test::makeTriangles(test::quad({ 1, 0.5f, 15 }, { 15, 0.5f, 15 }, { 15, 0.5f, 1 }, { 1, 0.5f, 1 })));
    scene.meshes.push_back(test::makeTriangles(
        test::quad({ 1.5f, 0.5f, 1 }, { 1.5f, 0.5f, 15 }, { 1.5f, 12, 15 }, { 1.5f, 12, 1 }), 1));
    scene.meshes.push_back(test::makeTriangles(
        test::quad({ 1, 0.5f, 1.5f }, { 1, 12, 1.5f }, { 15, 12, 1.5f }, { 15, 0.5f, 1.5f })));
    // Both faces of a slab thinner than a voxel: its voxels' normals cancel.
    scene.meshes.push_back(
        test::makeTriangles(test::quad({ 6, 4, 5 }, { 11, 4, 5 }, { 11, 4, 10 }, { 6, 4, 10 })));
    scene.meshes.push_back(
        test::makeTriangles(test::quad({ 6, 4.1f, 10 }, { 11, 4.1f, 10 }, { 11, 4.1f, 5 }, { 6, 4.1f, 5 })));
    scene.meshes.push_back(test::makeTriangles(
        test::quad({ 10, 1, 12 }, { 13, 2.5f, 12 }, { 13, 4, 14.5f }, { 10, 2.5f, 14.5f }), 1));
    scene.pointLights.push_back({ { 9.0f, 10.0f, 9.0f }, { 40.0f, 40.0f, 40.0f }, true });
    return scene;
}

glm::vec4 texel(const std::vector<float>& data, int size, glm::ivec3 v)
{
    const float* p = &data[((std::size_t(v.z) * std::size_t(size) + std::size_t(v.y)) * std::size_t(size)
                               + std::size_t(v.x))
        * 4];
    return { p[0], p[1], p[2], p[3] };
}

/** What the bounce cells hold, read back. */
struct Cells {
    std::vector<float> front, back, normals;
    int size = 0;

    glm::vec4 at(const std::vector<float>& data, glm::ivec3 c) const { return texel(data, size, c); }
};

/** common/IrradianceLookup.glsl's lookUpCells, for a voxel (voxel centre at `g` in cell units less one half).
 */
bool lookUp(const Cells& cells, glm::vec3 g, glm::vec3 n, glm::vec3& result)
{
    const glm::ivec3 base = glm::ivec3(glm::floor(g));
    const glm::vec3 f = g - glm::vec3(base);
    glm::vec3 sum(0.0f);
    float weightSum = 0.0f;
    for (int i = 0; i < 8; ++i) {
        const glm::ivec3 corner(i & 1, (i >> 1) & 1, i >> 2);
        const glm::ivec3 c = base + corner;
        if (glm::any(glm::lessThan(c, glm::ivec3(0)))
            || glm::any(glm::greaterThanEqual(c, glm::ivec3(cells.size))))
            continue;
        const glm::vec4 cellNormal = cells.at(cells.normals, c);
        if (cellNormal.w <= 0.0f)
            continue;
        float agreement = glm::dot(glm::vec3(cellNormal), n);
        const bool backSide = cellNormal.w > 0.75f && agreement < 0.0f;
        if (backSide)
            agreement = -agreement;
        if (agreement < 0.5f)
            continue;
        const glm::vec4 cached = cells.at(backSide ? cells.back : cells.front, c);
        if (cached.a < 0.0f)
            continue;
        const glm::vec3 t = glm::mix(glm::vec3(1.0f) - f, f, glm::vec3(corner));
        const float a2 = agreement * agreement;
        const float w = (t.x * t.y * t.z + 1e-3f) * a2 * a2;
        sum += w * glm::vec3(cached);
        weightSum += w;
    }
    if (weightSum <= 0.0f)
        return false;
    result = sum / weightSum;
    return true;
}

/** The voxel's own cell, where no cell around it faces its way (bounce/ReinjectBounce.comp). */
glm::vec3 ownCell(const Cells& cells, glm::ivec3 cell, glm::vec3 n, bool faced)
{
    const glm::vec4 cellNormal = cells.at(cells.normals, cell);
    if (cellNormal.w <= 0.0f)
        return glm::vec3(0.0f);
    const glm::vec3 front = glm::max(glm::vec3(cells.at(cells.front, cell)), glm::vec3(0.0f));
    if (cellNormal.w < 0.75f)
        return front;
    const glm::vec3 back = glm::max(glm::vec3(cells.at(cells.back, cell)), glm::vec3(0.0f));
    if (!faced)
        return 0.5f * (front + back);
    return glm::dot(n, glm::vec3(cellNormal)) >= 0.0f ? front : back;
}

} // namespace

void BounceReinjectionTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
}

void BounceReinjectionTest::voxelsTakeTheirLookedUpGather_data()
{
    QTest::addColumn<int>("cellVoxels");
    QTest::addColumn<bool>("sparse");
    QTest::newRow("cells of 2^3 voxels") << 2 << false;
    QTest::newRow("cells of 4^3 voxels") << 4 << false;
    QTest::newRow("cells of 8^3 voxels") << 8 << false;
    QTest::newRow("cells of 4^3 voxels, sparse grid") << 4 << true;
}

void BounceReinjectionTest::voxelsTakeTheirLookedUpGather()
{
    QFETCH(int, cellVoxels);
    QFETCH(bool, sparse);
    render::RenderSettings settings;
    settings.bounces = 2; // one iteration: the first-bounce light's gather, reinjected once
    settings.bounceCellSize = cellVoxels;
    settings.higherBounceCellSize = cellVoxels;
    settings.voxelResolution = kResolution;
    settings.voxelMode = sparse ? render::VoxelMode::Sparse : render::VoxelMode::Dense;
    settings.shadowMapSize = 512;
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(cornerScene());
    m_gl.renderer->setGridBounds(test::box(glm::vec3(0.0f), glm::vec3(16.0f)));
    m_gl.renderer->renderFrame(render::Camera {}, 8, 8);

    int size = 0;
    const std::vector<float> albedo = m_gl.renderer->readVoxels("albedo", 0, size);
    QCOMPARE(size, kResolution);
    const std::vector<float> normal = m_gl.renderer->readVoxels("normal", 0, size);
    const std::vector<float> direct = m_gl.renderer->readVoxels("radiance", 0, size);
    const std::vector<float> bounced = m_gl.renderer->readVoxels("bounced", 0, size);
    Cells cells;
    cells.front = m_gl.renderer->readVoxels("bounce cells", 0, cells.size);
    QCOMPARE(cells.size, kResolution / cellVoxels);
    cells.back = m_gl.renderer->readVoxels("bounce cells, back faces", 0, cells.size);
    cells.normals = m_gl.renderer->readVoxels("bounce cell normals", 0, cells.size);

    int occupied = 0, lookedUp = 0, ownCells = 0, twoSidedCells = 0;
    double worst = 0.0, brightened = 0.0, directSum = 0.0;
    for (int z = 0; z < cells.size; ++z)
        for (int y = 0; y < cells.size; ++y)
            for (int x = 0; x < cells.size; ++x)
                twoSidedCells += cells.at(cells.normals, { x, y, z }).w > 0.75f ? 1 : 0;
    for (int z = 0; z < kResolution; ++z)
        for (int y = 0; y < kResolution; ++y)
            for (int x = 0; x < kResolution; ++x) {
                const glm::ivec3 v(x, y, z);
                const glm::vec4 a = texel(albedo, size, v);
                if (a.a <= 0.0f)
                    continue;
                ++occupied;
                const glm::vec4 d = texel(direct, size, v);
                glm::vec3 expected(d);
                if (std::max({ a.r, a.g, a.b }) > 0.0f) {
                    const glm::vec3 normalSum(texel(normal, size, v));
                    const float normalLength = glm::length(normalSum);
                    const bool faced = normalLength >= 0.5f;
                    const glm::vec3 n = normalLength > 1e-4f ? normalSum / normalLength : glm::vec3(0.0f);
                    const glm::vec3 g = (glm::vec3(v) + 0.5f) / float(cellVoxels) - 0.5f;
                    glm::vec3 gathered;
                    if (faced && lookUp(cells, g, n, gathered)) {
                        ++lookedUp;
                    } else {
                        gathered = ownCell(cells, v / cellVoxels, n, faced);
                        ++ownCells;
                    }
                    expected = glm::max(expected + glm::vec3(a) * gathered * a.a, glm::vec3(0.0f));
                }
                const glm::vec4 actual = texel(bounced, size, v);
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst,
                        std::abs(double(actual[c]) - double(expected[c]))
                            - 2e-3 * std::abs(double(expected[c])));
                QCOMPARE(actual.a, d.a);
                brightened += double(actual.r) - double(d.r);
                directSum += double(d.r);
            }
    // The scene exercises what it is meant to: lookups, own cells, two-sided cells, and light that bounced.
    QVERIFY2(occupied > 500, qPrintable(QString::number(occupied)));
    QVERIFY2(lookedUp > occupied / 2, qPrintable(QString("%1 of %2").arg(lookedUp).arg(occupied)));
    QVERIFY2(ownCells > 0, "no voxel fell back to its own cell");
    QVERIFY2(twoSidedCells > 0, "no two-sided cell");
    QVERIFY2(
        brightened > 0.05 * directSum, qPrintable(QString("%1 against %2").arg(brightened).arg(directSum)));
    QVERIFY2(worst <= 1e-5, qPrintable(QString("a voxel off by %1").arg(worst)));
}

void BounceReinjectionTest::noGlErrors()
{
    const auto errors = m_gl.renderer->takeGlErrors();
    QVERIFY2(errors.empty(), errors.empty() ? "" : errors.front().c_str());
}

QTEST_GUILESS_MAIN(BounceReinjectionTest)
#include "tst_BounceReinjection.moc"
