#include "GlTestContext.h"
#include "TestSupport.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <QtTest>

using namespace vct;

class LightInjectionTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void litVoxelMatchesLambertFormula();
    void shadowedVoxelsGetNoLight();
    void directionalLightUsesIrradiance();
    void emissionIsAddedUnshadowed();
    void mipLevelsAreBoxFilters_data();
    void mipLevelsAreBoxFilters();
    void directionalMipsKeepThinWallsOpaque();
    void droppedBackFacesLeaveTheChainsTravellingTheirWay();
    void directionalChainsMatchCompositingAtEveryLevel_data();
    void directionalChainsMatchCompositingAtEveryLevel();
    void brickOccupancyMatchesTheVoxels();
    void noGlErrors();

private:
    /** Floor quad y = 0.5 over x,z in [1, 15] of a 16-unit grid at [0, 16]^3; optional occluder above it. */
    render::Scene floorScene(bool occluder);
    void render(const render::Scene& scene, int resolution = 16, bool anisotropic = false,
        bool emissionInVoxels = false);
    glm::vec4 voxel(const std::string& channel, int x, int y, int z, int level = 0);
    test::GlTestContext m_gl;
    const glm::vec3 m_albedo { 0.6f, 0.5f, 0.4f };
    const glm::vec3 m_lightPosition { 5.0f, 9.0f, 7.0f };
    const glm::vec3 m_intensity { 30.0f, 20.0f, 10.0f };
    bool m_dropBackFaces = false; ///< RenderSettings::dropBackFaces for the next render()
    int m_bounces = 1; ///< RenderSettings::bounces for the next render()
    render::VoxelMode m_voxelMode = render::VoxelMode::Dense; ///< for the next render()
};

void LightInjectionTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
}

render::Scene LightInjectionTest::floorScene(bool occluder)
{
    render::Scene scene;
    render::Material floor;
    floor.albedo = m_albedo;
    scene.materials.push_back(floor);
    // Floor in the middle of voxel layer y = 0 so the voxel centre lies on it.
    scene.meshes.push_back(
        test::makeTriangles(test::quad({ 1, 0.5f, 15 }, { 15, 0.5f, 15 }, { 15, 0.5f, 1 }, { 1, 0.5f, 1 })));
    if (occluder) // a 2x2 blocker at y = 5.5 over x in [6, 8], z in [7, 9]; its shadow falls around (10, 9.5)
        scene.meshes.push_back(
            test::makeTriangles(test::quad({ 6, 5.5f, 9 }, { 8, 5.5f, 9 }, { 8, 5.5f, 7 }, { 6, 5.5f, 7 })));
    scene.pointLights.push_back({ m_lightPosition, m_intensity, true });
    return scene;
}

void LightInjectionTest::render(
    const render::Scene& scene, int resolution, bool anisotropic, bool emissionInVoxels)
{
    render::RenderSettings settings;
    // Emitters are area lights while direct light is on, and their emission then stays out of the voxels:
    // the tests of emission in the voxels turn direct light off (they have no other light).
    settings.direct = !emissionInVoxels;
    // One bounce unless a test asks for more: the first-bounce volume then keeps its own levels (with more,
    // the bounced volume has them).
    settings.bounces = m_bounces;
    settings.voxelMode = m_voxelMode;
    settings.anisotropicMips = anisotropic;
    settings.dropBackFaces = m_dropBackFaces;
    settings.voxelResolution = resolution;
    settings.shadowMapSize = 512;
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(scene);
    m_gl.renderer->setGridBounds(
        test::box(glm::vec3(1.0f) * 16.0f / float(resolution), glm::vec3(16.0f - 16.0f / float(resolution))));
    m_gl.renderer->renderFrame(render::Camera {}, 8, 8);
}

glm::vec4 LightInjectionTest::voxel(const std::string& channel, int x, int y, int z, int level)
{
    int size = 0;
    const std::vector<float> data = m_gl.renderer->readVoxels(channel, level, size);
    const float* p = &data[((std::size_t(z) * size + y) * size + x) * 4];
    return { p[0], p[1], p[2], p[3] };
}

void LightInjectionTest::litVoxelMatchesLambertFormula()
{
    render(floorScene(false));
    for (const glm::ivec3 v :
        { glm::ivec3(5, 0, 7), glm::ivec3(2, 0, 3), glm::ivec3(12, 0, 13), glm::ivec3(9, 0, 4) }) {
        const glm::vec3 center = glm::vec3(v) + 0.5f;
        const glm::vec3 toLight = m_lightPosition - center;
        const float d2 = glm::dot(toLight, toLight);
        const float cosTheta = toLight.y / std::sqrt(d2);
        const glm::vec3 expected = m_albedo / glm::pi<float>() * m_intensity / d2 * cosTheta;
        const glm::vec4 actual = voxel("radiance", v.x, v.y, v.z);
        QCOMPARE(actual.a, 1.0f);
        for (int c = 0; c < 3; ++c)
            QVERIFY2(std::abs(actual[c] - expected[c]) <= 0.02f * expected[c],
                qPrintable(QString("voxel (%1,%2,%3) channel %4: %5 vs %6")
                               .arg(v.x)
                               .arg(v.y)
                               .arg(v.z)
                               .arg(c)
                               .arg(actual[c])
                               .arg(expected[c])));
    }
    QCOMPARE(voxel("radiance", 5, 3, 7), glm::vec4(0.0f)); // empty space stays empty
}

void LightInjectionTest::shadowedVoxelsGetNoLight()
{
    render(floorScene(true));
    // Project the blocker's centre from the light onto the floor plane y = 0.5.
    const glm::vec3 blocker(7.0f, 5.5f, 8.0f);
    const glm::vec3 dir = blocker - m_lightPosition;
    const glm::vec3 hit = m_lightPosition + dir * ((0.5f - m_lightPosition.y) / dir.y);
    const glm::ivec3 shadowed(int(hit.x), 0, int(hit.z));
    QVERIFY(shadowed.x >= 1 && shadowed.x < 15 && shadowed.z >= 1 && shadowed.z < 15);
    const glm::vec4 dark = voxel("radiance", shadowed.x, 0, shadowed.z);
    QCOMPARE(dark.a, 1.0f);
    QVERIFY2(dark.r == 0.0f && dark.g == 0.0f && dark.b == 0.0f, qPrintable(QString("%1").arg(dark.r)));
    // Outside the shadow the same floor is lit.
    QVERIFY(voxel("radiance", 3, 0, 3).r > 0.0f);
}

void LightInjectionTest::directionalLightUsesIrradiance()
{
    render::Scene scene = floorScene(false);
    scene.pointLights.clear();
    const glm::vec3 direction = glm::normalize(glm::vec3(1.0f, -2.0f, 0.5f));
    scene.directionalLights.push_back({ direction, glm::vec3(3.0f), true });
    render(scene);
    const float cosTheta = -direction.y;
    const glm::vec3 expected = m_albedo / glm::pi<float>() * 3.0f * cosTheta;
    const glm::vec4 actual = voxel("radiance", 7, 0, 7);
    for (int c = 0; c < 3; ++c)
        QVERIFY2(std::abs(actual[c] - expected[c]) <= 0.02f * expected[c],
            qPrintable(QString("%1 vs %2").arg(actual[c]).arg(expected[c])));
}

void LightInjectionTest::emissionIsAddedUnshadowed()
{
    render::Scene scene = floorScene(true);
    scene.pointLights.clear();
    scene.materials[0].emission = glm::vec3(2.0f, 1.0f, 0.5f);
    render(scene, 16, false, true);
    const glm::vec4 v = voxel("radiance", 10, 0, 10); // under the blocker: emission needs no light
    QVERIFY(std::abs(v.r - 2.0f) < 2e-3f && std::abs(v.g - 1.0f) < 1e-3f && std::abs(v.b - 0.5f) < 1e-3f);
}

void LightInjectionTest::mipLevelsAreBoxFilters_data()
{
    QTest::addColumn<bool>("bounced");
    QTest::newRow("first-bounce light") << false;
    // The bounce solve's reinjection writes level 1 itself, from the voxels it has just lit
    // (bounce/ReinjectBounce.comp); the mip filter the levels above.
    QTest::newRow("bounced light") << true;
}

void LightInjectionTest::mipLevelsAreBoxFilters()
{
    QFETCH(bool, bounced);
    render::Scene scene = floorScene(true);
    scene.materials[0].emission = glm::vec3(0.3f, 0.2f, 0.1f); // mixes lit, shadowed and emissive voxels
    m_bounces = bounced ? render::RenderSettings::kConvergedBounces : 1;
    render(scene, 16);
    m_bounces = 1;
    const std::string volume = bounced ? "bounced" : "radiance";
    int size0 = 0;
    const std::vector<float> level0 = m_gl.renderer->readVoxels(volume, 0, size0);
    for (int level = 1; level <= 4; ++level) {
        int size = 0;
        const std::vector<float> mip = m_gl.renderer->readVoxels(volume, level, size);
        QCOMPARE(size, size0 >> level);
        const int block = 1 << level;
        double worst = 0.0;
        for (int z = 0; z < size; ++z)
            for (int y = 0; y < size; ++y)
                for (int x = 0; x < size; ++x)
                    for (int c = 0; c < 4; ++c) {
                        double sum = 0.0;
                        for (int k = 0; k < block; ++k)
                            for (int j = 0; j < block; ++j)
                                for (int i = 0; i < block; ++i)
                                    sum += level0[((std::size_t(z * block + k) * size0 + (y * block + j))
                                                          * size0
                                                      + (x * block + i))
                                            * 4
                                        + c];
                        const double expected = sum / double(block * block * block);
                        const double actual = mip[((std::size_t(z) * size + y) * size + x) * 4 + c];
                        // Half floats round at every level: allow their relative precision per level.
                        worst = std::max(
                            worst, std::abs(actual - expected) - 2e-3 * level * std::abs(expected));
                    }
        QVERIFY2(worst <= 1e-5, qPrintable(QString("level %1 off by %2").arg(level).arg(worst)));
    }
}

// The floor fills one of the two voxel layers under each level-1 texel. Box filtering halves its opacity and
// radiance; compositing along y first keeps it opaque for cones travelling up or down, not sideways.
void LightInjectionTest::directionalMipsKeepThinWallsOpaque()
{
    render::Scene scene = floorScene(false);
    scene.pointLights.clear();
    scene.materials[0].emission = glm::vec3(1.0f, 0.5f, 0.25f);
    render(scene, 16, true, true);
    const glm::vec4 isotropic = voxel("radiance", 3, 0, 3, 1);
    QVERIFY(std::abs(isotropic.a - 0.5f) < 1e-3f);
    QVERIFY(std::abs(isotropic.r - 0.5f) < 2e-3f);
    for (const char* channel : { "radiance+y", "radiance-y" }) {
        const glm::vec4 v = voxel(channel, 3, 0, 3, 1);
        QVERIFY2(std::abs(v.a - 1.0f) < 1e-3f && std::abs(v.r - 1.0f) < 2e-3f,
            qPrintable(QString("%1: a %2 r %3").arg(channel).arg(v.a).arg(v.r)));
    }
    for (const char* channel : { "radiance+x", "radiance-z" })
        QVERIFY(std::abs(voxel(channel, 3, 0, 3, 1).a - 0.5f) < 1e-3f);
    // A level further up, the floor is one layer of four: upward cones still see it whole.
    QVERIFY(std::abs(voxel("radiance+y", 1, 0, 1, 2).a - 1.0f) < 1e-3f);
    QVERIFY(std::abs(voxel("radiance", 1, 0, 1, 2).a - 0.25f) < 1e-3f);
}

// With drop_back_faces a cone travelling up, the way the floor faces, has left it behind: the floor gives
// that chain neither light nor opacity, so it no longer lights or shades the cones leaving it. Cones
// travelling down onto it, and sideways, see it as before.
void LightInjectionTest::droppedBackFacesLeaveTheChainsTravellingTheirWay()
{
    render::Scene scene = floorScene(false);
    scene.pointLights.clear();
    scene.materials[0].emission = glm::vec3(1.0f, 0.5f, 0.25f);
    m_dropBackFaces = true;
    render(scene, 16, true, true);
    m_dropBackFaces = false;
    const glm::vec4 down = voxel("radiance-y", 3, 0, 3, 1);
    QVERIFY2(std::abs(down.a - 1.0f) < 1e-3f && std::abs(down.r - 1.0f) < 2e-3f,
        qPrintable(QString("radiance-y: a %1 r %2").arg(down.a).arg(down.r)));
    const glm::vec4 up = voxel("radiance+y", 3, 0, 3, 1);
    QVERIFY2(up.a == 0.0f && up.r == 0.0f, qPrintable(QString("radiance+y: a %1 r %2").arg(up.a).arg(up.r)));
    QCOMPARE(voxel("radiance+y", 1, 0, 1, 2).a, 0.0f);
    for (const char* channel : { "radiance+x", "radiance-z" })
        QVERIFY(std::abs(voxel(channel, 3, 0, 3, 1).a - 0.5f) < 1e-3f);
}

// The six chains share one texture as tiles (common/DirectionalStack.glsl); each must hold, at every level
// down to tiles two texels wide, its own front-to-back compositing of the level below, with nothing of its
// neighbours, and a level beyond that is not there.
void LightInjectionTest::directionalChainsMatchCompositingAtEveryLevel_data()
{
    QTest::addColumn<bool>("dropBackFaces");
    QTest::addColumn<bool>("bounced");
    QTest::addColumn<bool>("sparse");
    QTest::newRow("every voxel") << false << false << false;
    QTest::newRow("back faces dropped") << true << false << false;
    // The bounce solve's reinjection writes the chains' first level itself, from the voxels it has just lit
    // (bounce/ReinjectBounce.comp); the mip filter the levels above.
    QTest::newRow("bounced, every voxel") << false << true << false;
    QTest::newRow("bounced, back faces dropped") << true << true << false;
    QTest::newRow("bounced, sparse grid") << true << true << true;
}

void LightInjectionTest::directionalChainsMatchCompositingAtEveryLevel()
{
    QFETCH(bool, dropBackFaces);
    QFETCH(bool, bounced);
    QFETCH(bool, sparse);
    // A wall beside the floor gives the bounces light to carry and the cells two orientations.
    render::Scene scene = floorScene(true);
    scene.materials[0].emission = glm::vec3(0.3f, 0.2f, 0.1f);
    scene.meshes.push_back(test::makeTriangles(
        test::quad({ 12.5f, 0, 1 }, { 12.5f, 0, 15 }, { 12.5f, 9, 15 }, { 12.5f, 9, 1 })));
    m_dropBackFaces = dropBackFaces;
    m_bounces = bounced ? render::RenderSettings::kConvergedBounces : 1;
    m_voxelMode = sparse ? render::VoxelMode::Sparse : render::VoxelMode::Dense;
    render(scene, 16, true);
    m_dropBackFaces = false;
    m_bounces = 1;
    m_voxelMode = render::VoxelMode::Dense;
    const std::string volume = bounced ? "bounced" : "radiance";
    int size0 = 0;
    const std::vector<float> level0 = m_gl.renderer->readVoxels(volume, 0, size0);
    QCOMPARE(size0, 16);
    if (bounced) {
        // The bounces brightened the lit voxels: the chains below were filtered from the solve's light.
        int directSize = 0;
        const std::vector<float> direct = m_gl.renderer->readVoxels("radiance", 0, directSize);
        double bouncedSum = 0.0, directSum = 0.0;
        for (std::size_t k = 0; k < level0.size(); k += 4) {
            bouncedSum += level0[k];
            directSum += direct[k];
        }
        QVERIFY2(bouncedSum > 1.05 * directSum,
            qPrintable(QString("%1 against %2").arg(bouncedSum).arg(directSum)));
    }
    int normalSize = 0;
    const std::vector<float> normals = m_gl.renderer->readVoxels("normal", 0, normalSize);
    QCOMPARE(normalSize, size0);
    std::string channels[6];
    const char* const directions[6] = { "+x", "-x", "+y", "-y", "+z", "-z" };
    for (int tile = 0; tile < 6; ++tile)
        channels[tile] = volume + directions[tile];
    for (int tile = 0; tile < 6; ++tile) {
        const int axis = tile / 2;
        const bool positive = tile % 2 == 0; // travelling towards +axis: the lower child is in front
        std::vector<double> previous(level0.begin(), level0.end());
        int previousSize = size0;
        for (int level = 1; level <= 3; ++level) {
            const int size = previousSize / 2;
            std::vector<double> expected(std::size_t(size) * size * size * 4, 0.0);
            const auto at = [&previous, previousSize](glm::ivec3 v, int c) {
                return previous[((std::size_t(v.z) * previousSize + v.y) * previousSize + v.x) * 4 + c];
            };
            // With dropBackFaces level 1 drops the voxels of one-sided surfaces that face the way the chain
            // travels (they fade out over the first 15 degrees past edge-on).
            const auto seen = [&](glm::ivec3 v) {
                if (!dropBackFaces || level > 1)
                    return 1.0;
                const std::size_t k = ((std::size_t(v.z) * size0 + v.y) * size0 + v.x) * 4;
                const glm::dvec3 n(normals[k], normals[k + 1], normals[k + 2]);
                if (glm::length(n) < 0.5)
                    return 1.0;
                const double along = glm::normalize(n)[axis] * (positive ? 1.0 : -1.0);
                return 1.0 - std::clamp(4.0 * along, 0.0, 1.0);
            };
            for (int z = 0; z < size; ++z)
                for (int y = 0; y < size; ++y)
                    for (int x = 0; x < size; ++x)
                        for (int i = 0; i < 4; ++i) {
                            glm::ivec3 lateral(0);
                            lateral[(axis + 1) % 3] = i & 1;
                            lateral[(axis + 2) % 3] = i >> 1;
                            glm::ivec3 lower = glm::ivec3(x, y, z) * 2 + lateral;
                            glm::ivec3 upper = lower;
                            upper[axis] += 1;
                            const glm::ivec3 front = positive ? lower : upper,
                                             back = positive ? upper : lower;
                            const double frontSeen = seen(front), backSeen = seen(back);
                            const double frontAlpha = frontSeen * at(front, 3);
                            for (int c = 0; c < 4; ++c)
                                expected[((std::size_t(z) * size + y) * size + x) * 4 + c] += 0.25
                                    * (frontSeen * at(front, c)
                                        + (1.0 - frontAlpha) * backSeen * at(back, c));
                        }
            int gpuSize = 0;
            const std::vector<float> gpu = m_gl.renderer->readVoxels(channels[tile], level, gpuSize);
            QCOMPARE(gpuSize, size);
            double worst = 0.0;
            for (std::size_t k = 0; k < expected.size(); ++k)
                worst = std::max(
                    worst, std::abs(double(gpu[k]) - expected[k]) - 2e-3 * level * std::abs(expected[k]));
            QVERIFY2(worst <= 1e-5,
                qPrintable(
                    QString("%1 level %2 off by %3").arg(channels[tile].c_str()).arg(level).arg(worst)));
            previous = expected;
            previousSize = size;
        }
        int none = 0;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, m_gl.renderer->readVoxels(channels[tile], 4, none));
    }
}

// Renderer::brickOccupancy reads the occupied-voxel lists back; the albedo texture's opacity says the same
// independently: every brick holding a voxel with opacity, and only those.
void LightInjectionTest::brickOccupancyMatchesTheVoxels()
{
    render(floorScene(true), 16);
    int size = 0;
    const std::vector<float> albedo = m_gl.renderer->readVoxels("albedo", 0, size);
    QCOMPARE(size, 16);
    for (const int brickSize : { 4, 8 }) {
        const std::vector<render::BrickOccupancy> grids = m_gl.renderer->brickOccupancy(brickSize);
        QCOMPARE(grids.size(), std::size_t(1));
        const render::BrickOccupancy& o = grids.front();
        const int bricks = size / brickSize;
        std::vector<bool> expected(std::size_t(bricks * bricks * bricks), false);
        std::size_t voxels = 0;
        for (int z = 0; z < size; ++z)
            for (int y = 0; y < size; ++y)
                for (int x = 0; x < size; ++x)
                    if (albedo[((std::size_t(z) * size + y) * size + x) * 4 + 3] > 0.0f) {
                        ++voxels;
                        expected[std::size_t(
                            ((z / brickSize) * bricks + y / brickSize) * bricks + x / brickSize)]
                            = true;
                    }
        const auto occupied = std::size_t(std::count(expected.begin(), expected.end(), true));
        QCOMPARE(o.resolution, 16);
        QCOMPARE(o.occupiedVoxels, voxels);
        QCOMPARE(o.totalBricks, expected.size());
        QCOMPARE(o.occupiedBricks, occupied);
        QVERIFY(occupied > 0 && occupied < expected.size()); // the floor and the blocker, not the whole grid
        QVERIFY(std::abs(o.borderedPoolShare()
                    - double(occupied) * std::pow(brickSize + 2, 3) / std::pow(double(size), 3))
            < 1e-12);
    }
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, m_gl.renderer->brickOccupancy(0));
}

void LightInjectionTest::noGlErrors()
{
    const auto errors = m_gl.renderer->takeGlErrors();
    QVERIFY2(errors.empty(), errors.empty() ? "" : errors.front().c_str());
}

QTEST_GUILESS_MAIN(LightInjectionTest)
#include "tst_LightInjection.moc"
