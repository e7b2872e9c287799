#include "TestSupport.h"

#include "cli/BlackImageCheck.h"

#include <QtTest>

using namespace vct;

/** vct-render's warning for an image that came out black while the scene has light. */
class BlackImageCheckTest : public QObject {
    Q_OBJECT

private slots:
    void litPixelOrNoLightMeansNoWarning();
    void explainsACameraLookingAway();
    void explainsANearPlaneBeyondTheScene();
    void explainsASceneOutsideTheView();
};

namespace {

render::Scene litQuad()
{
    render::Scene scene;
    scene.materials.push_back({});
    scene.meshes.push_back(
        test::makeTriangles(test::quad({ -1, 0, 1 }, { 1, 0, 1 }, { 1, 0, -1 }, { -1, 0, -1 }), 0));
    scene.pointLights.push_back({ { 0.0f, 1.0f, 0.0f }, glm::vec3(1.0f), true });
    return scene;
}

} // namespace

void BlackImageCheckTest::litPixelOrNoLightMeansNoWarning()
{
    render::Scene scene = litQuad();
    render::Camera camera { { 0, 2, 3 }, { 0, 0, 0 }, { 0, 1, 0 }, 60.0f, 0.01f };
    render::RadianceImage image(4, 4);
    image.at(1, 1) = glm::vec3(0.0f, 0.5f, 0.0f);
    QVERIFY(cli::blackImageWarning(image, scene, camera).empty());
    const render::RadianceImage black(4, 4);
    QVERIFY(!cli::blackImageWarning(black, scene, camera).empty());
    scene.pointLights.clear(); // black is right for a scene with no light
    QVERIFY(cli::blackImageWarning(black, scene, camera).empty());
}

void BlackImageCheckTest::explainsACameraLookingAway()
{
    const render::Camera camera { { 0, 2, 3 }, { 0, 2, 6 }, { 0, 1, 0 }, 60.0f, 0.01f };
    const std::string warning = cli::blackImageWarning(render::RadianceImage(4, 4), litQuad(), camera);
    QVERIFY2(warning.find("looks away") != std::string::npos, warning.c_str());
}

void BlackImageCheckTest::explainsANearPlaneBeyondTheScene()
{
    const render::Camera camera { { 0, 2, 3 }, { 0, 0, 0 }, { 0, 1, 0 }, 60.0f, 100.0f };
    const std::string warning = cli::blackImageWarning(render::RadianceImage(4, 4), litQuad(), camera);
    QVERIFY2(warning.find("near plane") != std::string::npos, warning.c_str());
}

void BlackImageCheckTest::explainsASceneOutsideTheView()
{
    const render::Camera camera { { 100, 0, 3 }, { 100, 0, 0 }, { 0, 1, 0 }, 60.0f, 0.01f };
    const std::string warning = cli::blackImageWarning(render::RadianceImage(4, 4), litQuad(), camera);
    QVERIFY2(warning.find("outside the camera's view") != std::string::npos, warning.c_str());
}

QTEST_GUILESS_MAIN(BlackImageCheckTest)
#include "tst_BlackImageCheck.moc"
