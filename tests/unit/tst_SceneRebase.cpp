#include "TestSupport.h"

#include "document/SceneLoader.h"
#include "document/SceneRebase.h"

#include <glm/gtc/matrix_transform.hpp>

#include <QDir>
#include <QtTest>

using namespace vct;

/** A scene far from the world's origin is moved near it in double precision before anything becomes float. */
class tst_SceneRebase : public QObject {
    Q_OBJECT

private slots:
    // 100 km out a float resolves 8 mm: the camera and light files, read as doubles, must keep their
    // micrometres once the scene is rebased, and the geometry its own quantisation only.
    void farModelKeepsItsCameraAndLightsExact()
    {
        const QString dir = test::outputDir() + QStringLiteral("/scene-rebase");
        QDir(dir).removeRecursively();
        // A 2 m floor at (1e5, 0, -1e5); its corners are exact in float, the camera and light are not.
        test::writeFile(dir + QStringLiteral("/far.obj"),
            "v 99999 0 -100001\nv 100001 0 -100001\nv 100001 0 -99999\nv 99999 0 -99999\nf 1 3 2\nf 1 4 3\n");
        test::writeFile(dir + QStringLiteral("/far.camera.json"),
            R"({"position": [100000.123456, 1.5, -99996.654321], "look_at": [100000.000001, 0, -100000],
                "fov_y_deg": 40, "width": 32, "height": 32})");
        test::writeFile(dir + QStringLiteral("/far.lights.json"),
            R"({"lights": [{"type": "point", "position": [100000.000125, 1.25, -100000.000375], "intensity": [1, 1, 1]}]})");

        render::Scene scene;
        QString error;
        QVERIFY2(doc::SceneLoader::load(dir + QStringLiteral("/far.obj"), scene, &error, nullptr, 1.0f,
                     doc::SceneLoader::Origin::RebaseFar),
            qPrintable(error));
        QCOMPARE(scene.origin, glm::dvec3(1e5, 0.0, -1e5));
        const glm::dvec3 camera = glm::dvec3(scene.camera.position) + scene.origin;
        QVERIFY2(glm::length(camera - glm::dvec3(100000.123456, 1.5, -99996.654321)) < 1e-6,
            qPrintable(test::describe(scene.camera.position)));
        const glm::dvec3 lookAt = glm::dvec3(scene.camera.lookAt) + scene.origin;
        QVERIFY(glm::length(lookAt - glm::dvec3(100000.000001, 0.0, -1e5)) < 1e-7);
        QCOMPARE(scene.pointLights.size(), size_t(1));
        const glm::dvec3 light = glm::dvec3(scene.pointLights[0].position) + scene.origin;
        QVERIFY(glm::length(light - glm::dvec3(100000.000125, 1.25, -100000.000375)) < 1e-7);
        const render::Aabb bounds = scene.bounds();
        QCOMPARE(bounds.min, glm::vec3(-1.0f, 0.0f, -1.0f));
        QCOMPARE(bounds.max, glm::vec3(1.0f, 0.0f, 1.0f));

        // A document shares one frame between its sources: it keeps the file's coordinates.
        render::Scene kept;
        QVERIFY2(doc::SceneLoader::load(dir + QStringLiteral("/far.obj"), kept, &error), qPrintable(error));
        QCOMPARE(kept.origin, glm::dvec3(0.0));
        QCOMPARE(kept.bounds().min, glm::vec3(99999.0f, 0.0f, -100001.0f));
    }

    // A model matrix that carries the offset (a glTF node 1000 km out, a rotated instance) is baked in double
    // precision: the vertices come out as exact as if the model had been at the origin.
    void transformHoldingTheOffsetIsBakedExactly()
    {
        render::Scene scene;
        scene.meshes.push_back(
            test::makeTriangles({ { 0.001f, 0.0f, 0.0f }, { 1.0f, 0.0f, 0.0f }, { 0.0f, 0.0f, 1.0f } }));
        const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(30.0f), glm::vec3(0.0f, 1.0f, 0.0f));
        scene.meshes[0].transform = glm::translate(glm::mat4(1.0f), glm::vec3(1e6f, 0.0f, 0.0f)) * turn;
        render::Mesh moving = scene.meshes[0];
        moving.dynamic = true;
        scene.meshes.push_back(moving);
        scene.camera.position = glm::vec3(1e6f, 0.0f, 10.0f);

        const glm::dvec3 origin = doc::SceneRebase::originFor(scene);
        QVERIFY(glm::length(origin - glm::dvec3(1e6, 0.0, 0.0)) < 1.0);
        doc::SceneRebase::rebase(scene, glm::dvec3(1e6, 0.0, 0.0));
        QCOMPARE(scene.origin, glm::dvec3(1e6, 0.0, 0.0));
        const glm::vec3 expected = glm::vec3(turn * glm::vec4(0.001f, 0.0f, 0.0f, 1.0f));
        QVERIFY2(glm::length(scene.meshes[0].positions[0] - expected) < 1e-7f,
            qPrintable(test::describe(scene.meshes[0].positions[0])));
        QCOMPARE(scene.meshes[0].transform, glm::mat4(1.0f));
        const glm::vec3 normal = glm::mat3(turn) * scene.meshes[1].normals[0];
        QVERIFY(glm::length(scene.meshes[0].normals[0] - normal) < 1e-6f);
        // The dynamic copy keeps its matrix, for moving it; only the offset leaves it.
        QCOMPARE(scene.meshes[1].positions[0], glm::vec3(0.001f, 0.0f, 0.0f));
        QVERIFY(glm::length(glm::vec3(scene.meshes[1].transform[3])) < 1e-6f);
        QCOMPARE(scene.camera.position, glm::vec3(0.0f, 0.0f, 10.0f));
    }

    // A scene around the world's origin is left bit for bit as it was.
    void sceneAtTheOriginIsUntouched()
    {
        render::Scene scene;
        scene.meshes.push_back(
            test::makeTriangles({ { 0.3f, 0.0f, 0.0f }, { 1.0f, 0.0f, 0.0f }, { 0.0f, 0.0f, 1.0f } }));
        QCOMPARE(doc::SceneRebase::originFor(scene), glm::dvec3(0.0));
        QCOMPARE(doc::SceneRebase::originFor(render::Scene {}), glm::dvec3(0.0));
    }
};

QTEST_GUILESS_MAIN(tst_SceneRebase)
#include "tst_SceneRebase.moc"
