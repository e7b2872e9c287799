#include "Renderer.h"
#include "context/HeadlessContext.h"

#include <glad/gl.h>

#include <QtTest>

using namespace vct;

class HeadlessContextTest : public QObject {
    Q_OBJECT

private slots:
    void backendGives45Core_data();
    void backendGives45Core();
    void unknownBackendIsNamed();
};

void HeadlessContextTest::backendGives45Core_data()
{
    QTest::addColumn<QString>("backend");
    QTest::newRow("egl") << "egl";
    QTest::newRow("osmesa") << "osmesa";
}

void HeadlessContextTest::backendGives45Core()
{
    QFETCH(QString, backend);
    std::string error;
    auto context = render::HeadlessContext::create(backend.toStdString(), error);
    QVERIFY2(context, error.c_str());
    GLint major = 0, minor = 0, profile = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    QVERIFY(major * 10 + minor >= 45);
    QVERIFY(profile & GL_CONTEXT_CORE_PROFILE_BIT);
    QVERIFY(context->description().find(context->backendName()) == 0);
    // The same renderer runs on either backend.
    render::Renderer renderer(context->procAddressFunction());
    render::Scene scene;
    scene.materials.push_back({});
    render::Mesh mesh;
    mesh.positions = { { -1, -1, 0 }, { 1, -1, 0 }, { 0, 1, 0 } };
    mesh.normals = { { 0, 0, 1 }, { 0, 0, 1 }, { 0, 0, 1 } };
    mesh.indices = { 0, 1, 2 };
    scene.meshes.push_back(mesh);
    scene.materials[0].emission = glm::vec3(2.0f);
    scene.materials[0].albedo = glm::vec3(0.0f); // an emitter that reflects nothing reads exactly its Ke
    render::RenderSettings settings;
    settings.voxelResolution = 16;
    renderer.setSettings(settings);
    renderer.setScene(scene);
    renderer.renderFrame(render::Camera {}, 16, 16);
    const render::RadianceImage image = renderer.readFrame();
    QVERIFY2(std::abs(image.at(8, 8).r - 2.0f) < 1e-3f,
        qPrintable(QString::number(image.at(8, 8).r))); // the emitter's front face
    QCOMPARE(image.at(0, 0), glm::vec3(0.0f));
    const std::vector<std::string> errors = renderer.takeGlErrors();
    for (const std::string& error : errors)
        qWarning("%s", error.c_str());
    QVERIFY(errors.empty());
}

void HeadlessContextTest::unknownBackendIsNamed()
{
    std::string error;
    QVERIFY(!render::HeadlessContext::create("vulkan", error));
    QVERIFY(error.find("vulkan") != std::string::npos);
}

QTEST_GUILESS_MAIN(HeadlessContextTest)
#include "tst_HeadlessContext.moc"
