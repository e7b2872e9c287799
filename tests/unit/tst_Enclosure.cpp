#include "TestSupport.h"

#include "document/Document.h"
#include "document/Enclosure.h"
#include "document/SceneLoader.h"

#include <QDir>
#include <QtTest>

using namespace vct;

/**
 * A model opened without a camera or lights is not dead on arrival: a closed room is framed from inside, and
 * a light is added when the model brings none, said in a note for the status bar.
 */
class tst_Enclosure : public QObject {
    Q_OBJECT

private:
    /** A 4 x 3 x 6 m box room as an OBJ, closed or with its +z wall left out. */
    static QString writeRoom(const QString& name, bool closed)
    {
        const QString dir = test::outputDir() + QStringLiteral("/enclosure");
        QByteArray obj = "v -2 0 -3\nv 2 0 -3\nv 2 3 -3\nv -2 3 -3\nv -2 0 3\nv 2 0 3\nv 2 3 3\nv -2 3 3\n"
                         "f 1 2 3\nf 1 3 4\n" // -z
                         "f 1 5 6\nf 1 6 2\n" // floor
                         "f 4 3 7\nf 4 7 8\n" // ceiling
                         "f 1 4 8\nf 1 8 5\n" // -x
                         "f 2 6 7\nf 2 7 3\n"; // +x
        if (closed)
            obj += "f 5 8 7\nf 5 7 6\n"; // +z
        return test::writeFile(dir + QLatin1Char('/') + name + QStringLiteral(".obj"), obj);
    }

private slots:
    void closedRoomIsFramedFromInside()
    {
        render::Scene scene;
        QString error;
        QVERIFY2(doc::SceneLoader::load(writeRoom(QStringLiteral("closed"), true), scene, &error),
            qPrintable(error));
        QCOMPARE(doc::Enclosure::hitShare(scene, glm::vec3(0.0f, 1.5f, 0.0f), -1.0f, 1.0f), 1.0f);
        QVERIFY(doc::Enclosure::roofed(scene, glm::vec3(0.0f, 1.5f, 0.0f)));
        const render::Aabb bounds = scene.bounds();
        QVERIFY(bounds.contains(scene.camera.position));
        // Along the longer horizontal side (z, 6 m), level.
        const glm::vec3 view = scene.camera.lookAt - scene.camera.position;
        QVERIFY(std::abs(view.z) > 0.0f && view.x == 0.0f && view.y == 0.0f);
        QVERIFY(scene.camera.nearPlane < 0.01f * glm::length(bounds.size()));
    }

    void openRoomIsFramedFromOutside()
    {
        render::Scene scene;
        QString error;
        QVERIFY2(doc::SceneLoader::load(writeRoom(QStringLiteral("open"), false), scene, &error),
            qPrintable(error));
        QVERIFY(!doc::Enclosure::encloses(scene, glm::vec3(0.0f, 1.5f, 0.0f)));
        QVERIFY(!scene.bounds().contains(scene.camera.position));
    }

    void modelWithoutLightsGetsOneAndSaysSo()
    {
        doc::Document inside;
        QString error;
        QVERIFY2(inside.newFromScene(writeRoom(QStringLiteral("closed"), true), &error), qPrintable(error));
        QCOMPARE(inside.state().lights.size(), std::size_t(1));
        QCOMPARE(inside.state().lights[0].type, doc::LightType::Point);
        QVERIFY(inside.sceneBounds().contains(inside.state().lights[0].position));
        QVERIFY2(inside.openNote().contains(QStringLiteral("no light")), qPrintable(inside.openNote()));
        QVERIFY(!inside.isModified());

        doc::Document outside;
        QVERIFY2(outside.newFromScene(writeRoom(QStringLiteral("open"), false), &error), qPrintable(error));
        QCOMPARE(outside.state().lights.size(), std::size_t(1));
        QCOMPARE(outside.state().lights[0].type, doc::LightType::Directional);

        // A scene that has lights keeps them as they are, and says nothing.
        doc::Document lit;
        QVERIFY2(lit.newFromScene(test::referenceDir() + QStringLiteral("/cornell_point.obj"), &error),
            qPrintable(error));
        QCOMPARE(lit.state().lights.size(), std::size_t(1));
        QVERIFY(lit.openNote().isEmpty());
        QVERIFY2(lit.newFromScene(test::referenceDir() + QStringLiteral("/cornell.obj"), &error),
            qPrintable(error));
        QVERIFY2(lit.state().lights.empty(), "an emitter is a light");
        QVERIFY(lit.openNote().isEmpty());
    }
};

QTEST_GUILESS_MAIN(tst_Enclosure)
#include "tst_Enclosure.moc"
