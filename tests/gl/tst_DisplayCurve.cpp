#include "GlTestContext.h"

#include "document/BuiltinScenes.h"
#include "gl/Framebuffer.h"
#include "gl/Texture.h"
#include "imageio/ToneMapper.h"

#include <QtTest>

#include <cstdlib>

using namespace vct;

// The viewport (present/Present.frag) and PNG files (io::ToneMapper) show a frame through one display curve,
// defined once in shaders/common/ToneCurve.glsl: what the user saw is what an export writes.
class DisplayCurveTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void viewportShowsWhatAPngWrites_data();
    void viewportShowsWhatAPngWrites();

private:
    test::GlTestContext m_gl;
};

void DisplayCurveTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
}

void DisplayCurveTest::viewportShowsWhatAPngWrites_data()
{
    QTest::addColumn<float>("exposure");
    QTest::newRow("exposure 1") << 1.0f;
    QTest::newRow("exposure 8: the filmic shoulder") << 8.0f;
    QTest::newRow("exposure 1/16: the sRGB toe") << 0.0625f;
}

void DisplayCurveTest::viewportShowsWhatAPngWrites()
{
    QFETCH(float, exposure);
    render::Scene scene;
    QString error;
    QVERIFY2(doc::BuiltinScenes::load(QStringLiteral("cornell"), scene, &error), qPrintable(error));
    render::RenderSettings settings;
    settings.voxelResolution = 32;
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(scene);
    constexpr int kSize = 48;
    m_gl.renderer->renderFrame(scene.camera, kSize, kSize);
    const render::RadianceImage frame = m_gl.renderer->readFrame();

    const gl::Texture target = gl::Texture::create2D(GL_RGBA8, kSize, kSize);
    gl::Framebuffer framebuffer = gl::Framebuffer::create();
    framebuffer.attachColor(0, target);
    m_gl.renderer->present(framebuffer.id(), 0, 0, kSize, kSize, exposure);
    std::vector<std::uint8_t> shown(std::size_t(kSize) * kSize * 4);
    glGetTextureImage(target.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(shown.size()), shown.data());

    const std::vector<std::uint8_t> written = io::ToneMapper(exposure).toRgb8(frame);
    int worst = 0, distinct = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            for (int c = 0; c < 3; ++c) {
                // GL rows run bottom to top, image rows top to bottom.
                const int a
                    = shown[(std::size_t(kSize - 1 - y) * kSize + std::size_t(x)) * 4 + std::size_t(c)];
                const int b = written[(std::size_t(y) * kSize + std::size_t(x)) * 3 + std::size_t(c)];
                worst = std::max(worst, std::abs(a - b));
                distinct += a != b;
            }
    // One step of 8 bits for GPU against CPU rounding; a different curve or a missed sRGB step is tens.
    QVERIFY2(worst <= 1,
        qPrintable(QString("largest difference %1 of 255 (%2 values differ)").arg(worst).arg(distinct)));
    QVERIFY(m_gl.renderer->takeGlErrors().empty());
}

QTEST_GUILESS_MAIN(DisplayCurveTest)
#include "tst_DisplayCurve.moc"
