#include "GlTestContext.h"
#include "TestSupport.h"

#include "scene/VoxelTextureEstimate.h"

#include <QtTest>

#include <map>

using namespace vct;

/** Renderer::voxelMemory: bytes per 3D texture level, adding up to what FrameStats reports as voxel bytes. */
class VoxelTextureMemoryTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void levelsHalveAndAddUpToTheTotal_data();
    void levelsHalveAndAddUpToTheTotal();

private:
    test::GlTestContext m_gl;
};

void VoxelTextureMemoryTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
}

void VoxelTextureMemoryTest::levelsHalveAndAddUpToTheTotal_data()
{
    QTest::addColumn<bool>("anisotropic");
    QTest::newRow("box mips") << false;
    QTest::newRow("anisotropic mips") << true;
}

void VoxelTextureMemoryTest::levelsHalveAndAddUpToTheTotal()
{
    QFETCH(bool, anisotropic);
    render::Renderer& renderer = *m_gl.renderer;
    render::Scene scene;
    scene.materials.push_back(render::Material {});
    scene.meshes.push_back(
        test::makeTriangles(test::quad({ -1, 0, 1 }, { 1, 0, 1 }, { 1, 0, -1 }, { -1, 0, -1 }), 0));
    scene.pointLights.push_back(render::PointLight { { 0.0f, 1.0f, 0.0f }, glm::vec3(1.0f), true });
    render::RenderSettings settings;
    settings.voxelResolution = 16;
    settings.anisotropicMips = anisotropic;
    renderer.setSettings(settings);
    renderer.setScene(scene);
    const render::FrameStats stats = renderer.renderFrame(scene.camera, 16, 16);

    const std::vector<render::VoxelTextureMemory> memory = renderer.voxelMemory();
    std::size_t total = 0;
    bool sawRadiance = false, sawBounced = false;
    int directional = 0;
    for (const render::VoxelTextureMemory& m : memory) {
        total += m.totalBytes();
        // GL's own description of the storage (sizes and component bits per level) agrees with the count.
        QVERIFY2(m.glBytes == m.totalBytes(),
            qPrintable(QString("%1: GL reports %2 bytes, counted %3")
                           .arg(m.name.c_str())
                           .arg(m.glBytes)
                           .arg(m.totalBytes())));
        // With every bounce in the voxels (the default) cones trace the bounced volume: it has the levels,
        // and the first-bounce radiance keeps level 0 alone, as the iteration's source.
        QVERIFY2(
            m.name.rfind("radiance, directional", 0) != 0, "first-bounce radiance has no levels to trace");
        if (m.name.rfind("bounced, directional", 0) == 0) {
            // Six tiles with five empty gaps of half a tile between them (common/DirectionalStack.glsl),
            // tiles 8, 4 and 2 wide.
            ++directional;
            QCOMPARE(m.levelBytes.size(), std::size_t(3));
            for (std::size_t level = 0; level < m.levelBytes.size(); ++level) {
                const std::size_t side = std::size_t(8 >> level);
                QCOMPARE(m.levelBytes[level], side * side * (17 * side / 2) * 8);
            }
        }
        if (m.name == "radiance") {
            sawRadiance = true;
            QCOMPARE(m.format, std::string("rgba16f"));
            QCOMPARE(m.levelBytes, std::vector<std::size_t> { 16 * 16 * 16 * 8 });
        }
        if (m.name != "bounced")
            continue;
        sawBounced = true;
        QCOMPARE(m.format, std::string("rgba16f"));
        // With anisotropic mips cones read level 0 and the directional chains only; else 16, 8, 4, 2, 1.
        QCOMPARE(m.levelBytes.size(), std::size_t(anisotropic ? 1 : 5));
        for (std::size_t level = 0; level < m.levelBytes.size(); ++level) {
            const std::size_t side = std::size_t(16 >> level);
            QCOMPARE(m.levelBytes[level], side * side * side * 8);
        }
    }
    QVERIFY(sawRadiance && sawBounced);
    QCOMPARE(directional, anisotropic ? 1 : 0);
    QCOMPARE(total, renderer.voxelBytes());
    QCOMPARE(total, stats.voxelBytes);
    // The estimate the budget check uses, texture by texture: the same textures, by name, of the same sizes.
    std::map<std::string, std::uint64_t> estimated, allocated;
    for (const render::VoxelTextureEstimate& e : render::VoxelTextureEstimate::of(
             settings, { .emission = false, .areaLights = false, .lightSources = true }))
        estimated[e.name] = e.bytes;
    for (const render::VoxelTextureMemory& m : memory)
        allocated[m.name] = m.totalBytes();
    const auto listed = [](const std::map<std::string, std::uint64_t>& textures) {
        QStringList out;
        for (const auto& [name, bytes] : textures)
            out << QString("%1 %2").arg(name.c_str()).arg(bytes);
        return out.join(", ");
    };
    QVERIFY2(estimated == allocated,
        qPrintable(QString("estimated: %1\nallocated: %2").arg(listed(estimated), listed(allocated))));
    // The occupied voxels the stats report are those holding a surface.
    int size = 0;
    const std::vector<float> albedo = renderer.readVoxels("albedo", 0, size);
    std::size_t occupied = 0;
    for (std::size_t i = 3; i < albedo.size(); i += 4)
        occupied += albedo[i] > 0.0f ? 1 : 0;
    QVERIFY(occupied > 0);
    QCOMPARE(stats.occupiedVoxels, occupied);
    QVERIFY(renderer.takeGlErrors().empty());
}

QTEST_GUILESS_MAIN(VoxelTextureMemoryTest)
#include "tst_VoxelTextureMemory.moc"
