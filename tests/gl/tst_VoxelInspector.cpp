#include "GlTestContext.h"
#include "TestSupport.h"

#include "document/SceneLoader.h"
#include "gl/Framebuffer.h"
#include "gl/Texture.h"
#include "imageio/ToneMapper.h"

#include <QtTest>

using namespace vct;

/** The inspector's voxel list and instanced cubes agree with the voxels the renderer holds. */
class VoxelInspectorTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void levelZeroListsEveryNonEmptyVoxel();
    void coarserLevelsNeverListMore();
    void coarseRadianceFollowsTheLight();
    void cubesAreDrawnIntoTheGivenRectangle();
    void presentToneMapsIntoAFramebuffer();

private:
    test::GlTestContext m_gl;
    render::Scene m_scene;
    render::Camera m_camera;
};

void VoxelInspectorTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
    QString error;
    QVERIFY2(doc::SceneLoader::load(QStringLiteral("builtin:cornell"), m_scene, &error), qPrintable(error));
    render::RenderSettings settings;
    settings.voxelResolution = 32;
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(m_scene);
    m_camera = m_scene.camera;
    m_gl.renderer->renderFrame(m_camera, 32, 32);
}

void VoxelInspectorTest::levelZeroListsEveryNonEmptyVoxel()
{
    int size = 0;
    const std::vector<float> albedo = m_gl.renderer->readVoxels("albedo", 0, size);
    std::size_t nonEmpty = 0;
    for (std::size_t i = 3; i < albedo.size(); i += 4)
        nonEmpty += albedo[i] > 0.0f ? 1 : 0;
    QVERIFY(nonEmpty > 0);
    for (render::VoxelChannel channel : { render::VoxelChannel::Albedo, render::VoxelChannel::Radiance,
             render::VoxelChannel::Opacity, render::VoxelChannel::Normal, render::VoxelChannel::Emission })
        QCOMPARE(m_gl.renderer->listVoxels(0, channel).samples.size(), nonEmpty);
    // Each listed voxel really is occupied, and its albedo is what the volume holds.
    for (const render::VoxelSample& s : m_gl.renderer->listVoxels(0, render::VoxelChannel::Albedo).samples) {
        const std::size_t i = ((std::size_t(s.coord.z) * size + s.coord.y) * size + s.coord.x) * 4;
        QVERIFY(albedo[i + 3] > 0.0f);
        QVERIFY(std::abs(albedo[i] - s.value.r) < 1e-5f);
    }
}

void VoxelInspectorTest::coarserLevelsNeverListMore()
{
    std::size_t previous = std::numeric_limits<std::size_t>::max();
    const int levels = m_gl.renderer->voxelLevelCount();
    QCOMPARE(levels, 6); // 32 -> 1
    for (int level = 0; level < levels; ++level) {
        const std::size_t radiance
            = m_gl.renderer->listVoxels(level, render::VoxelChannel::Radiance).samples.size();
        const std::size_t albedo
            = m_gl.renderer->listVoxels(level, render::VoxelChannel::Albedo).samples.size();
        QVERIFY2(radiance <= previous,
            qPrintable(QString("level %1: %2 after %3").arg(level).arg(radiance).arg(previous)));
        QCOMPARE(albedo, radiance); // both channels list the cells any surface touches
        previous = radiance;
    }
    QCOMPARE(previous, std::size_t(1)); // the coarsest level is one cell
}

// With anisotropic mips (the default) cones never read the box-filtered levels, so they are filtered only
// when inspected: they must still show the voxels' current light, not the light they were last filtered for.
// With every bounce in the voxels (the default) that light is the bounced volume's, linear in the emission.
void VoxelInspectorTest::coarseRadianceFollowsTheLight()
{
    const auto levelSum = [this](int level) {
        int size = 0;
        double sum = 0.0;
        const std::vector<float> texels = m_gl.renderer->readVoxels("bounced", level, size);
        for (std::size_t i = 0; i < texels.size(); i += 4)
            sum += double(texels[i]) + texels[i + 1] + texels[i + 2];
        return sum;
    };
    const double before = levelSum(2);
    QVERIFY(before > 0.0);
    // The box is lit by its emitters alone: voxel radiance is proportional to their emission.
    for (std::size_t m = 0; m < m_scene.materials.size(); ++m)
        if (m_scene.materials[m].isEmissive()) {
            render::Material brighter = m_scene.materials[m];
            brighter.emission *= 2.0f;
            m_gl.renderer->setMaterial(m, brighter);
        }
    m_gl.renderer->renderFrame(m_camera, 32, 32);
    const double ratio = levelSum(2) / before;
    QVERIFY2(std::abs(ratio - 2.0) < 1e-3, qPrintable(QString::number(ratio)));
    QCOMPARE(m_gl.renderer->listVoxels(5, render::VoxelChannel::Radiance).samples.size(), std::size_t(1));
}

void VoxelInspectorTest::cubesAreDrawnIntoTheGivenRectangle()
{
    gl::Texture color = gl::Texture::create2D(GL_RGBA8, 64, 32);
    gl::Texture depth = gl::Texture::create2D(GL_DEPTH_COMPONENT24, 64, 32);
    gl::Framebuffer target = gl::Framebuffer::create();
    target.attachColor(0, color);
    target.attachDepth(depth);
    target.finish(1);
    const float black[4] = { 0, 0, 0, 1 };
    glClearNamedFramebufferfv(target.id(), GL_COLOR, 0, black);
    const std::size_t drawn = m_gl.renderer->drawVoxelCubes(
        m_camera, 1, render::VoxelChannel::Albedo, target.id(), 32, 0, 32, 32, 1.0f);
    QCOMPARE(drawn, m_gl.renderer->listVoxels(1, render::VoxelChannel::Albedo).samples.size());
    std::vector<unsigned char> pixels(64 * 32 * 4);
    glGetTextureImage(color.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(pixels.size()), pixels.data());
    int leftTouched = 0, rightLit = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x) {
            const unsigned char* p = &pixels[(std::size_t(y) * 64 + x) * 4];
            if (x < 32)
                leftTouched += p[0] || p[1] || p[2];
            else
                rightLit += p[0] > 60 || p[1] > 60 || p[2] > 60;
        }
    QCOMPARE(leftTouched, 0); // nothing drawn outside the rectangle
    QVERIFY(rightLit > 100); // the box's walls fill much of the view
    QVERIFY(m_gl.renderer->takeGlErrors().empty());
}

void VoxelInspectorTest::presentToneMapsIntoAFramebuffer()
{
    gl::Texture color = gl::Texture::create2D(GL_RGBA8, 32, 32);
    gl::Framebuffer target = gl::Framebuffer::create();
    target.attachColor(0, color);
    target.finish(1);
    m_gl.renderer->present(target.id(), 0, 0, 32, 32, 1.0f);
    std::vector<unsigned char> pixels(32 * 32 * 4);
    glGetTextureImage(color.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(pixels.size()), pixels.data());
    // The viewport shows what an exported PNG holds: the GPU curve equals io::ToneMapper within rounding.
    const render::RadianceImage frame = m_gl.renderer->readFrame();
    const io::ToneMapper toneMapper(1.0f);
    int worst = 0, saturated = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            const glm::u8vec3 expected = toneMapper.toRgb8(frame.at(x, 31 - y)); // GL rows run bottom up
            const unsigned char* p = &pixels[(std::size_t(y) * 32 + x) * 4];
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::abs(int(p[c]) - int(expected[c])));
            saturated += p[0] == 255 ? 1 : 0;
        }
    QVERIFY2(worst <= 2, qPrintable(QString("largest difference %1 levels").arg(worst)));
    QVERIFY(saturated > 0); // the ceiling light clips
    QVERIFY(m_gl.renderer->takeGlErrors().empty());
}

QTEST_GUILESS_MAIN(VoxelInspectorTest)
#include "tst_VoxelInspector.moc"
