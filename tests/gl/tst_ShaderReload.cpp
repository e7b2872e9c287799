#include "GlTestContext.h"
#include "TestSupport.h"

#include "document/SceneLoader.h"

#include <QDir>
#include <QFile>
#include <QtTest>

using namespace vct;

/**
 * Shader hot reload (the editor's F5): every program is rebuilt from a folder's text, a program that no
 * longer compiles keeps its last good build and says why, and reloading the original text gives back the
 * original image bit for bit.
 */
class ShaderReloadTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void reloadRebuildsEveryProgramAndKeepsTheLastGoodOne();

private:
    render::RadianceImage renderFrame();
    /** A shaders/ folder holding only composite/Composite.frag, with `text`. */
    QString folderWithComposite(const QString& name, const QByteArray& text);

    test::GlTestContext m_gl;
    render::Scene m_scene;
};

void ShaderReloadTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
    QString error;
    QVERIFY2(doc::SceneLoader::load(QStringLiteral("builtin:cornell"), m_scene, &error), qPrintable(error));
    m_gl.renderer->setScene(m_scene);
    render::RenderSettings settings;
    settings.voxelResolution = 32;
    m_gl.renderer->setSettings(settings);
}

render::RadianceImage ShaderReloadTest::renderFrame()
{
    m_gl.renderer->renderFrame(m_scene.camera, 32, 32);
    return m_gl.renderer->readFrame();
}

QString ShaderReloadTest::folderWithComposite(const QString& name, const QByteArray& text)
{
    const QString dir = test::outputDir() + QStringLiteral("/shader-reload/") + name;
    QDir(dir).removeRecursively();
    test::writeFile(dir + QStringLiteral("/composite/Composite.frag"), text);
    return dir;
}

void ShaderReloadTest::reloadRebuildsEveryProgramAndKeepsTheLastGoodOne()
{
    const render::RadianceImage original = renderFrame();
    QFile source(test::sourceDir() + QStringLiteral("/shaders/composite/Composite.frag"));
    QVERIFY2(source.open(QIODevice::ReadOnly), qPrintable(source.fileName()));
    const QByteArray text = source.readAll();
    const QByteArray output = "oRadiance = vec4(result, 1.0);";
    QVERIFY2(text.contains(output), "Composite.frag no longer writes its result as the test expects");

    // A valid edit takes effect on the next frame, without a new scene or settings.
    QByteArray doubled = text;
    doubled.replace(output, "oRadiance = vec4(2.0 * result, 1.0);");
    std::vector<std::string> failures
        = m_gl.renderer->reloadShaders(folderWithComposite(QStringLiteral("doubled"), doubled).toStdString());
    QVERIFY2(failures.empty(), failures.empty() ? "" : failures.front().c_str());
    const render::RadianceImage twice = renderFrame();
    QCOMPARE(twice.pixels.size(), original.pixels.size());
    double lit = 0.0;
    for (std::size_t i = 0; i < original.pixels.size(); ++i) {
        QCOMPARE(twice.pixels[i], 2.0f * original.pixels[i]);
        lit += original.pixels[i].r;
    }
    QVERIFY(lit > 0.0);

    // A broken edit is reported, naming the program and file, and the last good program stays.
    QByteArray broken = text;
    broken.replace(output, "oRadiance = vec4(result, 1.0) +;");
    failures
        = m_gl.renderer->reloadShaders(folderWithComposite(QStringLiteral("broken"), broken).toStdString());
    QVERIFY(!failures.empty());
    for (const std::string& failure : failures)
        QVERIFY2(QString::fromStdString(failure).contains(QStringLiteral("Composite.frag")), failure.c_str());
    // Drivers may also report the compile error on their debug channel: expected, so dropped.
    m_gl.renderer->takeGlErrors();
    const render::RadianceImage kept = renderFrame();
    QVERIFY(kept.pixels == twice.pixels);

    // Back to the tree's text: the original image exactly.
    failures = m_gl.renderer->reloadShaders((test::sourceDir() + QStringLiteral("/shaders")).toStdString());
    QVERIFY2(failures.empty(), failures.empty() ? "" : failures.front().c_str());
    QVERIFY(renderFrame().pixels == original.pixels);
    QVERIFY(m_gl.renderer->takeGlErrors().empty());
}

QTEST_GUILESS_MAIN(ShaderReloadTest)
#include "tst_ShaderReload.moc"
