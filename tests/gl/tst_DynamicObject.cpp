#include "GlTestContext.h"
#include "TestSupport.h"

#include <glm/gtc/matrix_transform.hpp>

#include <QtTest>

using namespace vct;

/** A dynamic mesh is re-voxelized when it moves; the static voxels stay as they were. */
class DynamicObjectTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void movingDynamicMeshRevoxelizesOnlyItself();
    void cameraOnlyFrameReusesVoxels();
    void objectOnTheFloorSharesItsVoxels();

private:
    render::Scene scene() const;
    float occupancy(int x, int y, int z);
    const render::PassStats& pass(const render::FrameStats& stats, const std::string& name);
    test::GlTestContext m_gl;
};

void DynamicObjectTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
}

render::Scene DynamicObjectTest::scene() const
{
    return test::floorAndDynamicPlate();
}

float DynamicObjectTest::occupancy(int x, int y, int z)
{
    int size = 0;
    const std::vector<float> albedo = m_gl.renderer->readVoxels("albedo", 0, size);
    return albedo[((std::size_t(z) * size + y) * size + x) * 4 + 3];
}

const render::PassStats& DynamicObjectTest::pass(const render::FrameStats& stats, const std::string& name)
{
    for (const render::PassStats& p : stats.passes)
        if (p.name == name)
            return p;
    qFatal("no pass %s", name.c_str());
}

void DynamicObjectTest::movingDynamicMeshRevoxelizesOnlyItself()
{
    render::RenderSettings settings;
    settings.voxelResolution = 16;
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(scene());
    m_gl.renderer->setGridBounds(test::box(glm::vec3(1.0f), glm::vec3(15.0f)));
    const render::Camera camera { { 8, 8, 30 }, { 8, 4, 8 }, { 0, 1, 0 }, 40.0f, 0.01f };
    m_gl.renderer->renderFrame(camera, 16, 16);
    QCOMPARE(occupancy(4, 4, 4), 1.0f);
    QCOMPARE(occupancy(10, 4, 4), 0.0f);
    QCOMPARE(occupancy(7, 0, 7), 1.0f);

    m_gl.renderer->setMeshTransform(1, glm::translate(glm::mat4(1.0f), glm::vec3(6.0f, 0.0f, 0.0f)));
    const render::FrameStats moved = m_gl.renderer->renderFrame(camera, 16, 16);
    QCOMPARE(pass(moved, "voxelize").action, std::string("run"));
    QVERIFY(pass(moved, "voxelize").reason.find("dynamic") != std::string::npos);
    QCOMPARE(occupancy(4, 4, 4), 0.0f); // the old place is empty again
    QCOMPARE(occupancy(10, 4, 4), 1.0f); // the new place is filled
    QCOMPARE(occupancy(7, 0, 7), 1.0f); // the static floor is still there
    const render::RadianceImage incremental = m_gl.renderer->readFrame();

    // The same state rendered from scratch gives the same image.
    render::Scene fresh = scene();
    fresh.meshes[1].transform = glm::translate(glm::mat4(1.0f), glm::vec3(6.0f, 0.0f, 0.0f));
    m_gl.renderer->setScene(fresh);
    m_gl.renderer->renderFrame(camera, 16, 16);
    const render::RadianceImage full = m_gl.renderer->readFrame();
    for (std::size_t i = 0; i < full.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            QVERIFY2(std::abs(full.pixels[i][c] - incremental.pixels[i][c])
                    <= 1e-3f * (1.0f + std::abs(full.pixels[i][c])),
                qPrintable(QString("pixel %1: %2 vs %3")
                               .arg(i)
                               .arg(incremental.pixels[i][c])
                               .arg(full.pixels[i][c])));
    QVERIFY(m_gl.renderer->takeGlErrors().empty());
}

// A moving object resting on the floor shares the floor's voxels: they hold the mean of both, the same after
// a move as after a rebuild from scratch, and the floor is whole again where the object was.
void DynamicObjectTest::objectOnTheFloorSharesItsVoxels()
{
    render::Scene onFloor = scene();
    onFloor.materials.push_back({});
    onFloor.materials[1].albedo = glm::vec3(0.9f, 0.1f, 0.1f);
    onFloor.meshes[1] = test::makeTriangles(
        test::quad({ 3.2f, 0.6f, 4.8f }, { 4.8f, 0.6f, 4.8f }, { 4.8f, 0.6f, 3.2f }, { 3.2f, 0.6f, 3.2f }),
        1);
    onFloor.meshes[1].dynamic = true;
    render::RenderSettings settings;
    settings.voxelResolution = 16;
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(onFloor);
    m_gl.renderer->setGridBounds(test::box(glm::vec3(1.0f), glm::vec3(15.0f)));
    const render::Camera camera { { 8, 8, 30 }, { 8, 4, 8 }, { 0, 1, 0 }, 40.0f, 0.01f };
    m_gl.renderer->renderFrame(camera, 16, 16);
    const glm::mat4 moved = glm::translate(glm::mat4(1.0f), glm::vec3(6.0f, 0.0f, 0.0f));
    m_gl.renderer->setMeshTransform(1, moved);
    const render::FrameStats afterMove = m_gl.renderer->renderFrame(camera, 16, 16);
    int size = 0;
    const std::vector<float> incremental = m_gl.renderer->readVoxels("albedo", 0, size);
    // The stats count each voxel holding a surface once, shared ones too.
    std::size_t occupied = 0;
    for (std::size_t i = 3; i < incremental.size(); i += 4)
        occupied += incremental[i] > 0.0f ? 1 : 0;
    QCOMPARE(afterMove.occupiedVoxels, occupied);

    onFloor.meshes[1].transform = moved;
    m_gl.renderer->setScene(onFloor);
    m_gl.renderer->renderFrame(camera, 16, 16);
    const std::vector<float> full = m_gl.renderer->readVoxels("albedo", 0, size);
    QCOMPARE(incremental.size(), full.size());
    for (std::size_t i = 0; i < full.size(); ++i)
        QVERIFY2(std::abs(full[i] - incremental[i]) <= 2.0f / 255.0f,
            qPrintable(QString("texel %1: %2 after the move, %3 from scratch")
                           .arg(i)
                           .arg(incremental[i])
                           .arg(full[i])));
    const auto albedoAt = [&](int x, int y, int z) {
        const float* p = &full[((std::size_t(z) * size + y) * size + x) * 4];
        return glm::vec3(p[0], p[1], p[2]);
    };
    const glm::vec3 shared = albedoAt(10, 0, 4), vacated = albedoAt(4, 0, 4);
    // Floor 0.8 grey, object (0.9, 0.1, 0.1): a mix of both, whatever their fragment counts.
    QVERIFY2(shared.r > 0.8f && shared.g > 0.2f && shared.g < 0.7f,
        qPrintable(QString("shared voxel %1 %2 %3").arg(shared.r).arg(shared.g).arg(shared.b)));
    QVERIFY2(glm::all(glm::lessThan(glm::abs(vacated - glm::vec3(0.8f)), glm::vec3(2.0f / 255.0f))),
        qPrintable(QString("vacated voxel %1 %2 %3").arg(vacated.r).arg(vacated.g).arg(vacated.b)));
}

void DynamicObjectTest::cameraOnlyFrameReusesVoxels()
{
    m_gl.renderer->setScene(scene());
    const render::Camera a { { 8, 8, 30 }, { 8, 4, 8 }, { 0, 1, 0 }, 40.0f, 0.01f };
    m_gl.renderer->renderFrame(a, 16, 16);
    render::Camera b = a;
    b.position.x += 1.0f;
    const render::FrameStats stats = m_gl.renderer->renderFrame(b, 16, 16);
    for (const char* name : { "shadow maps", "voxelize", "inject light", "mipmaps" })
        QCOMPARE(pass(stats, name).action, std::string("reused"));
    QCOMPARE(pass(stats, "cone trace").action, std::string("run"));
}

QTEST_GUILESS_MAIN(DynamicObjectTest)
#include "tst_DynamicObject.moc"
