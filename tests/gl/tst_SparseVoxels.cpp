#include "GlTestContext.h"
#include "TestSupport.h"

#include "document/SceneLoader.h"
#include "imageio/ImageMetrics.h"

#include <glm/gtc/matrix_transform.hpp>

#include <QtTest>

#include <random>

using namespace vct;

namespace {

constexpr int kSize = 48;

/** The largest difference between two arrays of voxel values, relative to the largest value of @p b. */
float largestDifference(const std::vector<float>& a, const std::vector<float>& b)
{
    if (a.size() != b.size())
        return std::numeric_limits<float>::infinity();
    float largest = 0.0f, peak = 1e-6f;
    for (std::size_t i = 0; i < a.size(); ++i) {
        largest = std::max(largest, std::abs(a[i] - b[i]));
        peak = std::max(peak, std::abs(b[i]));
    }
    return largest / peak;
}

/** The largest difference between two images, relative to the brighter image's largest value. */
double largestPixelDifference(const render::RadianceImage& a, const render::RadianceImage& b)
{
    double largest = 0.0, peak = 1e-6;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const glm::vec3 d = glm::abs(a.pixels[i] - b.pixels[i]);
        largest = std::max(largest, double(std::max(d.x, std::max(d.y, d.z))));
        peak = std::max(peak, double(std::max(a.pixels[i].x, std::max(a.pixels[i].y, a.pixels[i].z))));
    }
    return largest / peak;
}

} // namespace

/**
 * voxel_mode=sparse (core/BrickPool, common/VoxelBricks.glsl): level 0 of the grid's textures keeps only the
 * bricks geometry reaches. Nothing a dense grid stores may be lost or changed by it: the same voxels, the
 * same light, the same image, through every pass (area lights, emission, bounces, the irradiance cache,
 * dynamic objects, the inspector's levels), and in less memory.
 */
class SparseVoxelsTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void sameVoxelsAndImageAsDense_data();
    void sameVoxelsAndImageAsDense();
    void storesOnlyTheBricksReached();
    void dynamicObjectMovesIntoEmptyBricks();
    void slopedTrianglesLoseNoVoxel();
    void refusesBoxMips();

private:
    struct Frame {
        render::FrameStats stats;
        render::RadianceImage image;
    };
    Frame render(const render::RenderSettings& settings, const render::Camera& camera);
    test::GlTestContext m_gl;
};

void SparseVoxelsTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
}

SparseVoxelsTest::Frame SparseVoxelsTest::render(
    const render::RenderSettings& settings, const render::Camera& camera)
{
    m_gl.renderer->setSettings(settings);
    Frame frame;
    frame.stats = m_gl.renderer->renderFrame(camera, kSize, kSize);
    frame.image = m_gl.renderer->readFrame();
    return frame;
}

void SparseVoxelsTest::sameVoxelsAndImageAsDense_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<int>("resolution");
    QTest::addColumn<float>("aperture");
    // Area lights and emission; point light only; a sunlit open scene; a grid of one brick. Cones of 2
    // degrees read level 0 for most of their way, through the bricks' borders, where the default cones
    // leave it within a voxel or two.
    QTest::newRow("cornell 32^3") << QStringLiteral("builtin:cornell") << 32 << 22.0f;
    QTest::newRow("cornell_point 32^3") << QStringLiteral("builtin:cornell_point") << 32 << 22.0f;
    QTest::newRow("atrium 64^3") << QStringLiteral("builtin:atrium") << 64 << 22.0f;
    QTest::newRow("cornell_point 8^3") << QStringLiteral("builtin:cornell_point") << 8 << 22.0f;
    QTest::newRow("cornell_point 32^3, 2-degree cones")
        << QStringLiteral("builtin:cornell_point") << 32 << 2.0f;
}

// The sparse grid's voxels and image may differ from the dense grid's by what differs between two runs of
// either: the voxelizer's running means round in the order fragments arrive (a unit in the last place of
// the 8-bit albedo and normal), which llvmpipe's threads vary, and the light follows (two dense runs of the
// Cornell box: up to 1.4% of the peak in one bounced voxel, relative MSE up to 3e-4 in the image). A brick
// missed or a stale border copy would show as a whole voxel's value.
void SparseVoxelsTest::sameVoxelsAndImageAsDense()
{
    QFETCH(QString, scene);
    QFETCH(int, resolution);
    QFETCH(float, aperture);
    render::Scene loaded;
    QString error;
    QVERIFY2(doc::SceneLoader::load(scene, loaded, &error), qPrintable(error));
    m_gl.renderer->setScene(loaded);
    render::RenderSettings settings;
    settings.voxelResolution = resolution;
    settings.shadowMapSize = 256;
    settings.diffuseApertureDeg = aperture;
    const Frame dense = render(settings, loaded.camera);
    int size = 0;
    std::vector<std::vector<float>> denseVoxels;
    for (const char* channel : { "albedo", "normal", "radiance", "bounced" })
        denseVoxels.push_back(m_gl.renderer->readVoxels(channel, 0, size));
    const std::vector<float> denseLevel1 = m_gl.renderer->readVoxels("bounced", 1, size);

    settings.voxelMode = render::VoxelMode::Sparse;
    const Frame sparse = render(settings, loaded.camera);
    QVERIFY(sparse.stats.occupiedVoxels > 0);
    QCOMPARE(sparse.stats.occupiedVoxels, dense.stats.occupiedVoxels);
    int index = 0;
    for (const char* channel : { "albedo", "normal", "radiance", "bounced" }) {
        const std::vector<float> voxels = m_gl.renderer->readVoxels(channel, 0, size);
        QCOMPARE(size, resolution);
        const float difference = largestDifference(voxels, denseVoxels[std::size_t(index++)]);
        QVERIFY2(
            difference <= 0.03f, qPrintable(QStringLiteral("%1 differs by %2").arg(channel).arg(difference)));
    }
    // The inspector's box levels start from level 0 written out densely.
    const float level1 = largestDifference(m_gl.renderer->readVoxels("bounced", 1, size), denseLevel1);
    QVERIFY2(level1 <= 0.03f, qPrintable(QStringLiteral("level 1 differs by %1").arg(level1)));
    const double relative = io::ImageMetrics::relativeMse(sparse.image, dense.image);
    const double largest = largestPixelDifference(sparse.image, dense.image);
    qInfo("relative MSE %.2g, largest pixel difference %.2g of the peak", relative, largest);
    QVERIFY2(relative < 1e-3 && largest < 0.03,
        qPrintable(QStringLiteral("relative MSE %1, largest pixel difference %2 of the peak")
                       .arg(relative)
                       .arg(largest)));
}

// Empty bricks cost nothing but their table entry: on a scene whose walls fill a small part of the grid the
// sparse grid takes far less memory, and GL's own sizes of its pools agree with what the renderer counts.
void SparseVoxelsTest::storesOnlyTheBricksReached()
{
    render::Scene loaded;
    QString error;
    QVERIFY2(doc::SceneLoader::load(QStringLiteral("builtin:atrium"), loaded, &error), qPrintable(error));
    m_gl.renderer->setScene(loaded);
    render::RenderSettings settings;
    settings.voxelResolution = 128;
    settings.shadowMapSize = 256;
    settings.bounces = 1;
    const Frame dense = render(settings, loaded.camera);
    settings.voxelMode = render::VoxelMode::Sparse;
    const Frame sparse = render(settings, loaded.camera);
    QCOMPARE(sparse.stats.occupiedVoxels, dense.stats.occupiedVoxels);
    std::size_t pools = 0, table = 0;
    for (const render::VoxelTextureMemory& texture : m_gl.renderer->voxelMemory()) {
        QVERIFY2(texture.glBytes >= texture.totalBytes(), texture.name.c_str());
        if (texture.name == "albedo" || texture.name == "normal" || texture.name == "radiance")
            pools += texture.totalBytes();
        if (texture.name == "brick table")
            table += texture.totalBytes();
    }
    QCOMPARE(table, std::size_t(16 * 16 * 16 * 4));
    const std::size_t denseLevel0 = std::size_t(128) * 128 * 128 * (4 + 4 + 8);
    // The atrium's surfaces reach a fifth of its 8^3 bricks (docs/DESIGN.md, "Sparse storage").
    QVERIFY2(pools < denseLevel0 / 2,
        qPrintable(QStringLiteral("pools %1 bytes against %2 dense").arg(pools).arg(denseLevel0)));
    QVERIFY(sparse.stats.voxelBytes < dense.stats.voxelBytes);
}

// A dynamic object moved into bricks nothing reached before takes new ones (core/BrickPool keeps the slots
// it had), and the image stays the dense grid's, move after move.
void SparseVoxelsTest::dynamicObjectMovesIntoEmptyBricks()
{
    const render::Scene scene = test::floorAndDynamicPlate();
    const render::Camera camera { { 8, 8, 30 }, { 8, 4, 8 }, { 0, 1, 0 }, 40.0f, 0.01f };
    const glm::vec3 moves[] = { { 6.0f, 0.0f, 0.0f }, { 6.0f, 6.0f, 6.0f }, { 0.0f, 9.0f, 8.0f } };
    std::vector<render::RadianceImage> images[2];
    for (const bool sparse : { false, true }) {
        render::RenderSettings settings;
        settings.voxelResolution = 32;
        settings.shadowMapSize = 256;
        settings.voxelMode = sparse ? render::VoxelMode::Sparse : render::VoxelMode::Dense;
        m_gl.renderer->setSettings(settings);
        m_gl.renderer->setScene(scene);
        m_gl.renderer->setGridBounds(test::box(glm::vec3(0.0f), glm::vec3(16.0f)));
        render(settings, camera);
        for (const glm::vec3& move : moves) {
            m_gl.renderer->setMeshTransform(1, glm::translate(glm::mat4(1.0f), move));
            images[sparse].push_back(render(settings, camera).image);
        }
    }
    m_gl.renderer->setGridBounds({});
    for (std::size_t i = 0; i < images[0].size(); ++i) {
        const double relative = io::ImageMetrics::relativeMse(images[1][i], images[0][i]);
        QVERIFY2(
            relative < 1e-3, qPrintable(QStringLiteral("move %1: relative MSE %2").arg(i).arg(relative)));
    }
    // The plate's light on the floor below it moved with it: the images differ from move to move.
    const double moved = io::ImageMetrics::relativeMse(images[1][0], images[1][2]);
    QVERIFY2(moved > 1e-4, qPrintable(QStringLiteral("relative MSE between the moves %1").arg(moved)));
}

// Triangles sloped across all three axes: the voxelizer's depth spread then reaches up to two voxels from a
// triangle (BrickPool's reach), where the boxes and walls of the other scenes reach one. Every voxel a dense
// grid lists must have its brick.
void SparseVoxelsTest::slopedTrianglesLoseNoVoxel()
{
    const render::Camera camera { { 8, 8, 30 }, { 8, 8, 8 }, { 0, 1, 0 }, 40.0f, 0.01f };
    const auto occupied = [&](const std::vector<glm::vec3>& triangles, render::VoxelMode mode) {
        render::Scene scene;
        scene.materials.push_back({});
        scene.meshes.push_back(test::makeTriangles(triangles));
        scene.pointLights.push_back({ { 8, 20, 8 }, glm::vec3(50.0f), true });
        m_gl.renderer->setScene(scene);
        m_gl.renderer->setGridBounds(test::box(glm::vec3(0.0f), glm::vec3(16.0f)));
        render::RenderSettings settings;
        settings.voxelResolution = 64;
        settings.shadowMapSize = 256;
        settings.bounces = 1;
        settings.voxelMode = mode;
        const std::size_t count = render(settings, camera).stats.occupiedVoxels;
        m_gl.renderer->setGridBounds({});
        return count;
    };
    // One found by a model of the voxelizer: with bricks for one voxel of reach it lost three of its 44
    // voxels, 1.4 voxels from the triangle along the projection axis.
    const std::vector<glm::vec3> found { glm::vec3(39.07f, 29.35f, 22.57f) / 4.0f,
        glm::vec3(35.93f, 32.88f, 22.55f) / 4.0f, glm::vec3(36.67f, 36.22f, 19.33f) / 4.0f };
    const std::size_t dense = occupied(found, render::VoxelMode::Dense);
    QVERIFY(dense > 20);
    QCOMPARE(occupied(found, render::VoxelMode::Sparse), dense);
    std::mt19937 random(11);
    std::uniform_real_distribution<float> corner(1.0f, 15.0f), offset(-1.0f, 1.0f);
    std::vector<glm::vec3> many;
    for (int i = 0; i < 4000; ++i) {
        const glm::vec3 a(corner(random), corner(random), corner(random));
        many.push_back(a);
        many.push_back(a + glm::vec3(offset(random), offset(random), offset(random)));
        many.push_back(a + glm::vec3(offset(random), offset(random), offset(random)));
    }
    const std::size_t denseMany = occupied(many, render::VoxelMode::Dense);
    QVERIFY(denseMany > 1000);
    QCOMPARE(occupied(many, render::VoxelMode::Sparse), denseMany);
}

void SparseVoxelsTest::refusesBoxMips()
{
    render::RenderSettings settings;
    settings.voxelMode = render::VoxelMode::Sparse;
    settings.anisotropicMips = false;
    QVERIFY(settings.validate().find("anisotropic=on") != std::string::npos);
    render::RenderSettings parsed;
    QVERIFY(parsed.set("voxel_mode", "sparse").empty());
    QCOMPARE(parsed.voxelMode, render::VoxelMode::Sparse);
    QVERIFY(!parsed.set("voxel_mode", "bricks").empty());
    // 512^3 dense is over the default budget; sparse counts its pools once it knows its bricks, so the two
    // settings given together are valid in either order (the command line gives them so).
    render::RenderSettings fine;
    QVERIFY(!fine.set("voxel_res", "512").empty());
    QVERIFY2(fine.setAll({ { "voxel_res", "512" }, { "voxel_mode", "sparse" } }).empty(),
        fine.setAll({ { "voxel_res", "512" }, { "voxel_mode", "sparse" } }).c_str());
    QCOMPARE(fine.voxelResolution, 512);
    QVERIFY(!fine.setAll({ { "voxel_mode", "dense" }, { "anisotropic", "maybe" } }).empty());
    QCOMPARE(fine.voxelMode, render::VoxelMode::Sparse); // nothing applied when one is wrong
}

QTEST_GUILESS_MAIN(SparseVoxelsTest)
#include "tst_SparseVoxels.moc"
