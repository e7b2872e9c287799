#include "BuiltinScenes.h"
#include "GlTestContext.h"
#include "TestSupport.h"

#include <glm/geometric.hpp>

#include <QtTest>

#include <set>
#include <tuple>

using namespace vct;

namespace {

using Voxel = std::tuple<int, int, int>;

// Exact triangle / axis-aligned box overlap by the separating axis theorem (Akenine-Moeller).
bool triangleOverlapsBox(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 center, float half)
{
    a -= center;
    b -= center;
    c -= center;
    const glm::vec3 e[3] = { b - a, c - b, a - c };
    const glm::vec3 axesUnit[3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
    auto separated = [&](const glm::vec3& axis) {
        const float pa = glm::dot(a, axis), pb = glm::dot(b, axis), pc = glm::dot(c, axis);
        const float r = half * (std::abs(axis.x) + std::abs(axis.y) + std::abs(axis.z));
        return std::min({ pa, pb, pc }) > r || std::max({ pa, pb, pc }) < -r;
    };
    for (const glm::vec3& u : axesUnit)
        for (const glm::vec3& edge : e)
            if (separated(glm::cross(u, edge)))
                return false;
    for (const glm::vec3& u : axesUnit)
        if (separated(u))
            return false;
    return !separated(glm::cross(e[0], e[1]));
}

std::set<Voxel> occupiedVoxels(render::Renderer& renderer)
{
    int size = 0;
    const std::vector<float> albedo = renderer.readVoxels("albedo", 0, size);
    std::set<Voxel> voxels;
    for (int z = 0; z < size; ++z)
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x)
                if (albedo[((std::size_t(z) * size + y) * size + x) * 4 + 3] > 0.5f)
                    voxels.insert({ x, y, z });
    return voxels;
}

std::set<Voxel> expectedConservative(const render::Renderer& renderer, glm::vec3 a, glm::vec3 b, glm::vec3 c)
{
    std::set<Voxel> voxels;
    const int n = renderer.voxelResolution();
    const float v = renderer.voxelSize();
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const glm::vec3 center = renderer.gridOrigin() + (glm::vec3(x, y, z) + 0.5f) * v;
                // A hair inside the box so touching at a face or edge does not count.
                if (triangleOverlapsBox(a, b, c, center, 0.5f * v * 0.999f))
                    voxels.insert({ x, y, z });
            }
    return voxels;
}

// A sphere of `rings` x 2 `rings` quads: triangles well under a voxel for the grids below, with smooth
// normals and uvs running once around (u) and from pole to pole (v).
render::Mesh makeSphere(glm::vec3 centre, float radius, int rings, int material)
{
    render::Mesh mesh;
    mesh.material = material;
    const int segments = 2 * rings;
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s <= segments; ++s) {
            const float theta = 3.14159265f * float(r) / float(rings);
            const float phi = 6.28318531f * float(s) / float(segments);
            const glm::vec3 n(
                std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            mesh.positions.push_back(centre + radius * n);
            mesh.normals.push_back(n);
            mesh.uvs.push_back({ float(s) / float(segments), float(r) / float(rings) });
        }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const std::uint32_t a = std::uint32_t(r * (segments + 1) + s), b = a + 1,
                                c = a + std::uint32_t(segments + 1), d = c + 1;
            mesh.indices.insert(mesh.indices.end(), { a, c, b, b, c, d });
        }
    return mesh;
}

struct VoxelValues {
    std::vector<float> albedo, normal, emission;
    int size = 0;
};

QString describe(const std::set<Voxel>& s)
{
    QStringList parts;
    for (const auto& [x, y, z] : s)
        parts << QString("(%1,%2,%3)").arg(x).arg(y).arg(z);
    return parts.join(' ');
}

} // namespace

class VoxelizationTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void knownTriangleGivesExactlyItsVoxels_data();
    void knownTriangleGivesExactlyItsVoxels();
    void tiltedTriangleIsCoveredConservatively();
    void subVoxelSliverNeedsConservativeVoxelization();
    void overlappingSurfacesAverage();
    void manySurfacesAverageWithinQuantization();
    void opposingFacesCancelTheirNormals();
    void smallTrianglesMatchTheRasterizer_data();
    void smallTrianglesMatchTheRasterizer();
    void atriumVoxelsTheSameEitherWay();
    void edgesThroughPixelCentresMatchTheRasterizer_data();
    void edgesThroughPixelCentresMatchTheRasterizer();
    void noGlErrors();

private:
    /** Voxelizes @p scene into a 16^3 grid over [1, 15]^3 m. */
    void renderOnSixteenCubed(const render::Scene& scene);
    void voxelize(
        const std::vector<glm::vec3>& triangles, bool conservative, glm::vec3 albedo = glm::vec3(0.5f));
    VoxelValues voxelizeAtResolution(const render::Scene& scene, const render::RenderSettings& settings);
    test::GlTestContext m_gl;
};

void VoxelizationTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
}

// A 16^3 grid over [0, 16]^3 after fitting: the bounds are chosen so voxels are 1 unit and start at 0.
void VoxelizationTest::voxelize(const std::vector<glm::vec3>& triangles, bool conservative, glm::vec3 albedo)
{
    render::Scene scene;
    render::Material material;
    material.albedo = albedo;
    scene.materials.push_back(material);
    scene.meshes.push_back(test::makeTriangles(triangles));
    render::RenderSettings settings;
    settings.voxelResolution = 16;
    settings.conservativeVoxelization = conservative;
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(scene);
    m_gl.renderer->setGridBounds(test::box(glm::vec3(1.0f), glm::vec3(15.0f)));
    // fit() adds one cell on each side: the 16^3 grid spans exactly [0, 16]^3.
    m_gl.renderer->renderFrame(render::Camera {}, 8, 8);
    QVERIFY(std::abs(m_gl.renderer->voxelSize() - 1.0f) < 1e-5f);
    QVERIFY(glm::length(m_gl.renderer->gridOrigin()) < 1e-5f);
}

void VoxelizationTest::knownTriangleGivesExactlyItsVoxels_data()
{
    QTest::addColumn<bool>("conservative");
    QTest::addColumn<float>("leg");
    // Legs of 7.5 voxels go through the rasteriser; of 2.7 (pixel bounds 3.7 wide with the enlargement),
    // through the compute path for small triangles (voxelize/VoxelizeSmall.comp).
    QTest::newRow("conservative, rasterised") << true << 7.5f;
    QTest::newRow("plain, rasterised") << false << 7.5f;
    QTest::newRow("conservative, small") << true << 2.7f;
    QTest::newRow("plain, small") << false << 2.7f;
}

void VoxelizationTest::knownTriangleGivesExactlyItsVoxels()
{
    QFETCH(bool, conservative);
    QFETCH(float, leg);
    // A right isosceles triangle in the plane z = 5.3, legs along x and y: its exact voxel set is known both
    // ways. Plain rasterisation keeps voxels whose column centre lies inside; conservative keeps every voxel
    // the triangle touches.
    const glm::vec3 a(2.2f, 3.2f, 5.3f), b(2.2f + leg, 3.2f, 5.3f), c(2.2f, 3.2f + leg, 5.3f);
    voxelize({ a, b, c }, conservative);
    const std::set<Voxel> actual = occupiedVoxels(*m_gl.renderer);
    std::set<Voxel> expected;
    if (conservative) {
        expected = expectedConservative(*m_gl.renderer, a, b, c);
    } else {
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                const float px = x + 0.5f, py = y + 0.5f;
                if (px > a.x && py > a.y && (px - a.x) + (py - a.y) < (b.x - a.x))
                    expected.insert({ x, y, 5 });
            }
    }
    QVERIFY(!expected.empty());
    QVERIFY2(actual == expected,
        qPrintable(QString("actual %1\nexpected %2").arg(describe(actual), describe(expected))));
}

void VoxelizationTest::tiltedTriangleIsCoveredConservatively()
{
    const glm::vec3 a(2.3f, 2.6f, 3.1f), b(12.4f, 5.2f, 9.7f), c(4.9f, 13.1f, 6.2f);
    voxelize({ a, b, c }, true);
    const std::set<Voxel> actual = occupiedVoxels(*m_gl.renderer);
    const std::set<Voxel> expected = expectedConservative(*m_gl.renderer, a, b, c);
    std::set<Voxel> missing;
    for (const Voxel& v : expected)
        if (!actual.count(v))
            missing.insert(v);
    QVERIFY2(missing.empty(), qPrintable("missing " + describe(missing)));
    // Enlargement overshoots near acute corners and in depth; keep the excess modest.
    QVERIFY2(actual.size() <= expected.size() * 3 / 2,
        qPrintable(QString("%1 voxels for %2 touched").arg(actual.size()).arg(expected.size())));
}

void VoxelizationTest::subVoxelSliverNeedsConservativeVoxelization()
{
    // 0.1 voxel wide, between pixel centres: no column centre lies inside it.
    const std::vector<glm::vec3> sliver
        = { { 2.1f, 6.55f, 4.5f }, { 13.9f, 6.6f, 4.5f }, { 2.1f, 6.65f, 4.5f } };
    voxelize(sliver, false);
    QCOMPARE(occupiedVoxels(*m_gl.renderer).size(), std::size_t(0));
    voxelize(sliver, true);
    const std::set<Voxel> kept = occupiedVoxels(*m_gl.renderer);
    const std::set<Voxel> expected = expectedConservative(*m_gl.renderer, sliver[0], sliver[1], sliver[2]);
    QVERIFY(!expected.empty());
    QVERIFY2(kept == expected,
        qPrintable(QString("kept %1\nexpected %2").arg(describe(kept), describe(expected))));
}

void VoxelizationTest::renderOnSixteenCubed(const render::Scene& scene)
{
    render::RenderSettings settings;
    settings.voxelResolution = 16;
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(scene);
    m_gl.renderer->setGridBounds(test::box(glm::vec3(1.0f), glm::vec3(15.0f)));
    m_gl.renderer->renderFrame(render::Camera {}, 8, 8);
}

void VoxelizationTest::overlappingSurfacesAverage()
{
    // Two coplanar quads with different albedos over the same voxels: the voxel holds the mean. Only the blue
    // one emits; it is voxelized by the emissive shader variant, the red one by the plain one, and the
    // voxel's emission is still the mean over both.
    render::Scene scene;
    render::Material red, blue;
    red.albedo = glm::vec3(0.8f, 0.0f, 0.0f);
    blue.albedo = glm::vec3(0.0f, 0.0f, 0.4f);
    blue.emission = glm::vec3(3.0f, 2.0f, 1.0f);
    scene.materials = { red, blue };
    const auto q
        = test::quad({ 4.2f, 4.2f, 7.5f }, { 8.8f, 4.2f, 7.5f }, { 8.8f, 8.8f, 7.5f }, { 4.2f, 8.8f, 7.5f });
    scene.meshes.push_back(test::makeTriangles(q, 0));
    scene.meshes.push_back(test::makeTriangles(q, 1));
    renderOnSixteenCubed(scene);
    int size = 0;
    const std::vector<float> albedo = m_gl.renderer->readVoxels("albedo", 0, size);
    const std::size_t i = ((std::size_t(7) * size + 6) * size + 6) * 4; // an interior voxel of the quads
    QVERIFY(std::abs(albedo[i + 0] - 0.4f) < 1.5f / 255.0f);
    QVERIFY(std::abs(albedo[i + 2] - 0.2f) < 1.5f / 255.0f);
    QCOMPARE(albedo[i + 3], 1.0f);
    const std::vector<float> emission = m_gl.renderer->readVoxels("emission", 0, size);
    for (int c = 0; c < 3; ++c)
        QVERIFY2(std::abs(emission[i + std::size_t(c)] - 0.5f * blue.emission[c]) < 1e-3f,
            qPrintable(QString("emission channel %1: %2").arg(c).arg(emission[i + std::size_t(c)])));
}

void VoxelizationTest::manySurfacesAverageWithinQuantization()
{
    // The voxelizer keeps a running mean in 8-bit albedo and 11/10-bit float emission
    // (common/VoxelWords.glsl): twelve coplanar quads with albedos and emissions from dark to bright must
    // still average to their mean, whatever order the fragments arrive in, within a few steps of the stored
    // precision.
    render::Scene scene;
    const auto q
        = test::quad({ 4.2f, 4.2f, 7.5f }, { 8.8f, 4.2f, 7.5f }, { 8.8f, 8.8f, 7.5f }, { 4.2f, 8.8f, 7.5f });
    constexpr int kSurfaces = 12;
    glm::vec3 meanAlbedo(0.0f), meanEmission(0.0f);
    for (int k = 0; k < kSurfaces; ++k) {
        render::Material m;
        const float t = float(k) / float(kSurfaces - 1);
        m.albedo = glm::vec3(t, 1.0f - t, 0.5f);
        m.emission = glm::vec3(0.1f + 4.0f * t, 2.0f, 0.0f);
        meanAlbedo += m.albedo / float(kSurfaces);
        meanEmission += m.emission / float(kSurfaces);
        scene.materials.push_back(m);
        scene.meshes.push_back(test::makeTriangles(q, k));
    }
    renderOnSixteenCubed(scene);
    int size = 0;
    const std::vector<float> albedo = m_gl.renderer->readVoxels("albedo", 0, size);
    const std::vector<float> emission = m_gl.renderer->readVoxels("emission", 0, size);
    const std::size_t i = ((std::size_t(7) * size + 6) * size + 6) * 4;
    for (int c = 0; c < 3; ++c) {
        QVERIFY2(std::abs(albedo[i + std::size_t(c)] - meanAlbedo[c]) < 3.0f / 255.0f,
            qPrintable(QString("albedo channel %1: %2, mean %3")
                           .arg(c)
                           .arg(albedo[i + std::size_t(c)])
                           .arg(meanAlbedo[c])));
        QVERIFY2(std::abs(emission[i + std::size_t(c)] - meanEmission[c]) <= 0.02f * meanEmission[c],
            qPrintable(QString("emission channel %1: %2, mean %3")
                           .arg(c)
                           .arg(emission[i + std::size_t(c)])
                           .arg(meanEmission[c])));
    }
    QCOMPARE(albedo[i + 3], 1.0f);
}

void VoxelizationTest::opposingFacesCancelTheirNormals()
{
    // Two faces of a thin wall in one voxel: their normals cancel, which lighting reads as a two-sided voxel;
    // a lone face keeps a unit normal within the 8-bit precision.
    render::Scene scene;
    scene.materials = { render::Material {} };
    const auto up
        = test::quad({ 4.2f, 4.2f, 7.5f }, { 8.8f, 4.2f, 7.5f }, { 8.8f, 8.8f, 7.5f }, { 4.2f, 8.8f, 7.5f });
    const auto down
        = test::quad({ 4.2f, 4.2f, 7.6f }, { 4.2f, 8.8f, 7.6f }, { 8.8f, 8.8f, 7.6f }, { 8.8f, 4.2f, 7.6f });
    const auto lone = test::quad(
        { 4.2f, 4.2f, 11.2f }, { 8.8f, 4.2f, 11.2f }, { 8.8f, 8.8f, 11.2f }, { 4.2f, 8.8f, 11.2f });
    for (const auto& quad : { up, down, lone })
        scene.meshes.push_back(test::makeTriangles(quad, 0));
    renderOnSixteenCubed(scene);
    int size = 0;
    const std::vector<float> normal = m_gl.renderer->readVoxels("normal", 0, size);
    auto at = [&](int z) {
        const std::size_t i = ((std::size_t(z) * size + 6) * size + 6) * 4;
        return glm::vec4(normal[i], normal[i + 1], normal[i + 2], normal[i + 3]);
    };
    QVERIFY2(glm::length(glm::vec3(at(7))) < 0.02f,
        qPrintable(QString("wall: |n| %1").arg(glm::length(glm::vec3(at(7))))));
    const glm::vec4 face = at(11);
    QVERIFY2(std::abs(face.z - 1.0f) < 0.01f, qPrintable(QString("face: n.z %1").arg(face.z)));
    QCOMPARE(face.w, 0.0f);
}

VoxelValues VoxelizationTest::voxelizeAtResolution(
    const render::Scene& scene, const render::RenderSettings& settings)
{
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(scene);
    m_gl.renderer->setGridBounds(test::box(glm::vec3(1.0f), glm::vec3(15.0f)));
    m_gl.renderer->renderFrame(render::Camera {}, 8, 8);
    VoxelValues v;
    v.albedo = m_gl.renderer->readVoxels("albedo", 0, v.size);
    v.normal = m_gl.renderer->readVoxels("normal", 0, v.size);
    v.emission = m_gl.renderer->readVoxels("emission", 0, v.size);
    return v;
}

void VoxelizationTest::smallTrianglesMatchTheRasterizer_data()
{
    QTest::addColumn<bool>("conservative");
    QTest::addColumn<bool>("textured");
    QTest::newRow("conservative") << true << false;
    QTest::newRow("plain") << false << false;
    QTest::newRow("conservative, textured") << true << true;
    QTest::newRow("plain, textured") << false << true;
}

void VoxelizationTest::smallTrianglesMatchTheRasterizer()
{
    // Spheres of triangles a few tenths of a voxel wide, one emissive, and a large quad through both, whose
    // fragments mix with theirs in the same voxels: voxelized with the compute path for small triangles, the
    // grid holds the voxels the rasteriser gives them, with the same material to within the running means'
    // dependence on the order of arrival.
    QFETCH(bool, conservative);
    QFETCH(bool, textured);
    render::Scene scene;
    render::Material grey, lamp, wall;
    grey.albedo = glm::vec3(0.6f, 0.5f, 0.4f);
    lamp.albedo = glm::vec3(0.2f, 0.3f, 0.9f);
    lamp.emission = glm::vec3(2.0f, 1.0f, 0.5f);
    wall.albedo = glm::vec3(0.9f, 0.1f, 0.1f);
    if (textured) {
        // Stripes along u: what each voxel gets depends on where and at what level the texture is read.
        render::TextureImage stripes;
        stripes.width = 64;
        stripes.height = 4;
        for (int y = 0; y < stripes.height; ++y)
            for (int x = 0; x < stripes.width; ++x) {
                const std::uint8_t value = (x / 8) % 2 ? 255 : 40;
                stripes.rgba.insert(stripes.rgba.end(), { value, std::uint8_t(255 - value), 128, 255 });
            }
        scene.textures.push_back(stripes);
        grey.albedoTexture = 0;
        lamp.albedoTexture = 0; // the emissive and textured variant too
    }
    scene.materials = { grey, lamp, wall };
    scene.meshes.push_back(makeSphere({ 6.3f, 7.9f, 8.1f }, 3.7f, 40, 0));
    scene.meshes.push_back(makeSphere({ 11.2f, 9.4f, 7.3f }, 2.1f, 24, 1));
    scene.meshes.push_back(test::makeTriangles(test::quad({ 2.3f, 2.2f, 8.45f }, { 13.6f, 2.2f, 8.45f },
                                                   { 13.6f, 13.7f, 8.45f }, { 2.3f, 13.7f, 8.45f }),
        2));
    render::RenderSettings settings;
    settings.voxelResolution = 32;
    settings.conservativeVoxelization = conservative;
    settings.smallTrianglesByCompute = false;
    const VoxelValues raster = voxelizeAtResolution(scene, settings);
    settings.smallTrianglesByCompute = true;
    const VoxelValues compute = voxelizeAtResolution(scene, settings);
    QCOMPARE(compute.size, 32);
    QCOMPARE(raster.size, 32);

    int occupied = 0, onlyRaster = 0, onlyCompute = 0, emitting = 0;
    float albedoError = 0.0f, emissionError = 0.0f, normalError = 0.0f;
    for (std::size_t i = 0; i < raster.albedo.size(); i += 4) {
        const bool inRaster = raster.albedo[i + 3] > 0.5f, inCompute = compute.albedo[i + 3] > 0.5f;
        onlyRaster += inRaster && !inCompute;
        onlyCompute += inCompute && !inRaster;
        if (!inRaster || !inCompute)
            continue;
        ++occupied;
        emitting += raster.emission[i] > 0.0f;
        for (std::size_t c = 0; c < 3; ++c) {
            albedoError = std::max(albedoError, std::abs(raster.albedo[i + c] - compute.albedo[i + c]));
            emissionError = std::max(emissionError,
                std::abs(raster.emission[i + c] - compute.emission[i + c])
                    / std::max(lamp.emission[int(c)], 1e-6f));
            normalError = std::max(normalError, std::abs(raster.normal[i + c] - compute.normal[i + c]));
        }
    }
    const QString summary
        = QString("%1 voxels in both, %2 only rasterised, %3 only by the compute path; largest "
                  "differences: albedo %4, emission %5 (of the lamp's), normal %6")
              .arg(occupied)
              .arg(onlyRaster)
              .arg(onlyCompute)
              .arg(albedoError)
              .arg(emissionError)
              .arg(normalError);
    qInfo("%s", qPrintable(summary));
    QVERIFY2(occupied > 1000 && emitting > 100, qPrintable(summary));
    QVERIFY2(onlyRaster == 0 && onlyCompute == 0, qPrintable(summary));
    // The running means (common/VoxelWords.glsl) round to 8 bits at every step, in whatever order the
    // fragments arrive; the two paths only change that order.
    QVERIFY2(albedoError < 0.05f && emissionError < 0.05f && normalError < 0.1f, qPrintable(summary));
}

void VoxelizationTest::atriumVoxelsTheSameEitherWay()
{
    // The built-in atrium as a user opens it: tens of thousands of column triangles under a voxel, walls
    // lying on voxel boundaries (where weights summing to a hair under one once put a wall's triangles in the
    // voxel below: 1,390 voxels the rasteriser does not give), and the bunny, dynamic.
    render::Scene scene;
    QString error;
    QVERIFY2(doc::BuiltinScenes::load("atrium", scene, &error), qPrintable(error));
    std::vector<float> albedo[2];
    int size = 0;
    for (const bool compute : { false, true }) {
        render::RenderSettings settings;
        settings.smallTrianglesByCompute = compute;
        m_gl.renderer->setSettings(settings);
        m_gl.renderer->setScene(scene);
        m_gl.renderer->renderFrame(render::Camera {}, 8, 8);
        albedo[compute] = m_gl.renderer->readVoxels("albedo", 0, size);
    }
    QCOMPARE(size, 128);
    int occupied = 0, onlyRaster = 0, onlyCompute = 0;
    for (std::size_t i = 3; i < albedo[0].size(); i += 4) {
        const bool raster = albedo[0][i] > 0.5f, compute = albedo[1][i] > 0.5f;
        occupied += raster;
        onlyRaster += raster && !compute;
        onlyCompute += compute && !raster;
    }
    const QString summary = QString("%1 voxels rasterised; %2 of them missing with the compute path, %3 more")
                                .arg(occupied)
                                .arg(onlyRaster)
                                .arg(onlyCompute);
    QVERIFY2(occupied > 50000 && onlyRaster == 0 && onlyCompute == 0, qPrintable(summary));
}

void VoxelizationTest::edgesThroughPixelCentresMatchTheRasterizer_data()
{
    QTest::addColumn<bool>("conservative");
    QTest::addColumn<float>("offset");
    // Plain: corners on pixel centres, so edges (along the axes and the diagonals) pass through rows of them.
    QTest::newRow("plain, corners on pixel centres") << false << 0.5f;
    // Conservative: corners on voxel corners, so the enlarged edges along the axes land on pixel centres.
    QTest::newRow("conservative, corners on voxel corners") << true << 0.0f;
}

void VoxelizationTest::edgesThroughPixelCentresMatchTheRasterizer()
{
    // A 10 x 10 voxel plane of 2 x 2 voxel quads, each split along a diagonal (both ways, alternately), in
    // the plane z = 5.3: every triangle small enough for the compute path, every shared edge through pixel
    // centres or, enlarged, on them. A centre exactly on an edge must go to the same one of its two triangles
    // as the rasteriser's fill rule gives it, or neither path's voxels would match the other's.
    QFETCH(bool, conservative);
    QFETCH(float, offset);
    std::vector<glm::vec3> triangles;
    for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 5; ++i) {
            const float x = 3.0f + offset + 2.0f * float(i), y = 3.0f + offset + 2.0f * float(j);
            const glm::vec3 a(x, y, 5.3f), b(x + 2.0f, y, 5.3f), c(x + 2.0f, y + 2.0f, 5.3f),
                d(x, y + 2.0f, 5.3f);
            if ((i + j) % 2 == 0)
                triangles.insert(triangles.end(), { a, b, c, a, c, d });
            else
                triangles.insert(triangles.end(), { a, b, d, b, c, d });
        }
    std::set<Voxel> voxels[2];
    for (const bool compute : { false, true }) {
        render::Scene scene;
        scene.materials.push_back(render::Material {});
        scene.meshes.push_back(test::makeTriangles(triangles));
        render::RenderSettings settings;
        settings.voxelResolution = 16;
        settings.conservativeVoxelization = conservative;
        settings.smallTrianglesByCompute = compute;
        m_gl.renderer->setSettings(settings);
        m_gl.renderer->setScene(scene);
        m_gl.renderer->setGridBounds(test::box(glm::vec3(1.0f), glm::vec3(15.0f)));
        m_gl.renderer->renderFrame(render::Camera {}, 8, 8);
        voxels[compute] = occupiedVoxels(*m_gl.renderer);
    }
    QVERIFY(voxels[0].size() > 50);
    QVERIFY2(voxels[0] == voxels[1],
        qPrintable(QString("rasterised %1\ncompute path %2").arg(describe(voxels[0]), describe(voxels[1]))));
}

void VoxelizationTest::noGlErrors()
{
    const auto errors = m_gl.renderer->takeGlErrors();
    QVERIFY2(errors.empty(), errors.empty() ? "" : errors.front().c_str());
}

QTEST_GUILESS_MAIN(VoxelizationTest)
#include "tst_Voxelization.moc"
