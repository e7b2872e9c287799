#include "GlTestContext.h"
#include "TestSupport.h"

#include <QtTest>

using namespace vct;

namespace {

/** The box [lo, hi] as twelve triangles, counter-clockwise seen from outside: a closed, solid mesh. */
std::vector<glm::vec3> solidBox(glm::vec3 lo, glm::vec3 hi)
{
    const auto corner
        = [&](int c) { return glm::vec3(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z); };
    static const int kFaces[6][4]
        = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
    std::vector<glm::vec3> triangles;
    for (const auto& f : kFaces) {
        const std::vector<glm::vec3> q = test::quad(corner(f[0]), corner(f[1]), corner(f[2]), corner(f[3]));
        triangles.insert(triangles.end(), q.begin(), q.end());
    }
    return triangles;
}

} // namespace

Q_DECLARE_METATYPE(render::Camera)
Q_DECLARE_METATYPE(glm::vec3)

/**
 * View culling (RenderSettings::viewCulling) leaves out what a view cannot see: clusters outside its frustum
 * and the back faces of closed meshes seen from outside. It must never change the image: every case here
 * renders with it on and off and requires the same pixels, including the views where back faces are the
 * nearest surface (an eye inside a solid, a near plane cutting into one, a light inside one), where culling
 * must stay off.
 */
class ViewCullingTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void sameImage_data();
    void sameImage();
    void singleSidedSolidsLookTheSameFromOutside();
    void singleSidedSurfacesShowTheirFrontOnly();

private:
    render::RadianceImage renderWith(bool culling, const render::Camera& camera, const glm::vec3& light);
    static double largestDifference(const render::RadianceImage& a, const render::RadianceImage& b);
    test::GlTestContext m_gl;
    render::Scene m_scene;
};

double ViewCullingTest::largestDifference(const render::RadianceImage& a, const render::RadianceImage& b)
{
    double worst = 0.0;
    for (std::size_t i = 0; i < b.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            worst
                = std::max(worst, double(std::abs(a.pixels[i][c] - b.pixels[i][c])) / (1.0 + b.pixels[i][c]));
    return worst;
}

void ViewCullingTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
    render::Material floor, block, glossy;
    floor.albedo = glm::vec3(0.6f, 0.55f, 0.5f);
    block.albedo = glm::vec3(0.2f, 0.5f, 0.8f);
    glossy.albedo = glm::vec3(0.7f, 0.3f, 0.2f);
    glossy.specular = glm::vec3(0.3f);
    glossy.shininess = 40.0f;
    m_scene.materials = { floor, block, glossy };
    // An open floor (never culled), and a solid box and a solid glossy slab just above it: no two surfaces
    // coincide, since which of two wins the depth test would then depend on the drawing order.
    m_scene.meshes.push_back(
        test::makeTriangles(test::quad({ 1, 1, 15 }, { 15, 1, 15 }, { 15, 1, 1 }, { 1, 1, 1 }), 0));
    m_scene.meshes.push_back(test::makeTriangles(solidBox({ 5, 1.2f, 5 }, { 9, 5, 9 }), 1));
    m_scene.meshes.push_back(test::makeTriangles(solidBox({ 10, 1.1f, 3 }, { 13, 2, 12 }), 2));
    m_scene.pointLights.push_back({});
}

render::RadianceImage ViewCullingTest::renderWith(
    bool culling, const render::Camera& camera, const glm::vec3& light)
{
    m_scene.pointLights[0].position = light;
    m_scene.pointLights[0].intensity = glm::vec3(40.0f);
    m_scene.pointLights[0].castsShadows = true;
    render::RenderSettings settings;
    settings.voxelResolution = 32;
    settings.shadowMapSize = 256;
    settings.viewCulling = culling;
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(m_scene);
    m_gl.renderer->setGridBounds(test::box(glm::vec3(0.5f), glm::vec3(15.5f)));
    m_gl.renderer->renderFrame(camera, 64, 48);
    return m_gl.renderer->readFrame();
}

void ViewCullingTest::sameImage_data()
{
    QTest::addColumn<render::Camera>("camera");
    QTest::addColumn<glm::vec3>("light");
    const glm::vec3 up(0, 1, 0);
    const glm::vec3 overhead(8, 12, 8);
    QTest::newRow("outside everything")
        << render::Camera { { 2, 7, 16 }, { 8, 2, 6 }, up, 60.0f, 0.05f } << overhead;
    QTest::newRow("most of it outside the view")
        << render::Camera { { 8, 6, 14 }, { 14, 1, 13 }, up, 40.0f, 0.05f } << overhead;
    QTest::newRow("eye inside the box")
        << render::Camera { { 7, 3, 7 }, { 9, 2, 8.5f }, up, 70.0f, 0.05f } << overhead;
    // 2 cm in front of the box's +z face with a 5 cm near plane: the near plane cuts into the box.
    QTest::newRow("near plane inside the box")
        << render::Camera { { 7, 3, 9.02f }, { 7, 3, 0 }, up, 60.0f, 0.05f } << overhead;
    QTest::newRow("light inside the slab")
        << render::Camera { { 2, 7, 16 }, { 8, 2, 6 }, up, 60.0f, 0.05f } << glm::vec3(11.5f, 1.5f, 7.5f);
}

void ViewCullingTest::sameImage()
{
    QFETCH(render::Camera, camera);
    QFETCH(glm::vec3, light);
    const render::RadianceImage culled = renderWith(true, camera, light);
    const render::RadianceImage full = renderWith(false, camera, light);
    double sum = 0.0;
    for (const glm::vec3& p : full.pixels)
        sum += double(p.r) + p.g + p.b;
    const double worst = largestDifference(culled, full);
    qInfo(
        "image mean %.4f, largest difference with culling %.2e", sum / double(3 * full.pixels.size()), worst);
    QVERIFY2(sum > 0.0, "the view shows nothing: the case tests nothing");
    // Voxel fragments are summed by float atomics in varying order: the last bits may differ.
    QVERIFY2(worst <= 1e-4, qPrintable(QString::number(worst)));
    QVERIFY(m_gl.renderer->takeGlErrors().empty());
}

// Closed solids seen from outside look the same single-sided (Material::doubleSided off: back faces left out
// of the g-buffer and of the shadow maps), whether or not the closed-surface test would have culled them.
void ViewCullingTest::singleSidedSolidsLookTheSameFromOutside()
{
    const render::Camera camera { { 2, 7, 16 }, { 8, 2, 6 }, { 0, 1, 0 }, 60.0f, 0.05f };
    const glm::vec3 light(8, 12, 8);
    const render::RadianceImage both = renderWith(false, camera, light);
    for (std::size_t m = 1; m < m_scene.materials.size(); ++m)
        m_scene.materials[m].doubleSided = false;
    const render::RadianceImage front = renderWith(true, camera, light);
    for (std::size_t m = 1; m < m_scene.materials.size(); ++m)
        m_scene.materials[m].doubleSided = true;
    const double worst = largestDifference(front, both);
    qInfo("single-sided solids against double-sided: largest difference %.2e", worst);
    QVERIFY2(worst <= 1e-4, qPrintable(QString::number(worst)));
}

// A single-sided wall seen from behind is not there for the camera; double-sided, it is.
void ViewCullingTest::singleSidedSurfacesShowTheirFrontOnly()
{
    render::Scene scene = m_scene;
    render::Material wall;
    wall.albedo = glm::vec3(0.1f, 0.9f, 0.2f);
    scene.materials.push_back(wall);
    // Facing -z, away from a camera on its +z side.
    scene.meshes.push_back(
        test::makeTriangles(test::quad({ 10, 1, 14 }, { 4, 1, 14 }, { 4, 6, 14 }, { 10, 6, 14 }),
            int(scene.materials.size()) - 1));
    const render::Camera camera { { 7, 3.5f, 15.5f }, { 7, 3.5f, 0 }, { 0, 1, 0 }, 40.0f, 0.05f };
    render::RenderSettings settings;
    settings.voxelResolution = 32;
    settings.view = render::DebugView::Albedo;
    for (const bool doubleSided : { true, false }) {
        scene.materials.back().doubleSided = doubleSided;
        m_gl.renderer->setSettings(settings);
        m_gl.renderer->setScene(scene);
        m_gl.renderer->setGridBounds(test::box(glm::vec3(0.5f), glm::vec3(15.5f)));
        m_gl.renderer->renderFrame(camera, 32, 32);
        const glm::vec3 centre = m_gl.renderer->readFrame().at(16, 16);
        qInfo("%s wall seen from behind: albedo %.3f %.3f %.3f",
            doubleSided ? "double-sided" : "single-sided", double(centre.r), double(centre.g),
            double(centre.b));
        QCOMPARE(std::abs(centre.g - wall.albedo.g) < 0.01f, doubleSided);
    }
    QVERIFY(m_gl.renderer->takeGlErrors().empty());
}

QTEST_GUILESS_MAIN(ViewCullingTest)
#include "tst_ViewCulling.moc"
