#include "GlTestContext.h"
#include "TestSupport.h"

#include <glm/gtc/matrix_transform.hpp>

#include <QtTest>

using namespace vct;

/** The specular cone: glossy surfaces reflect what lies along the mirror direction, others get none. */
class SpecularConeTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void glossyFloorMirrorsEmitter();
    void matteFloorHasNoSpecularTerm();

private:
    render::RadianceImage renderSpecular(bool glossy);
    glm::ivec2 pixelOf(const glm::vec3& world) const;
    test::GlTestContext m_gl;
    const render::Camera m_camera{{8.0f, 4.0f, 14.0f}, {8.0f, 0.5f, 6.0f}, {0, 1, 0}, 70.0f, 0.01f};
    static constexpr int kSize = 48;
};

void SpecularConeTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
}

render::RadianceImage SpecularConeTest::renderSpecular(bool glossy)
{
    render::Scene scene;
    render::Material floor;
    floor.albedo = glm::vec3(0.0f);
    floor.specular = glm::vec3(glossy ? 0.5f : 0.0f);
    floor.shininess = glossy ? 200.0f : 0.0f;
    render::Material emitter;
    emitter.albedo = glm::vec3(0.0f);
    emitter.emission = glm::vec3(5.0f);
    scene.materials = {floor, emitter};
    scene.meshes.push_back(test::makeTriangles(test::quad({1, 0.5f, 15}, {15, 0.5f, 15}, {15, 0.5f, 1}, {1, 0.5f, 1}), 0));
    // A wall of light at z = 2 facing the camera (+z).
    scene.meshes.push_back(test::makeTriangles(test::quad({4, 1, 2}, {12, 1, 2}, {12, 8, 2}, {4, 8, 2}), 1));
    render::RenderSettings settings;
    settings.voxelResolution = 32;
    settings.view = render::DebugView::IndirectSpecular;
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(scene);
    m_gl.renderer->setGridBounds(test::box(glm::vec3(0.5f), glm::vec3(15.5f)));
    m_gl.renderer->renderFrame(m_camera, kSize, kSize);
    return m_gl.renderer->readFrame();
}

glm::ivec2 SpecularConeTest::pixelOf(const glm::vec3& world) const
{
    const glm::mat4 view = glm::lookAt(m_camera.position, m_camera.lookAt, m_camera.up);
    const glm::mat4 projection = glm::perspective(glm::radians(m_camera.fovYDeg), 1.0f, 0.01f, 100.0f);
    const glm::vec3 p = glm::project(world, view, projection, glm::vec4(0, 0, kSize, kSize));
    return {int(p.x), kSize - 1 - int(p.y)}; // RadianceImage rows run top to bottom
}

void SpecularConeTest::glossyFloorMirrorsEmitter()
{
    const render::RadianceImage image = renderSpecular(true);
    // The mirror ray from (8, 0.5, 6) meets the wall at (8, 2.25, 2): it sees the light. From (13, 0.5, 7)
    // it meets the wall's plane at x = 16.6, well beside the light (x in [4, 12]), and sees nothing.
    const glm::ivec2 hit = pixelOf({8.0f, 0.5f, 6.0f});
    const glm::ivec2 miss = pixelOf({13.0f, 0.5f, 7.0f});
    for (const glm::ivec2& p : {hit, miss})
        QVERIFY(p.x >= 0 && p.y >= 0 && p.x < kSize && p.y < kSize);
    const float lit = image.at(hit.x, hit.y).r, dark = image.at(miss.x, miss.y).r;
    qInfo("specular term where the mirror sees the light %.3f, where it does not %.3f", lit, dark);
    // At most Ks * Ke = 2.5, and a clear share of it where the cone meets the emitter head-on.
    QVERIFY2(lit > 0.5f && lit <= 2.5f * 1.05f, qPrintable(QString::number(lit)));
    QVERIFY2(dark < 0.1f * lit, qPrintable(QString::number(dark)));
    QVERIFY(m_gl.renderer->takeGlErrors().empty());
}

void SpecularConeTest::matteFloorHasNoSpecularTerm()
{
    const render::RadianceImage image = renderSpecular(false);
    for (const glm::vec3& p : image.pixels)
        QCOMPARE(p, glm::vec3(0.0f));
}

QTEST_GUILESS_MAIN(SpecularConeTest)
#include "tst_SpecularCone.moc"
