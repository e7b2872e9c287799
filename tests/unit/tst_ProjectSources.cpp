#include "TestSupport.h"

#include "document/Document.h"
#include "document/ProjectFile.h"
#include "document/SceneLoader.h"

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtGui/QImage>
#include <QtTest>

using namespace vct;
using doc::Document;
using doc::DocumentState;
using doc::ProjectFile;

namespace {

QString testDir(const QString& name)
{
    const QString dir = test::outputDir() + QStringLiteral("/project-sources/") + name;
    QDir(dir).removeRecursively();
    QDir().mkpath(dir);
    return dir;
}

QString cornellModel()
{
    return test::referenceDir() + QStringLiteral("/cornell.obj");
}

/** A project with these sources and no lights, as a hand-written file for a big external model would be. */
QJsonObject projectWith(const QJsonArray& sources)
{
    return QJsonObject { { "format", "vct-studio-project" }, { "version", 1 }, { "sources", sources },
        { "lights", QJsonArray {} },
        { "camera",
            QJsonObject { { "position", QJsonArray { 0, 1, 4 } }, { "look_at", QJsonArray { 0, 1, 0 } },
                { "up", QJsonArray { 0, 1, 0 } }, { "fov_y_deg", 40 } } },
        { "settings", QJsonObject {} }, { "next_id", 1 } };
}

QString writeProject(const QString& path, const QJsonObject& root)
{
    return test::writeFile(path, QJsonDocument(root).toJson());
}

/** A one-quad OBJ whose material has a one-colour texture: for checking how texture indices are offset. */
QString writeTexturedObj(const QString& folder, const QString& name, QColor color)
{
    const QString stem = QDir(folder).filePath(name);
    QDir().mkpath(folder);
    QImage image(2, 2, QImage::Format_RGBA8888);
    image.fill(color);
    if (!image.save(stem + QStringLiteral(".png")))
        return {};
    test::writeFile(stem + QStringLiteral(".mtl"),
        QStringLiteral("newmtl %1_mat\nKd 1 1 1\nmap_Kd %1.png\n").arg(name).toUtf8());
    return test::writeFile(stem + QStringLiteral(".obj"),
        QStringLiteral(
            "mtllib %1.mtl\no %1\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
            "usemtl %1_mat\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n")
            .arg(name)
            .toUtf8());
}

} // namespace

class tst_ProjectSources : public QObject {
    Q_OBJECT

private slots:
    void unitScaleRoundTripsAndScalesTheGeometry()
    {
        const QString dir = testDir(QStringLiteral("unit-scale"));
        Document doc;
        QString error;
        QVERIFY2(doc.newFromScene(cornellModel(), &error), qPrintable(error));
        QVERIFY2(doc.importModel(cornellModel(), &error, 0.5f), qPrintable(error));
        const QString path = dir + QStringLiteral("/scaled.vctproj");
        QVERIFY2(doc.saveProject(path, &error), qPrintable(error));

        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QJsonArray sources
            = QJsonDocument::fromJson(file.readAll()).object().value("sources").toArray();
        QCOMPARE(sources.size(), 2);
        QVERIFY(!sources[0].toObject().contains("unit_scale")); // metres: written as before the field
        QCOMPARE(sources[1].toObject().value("unit_scale").toDouble(), 0.5);

        Document reopened;
        QVERIFY2(reopened.openProject(path, &error), qPrintable(error));
        QVERIFY(doc::sameDocument(doc.state(), reopened.state()));
        QCOMPARE(reopened.state().sources[1].unitScale, 0.5f);
        const render::Aabb metres = reopened.sourceScene(0).bounds();
        const render::Aabb halved = reopened.sourceScene(1).bounds();
        QVERIFY(!metres.isEmpty());
        QVERIFY(glm::length(halved.min - 0.5f * metres.min) < 1e-5f);
        QVERIFY(glm::length(halved.max - 0.5f * metres.max) < 1e-5f);
        QCOMPARE(reopened.buildRenderScene().triangleCount(), doc.buildRenderScene().triangleCount());

        // A different scale is a different document.
        DocumentState other = reopened.state();
        other.sources[1].unitScale = 0.25f;
        QVERIFY(!doc::sameDocument(other, reopened.state()));
    }

    void badUnitScalesAreRefused_data()
    {
        QTest::addColumn<QJsonObject>("source");
        QTest::addColumn<QString>("expected");
        const QString model = cornellModel();
        QTest::newRow("zero") << QJsonObject { { "spec", model }, { "unit_scale", 0 } }
                              << QStringLiteral("sources[0].unit_scale");
        QTest::newRow("negative") << QJsonObject { { "spec", model }, { "unit_scale", -0.01 } }
                                  << QStringLiteral("sources[0].unit_scale");
        QTest::newRow("beyond float") << QJsonObject { { "spec", model }, { "unit_scale", 1e300 } }
                                      << QStringLiteral("sources[0].unit_scale");
        QTest::newRow("text") << QJsonObject { { "spec", model }, { "unit_scale", "cm" } }
                              << QStringLiteral("sources[0].unit_scale");
        QTest::newRow("builtin") << QJsonObject { { "spec", "builtin:cornell" }, { "unit_scale", 0.01 } }
                                 << QStringLiteral("built-in scenes are in metres");
    }

    void badUnitScalesAreRefused()
    {
        QFETCH(QJsonObject, source);
        QFETCH(QString, expected);
        const QString path = writeProject(
            testDir(QStringLiteral("bad-scale")) + QStringLiteral("/bad.vctproj"), projectWith({ source }));
        DocumentState state;
        QString error;
        QVERIFY(!ProjectFile::load(path, &state, &error));
        QVERIFY2(
            error.contains(QStringLiteral("bad.vctproj")) && error.contains(expected), qPrintable(error));
        Document doc;
        QVERIFY(!doc.openProject(path, &error));
        QVERIFY2(error.contains(expected), qPrintable(error));
    }

    // A project for a model it does not ship: sources only; every mesh becomes a node with the model's own
    // materials, and the lights are the project's.
    void projectWithoutNodesTakesTheSourcesWhole()
    {
        const QString dir = testDir(QStringLiteral("whole"));
        // Beside the model copy, a sibling lights file the project must not take.
        QVERIFY(QDir().mkpath(dir + QStringLiteral("/models")));
        for (const char* name : { "cornell.obj", "cornell.mtl" })
            QVERIFY(QFile::copy(test::referenceDir() + QLatin1Char('/') + QLatin1String(name),
                dir + QStringLiteral("/models/") + QLatin1String(name)));
        test::writeFile(dir + QStringLiteral("/models/cornell.lights.json"),
            R"({"lights": [{"type": "point", "position": [0, 0.5, 0], "intensity": [1, 1, 1]}]})");
        const QString path = writeProject(dir + QStringLiteral("/whole.vctproj"),
            projectWith({ QJsonObject { { "spec", "models/cornell.obj" }, { "unit_scale", 0.5 } } }));

        render::Scene model;
        QString error;
        QVERIFY2(
            doc::SceneLoader::load(dir + QStringLiteral("/models/cornell.obj"), model, &error, nullptr, 0.5f),
            qPrintable(error));
        QVERIFY(model.meshes.size() >= 7);

        Document doc;
        QVERIFY2(doc.openProject(path, &error), qPrintable(error));
        const DocumentState& s = doc.state();
        QCOMPARE(s.nodes.size(), model.meshes.size());
        for (std::size_t i = 0; i < s.nodes.size(); ++i) {
            QCOMPARE(s.nodes[i].source, 0);
            QCOMPARE(s.nodes[i].mesh, int(i));
            QCOMPARE(s.nodes[i].material, model.meshes[i].material);
            QCOMPARE(s.nodes[i].name, QString::fromStdString(model.meshes[i].name));
            QVERIFY(s.nodes[i].id >= 1 && s.nodes[i].id < s.nextId);
        }
        QCOMPARE(s.materials.size(), model.materials.size());
        for (std::size_t i = 0; i < s.materials.size(); ++i)
            QVERIFY(doc::sameMaterial(s.materials[i], model.materials[i]));
        QVERIFY(s.lights.empty());
        QCOMPARE(s.camera.position, glm::vec3(0.0f, 1.0f, 4.0f));
        QCOMPARE(doc.buildRenderScene().triangleCount(), model.triangleCount());
        QVERIFY(glm::length(doc.buildRenderScene().bounds().max - model.bounds().max) < 1e-5f);
        QVERIFY(!doc.isModified());

        // Saved in full, and read back the same.
        const QString saved = dir + QStringLiteral("/saved.vctproj");
        QVERIFY2(doc.saveProject(saved, &error), qPrintable(error));
        QFile file(saved);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QJsonObject root = QJsonDocument::fromJson(file.readAll()).object();
        QCOMPARE(root.value("nodes").toArray().size(), int(model.meshes.size()));
        QCOMPARE(root.value("materials").toArray().size(), int(model.materials.size()));
        Document reopened;
        QVERIFY2(reopened.openProject(saved, &error), qPrintable(error));
        QVERIFY(doc::sameDocument(doc.state(), reopened.state()));
    }

    // Several whole sources get what importing them one after another gives: materials and texture indices
    // offset by the sources before them.
    void wholeSourcesMatchImportsInOrder()
    {
        const QString dir = testDir(QStringLiteral("whole-textured"));
        const QString red = writeTexturedObj(dir, QStringLiteral("red"), QColor(255, 0, 0));
        const QString blue = writeTexturedObj(dir, QStringLiteral("blue"), QColor(0, 0, 255));
        const QString path = writeProject(dir + QStringLiteral("/two.vctproj"),
            projectWith({ QJsonObject { { "spec", "red.obj" } }, QJsonObject { { "spec", "blue.obj" } } }));
        Document whole;
        QString error;
        QVERIFY2(whole.openProject(path, &error), qPrintable(error));

        Document imported;
        QVERIFY2(imported.newFromScene(red, &error), qPrintable(error));
        QVERIFY2(imported.importModel(blue, &error), qPrintable(error));
        // Ids aside: opening a model that brings no light adds one, which takes an id the project does not.
        const auto withoutIds = [](std::vector<doc::SceneNode> nodes) {
            for (doc::SceneNode& node : nodes)
                node.id = 0;
            return nodes;
        };
        QCOMPARE(withoutIds(whole.state().nodes), withoutIds(imported.state().nodes));
        QCOMPARE(imported.state().lights.size(), std::size_t(1));
        QCOMPARE(whole.state().materials.size(), std::size_t(2));
        QVERIFY(std::equal(whole.state().materials.begin(), whole.state().materials.end(),
            imported.state().materials.begin(), imported.state().materials.end(), doc::sameMaterial));
        QCOMPARE(whole.state().materials[0].albedoTexture, 0);
        QCOMPARE(whole.state().materials[1].albedoTexture, 1);
        const render::Scene scene = whole.buildRenderScene();
        QCOMPARE(scene.textures.size(), std::size_t(2));
        QCOMPARE(int(scene.textures[1].rgba[2]), 255);
    }

    void omittingOnlyNodesOrMaterialsFails()
    {
        const QString dir = testDir(QStringLiteral("half"));
        for (const char* kept : { "nodes", "materials" }) {
            QJsonObject root = projectWith({ QJsonObject { { "spec", cornellModel() } } });
            root.insert(QLatin1String(kept), QJsonArray {});
            const QString path = writeProject(dir + QStringLiteral("/half.vctproj"), root);
            const QString missing = QLatin1String(kept) == QLatin1String("nodes")
                ? QStringLiteral("materials")
                : QStringLiteral("nodes");
            Document doc;
            QString error;
            QVERIFY(!doc.openProject(path, &error));
            QVERIFY2(error.contains(QStringLiteral("half.vctproj"))
                    && error.contains(QStringLiteral("field '%1'").arg(missing))
                    && error.contains(QStringLiteral("missing")),
                qPrintable(error));
        }
    }

    // The project ships in the repository, the model lives elsewhere: the root replaces the project's folder.
    void relativeSourcesResolveAgainstTheModelRoot()
    {
        const QString projects = testDir(QStringLiteral("root-projects"));
        const QString models = testDir(QStringLiteral("root-models"));
        QVERIFY(QDir().mkpath(models + QStringLiteral("/box")));
        for (const char* name : { "cornell.obj", "cornell.mtl" })
            QVERIFY(QFile::copy(test::referenceDir() + QLatin1Char('/') + QLatin1String(name),
                models + QStringLiteral("/box/") + QLatin1String(name)));
        const QString path = writeProject(projects + QStringLiteral("/box.vctproj"),
            projectWith({ QJsonObject { { "spec", "box/cornell.obj" } } }));

        Document doc;
        QString error;
        QVERIFY(!doc.openProject(path, &error));
        const QString resolved = QDir::toNativeSeparators(projects + QStringLiteral("/box/cornell.obj"));
        QVERIFY2(error.contains(resolved)
                && error.contains(QStringLiteral("sources[0].spec 'box/cornell.obj'"))
                && error.contains(QStringLiteral("--scene-root"))
                && error.contains(QLatin1String(ProjectFile::kModelRootVariable)),
            qPrintable(error));

        doc.setModelRoot(models);
        QVERIFY2(doc.openProject(path, &error), qPrintable(error));
        QCOMPARE(doc.state().sources[0].spec, QDir::cleanPath(models + QStringLiteral("/box/cornell.obj")));
        QVERIFY(!doc.state().nodes.empty());
        DocumentState state;
        QVERIFY2(ProjectFile::load(path, &state, &error, models), qPrintable(error));

        // Saved with the root, the path stays relative to it: the project still travels without the model.
        doc.setNodeName(0, QStringLiteral("renamed"));
        const QString saved = projects + QStringLiteral("/saved.vctproj");
        QVERIFY2(doc.saveProject(saved, &error), qPrintable(error));
        QFile file(saved);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QJsonObject root = QJsonDocument::fromJson(file.readAll()).object();
        QCOMPARE(root.value("sources").toArray()[0].toObject().value("spec").toString(),
            QStringLiteral("box/cornell.obj"));
        Document reopened;
        reopened.setModelRoot(models);
        QVERIFY2(reopened.openProject(saved, &error), qPrintable(error));
        QVERIFY(doc::sameDocument(doc.state(), reopened.state()));

        // An absolute path ignores the root and says only that the file is missing.
        const QString absent = writeProject(projects + QStringLiteral("/absent.vctproj"),
            projectWith({ QJsonObject { { "spec", models + QStringLiteral("/gone.obj") } } }));
        QVERIFY(!reopened.openProject(absent, &error));
        QVERIFY2(error.contains(QStringLiteral("gone.obj")) && error.contains(QStringLiteral("not found"))
                && !error.contains(QStringLiteral("--scene-root")),
            qPrintable(error));
    }

    // A whole source's placement reaches each of its nodes; it is refused, naming the field, where the
    // project lists its nodes (they carry their own) and where its scale is not above zero.
    void placementOfWholeSources()
    {
        const QString dir = testDir(QStringLiteral("placement"));
        QJsonObject source { { "spec", cornellModel() },
            { "placement",
                QJsonObject { { "translation", QJsonArray { 1, 2, 3 } }, { "scale", QJsonArray { 2, 2, 2 } },
                    { "dynamic", true } } } };
        Document doc;
        QString error;
        QVERIFY2(doc.openProject(
                     writeProject(dir + QStringLiteral("/placed.vctproj"), projectWith({ source })), &error),
            qPrintable(error));
        QVERIFY(!doc.state().nodes.empty());
        for (const doc::SceneNode& node : doc.state().nodes) {
            QVERIFY(node.dynamic);
            QCOMPARE(node.transform.translation, glm::vec3(1, 2, 3));
            QCOMPARE(node.transform.scale, glm::vec3(2.0f));
        }

        QJsonObject listed = projectWith({ source });
        listed.insert("nodes", QJsonArray {});
        listed.insert("materials", QJsonArray {});
        QVERIFY(!doc.openProject(writeProject(dir + QStringLiteral("/listed.vctproj"), listed), &error));
        QVERIFY2(error.contains(QStringLiteral("sources[0].placement")), qPrintable(error));

        QJsonObject flat = source;
        flat.insert("placement", QJsonObject { { "scale", QJsonArray { 1, 0, 1 } } });
        QVERIFY(!doc.openProject(
            writeProject(dir + QStringLiteral("/flat.vctproj"), projectWith({ flat })), &error));
        QVERIFY2(error.contains(QStringLiteral("sources[0].placement.scale")), qPrintable(error));
    }

    // The shipped resources/scenes/sponza.vctproj stays loadable: with a stand-in for the model (the real
    // one is not in the repository) under a scene root, it opens with its sun, camera and settings, in
    // centimetres.
    void shippedSponzaProjectOpens()
    {
        const QString root = testDir(QStringLiteral("sponza-root"));
        QVERIFY(QDir().mkpath(root + QStringLiteral("/sponza")));
        for (const char* name : { "cornell.obj", "cornell.mtl" }) {
            const QString target = root + QStringLiteral("/sponza/")
                + QString::fromLatin1(name).replace(QStringLiteral("cornell"), QStringLiteral("sponza"));
            QFile::remove(target);
            QVERIFY(QFile::copy(test::referenceDir() + QLatin1Char('/') + QLatin1String(name), target));
        }
        // The OBJ names its material library: the stand-in's must be found under its new name.
        QFile obj(root + QStringLiteral("/sponza/sponza.obj"));
        QVERIFY(obj.open(QIODevice::ReadOnly));
        QByteArray text = obj.readAll();
        obj.close();
        text.replace("cornell.mtl", "sponza.mtl");
        test::writeFile(obj.fileName(), text);

        Document doc;
        doc.setModelRoot(root);
        QString error;
        QVERIFY2(
            doc.openProject(test::sourceDir() + QStringLiteral("/resources/scenes/sponza.vctproj"), &error),
            qPrintable(error));
        QCOMPARE(doc.state().sources.size(), std::size_t(2));
        QCOMPARE(doc.state().sources[0].unitScale, 0.01f);
        QVERIFY(!doc.state().nodes.empty());
        // The bunny, placed and dynamic on the floor as in the paper's benchmark.
        const doc::SceneNode& bunny = doc.state().nodes.back();
        QCOMPARE(bunny.source, 1);
        QVERIFY(bunny.dynamic);
        QCOMPARE(bunny.transform.rotationDeg.y, 50.0f);
        QVERIFY(!doc.state().nodes.front().dynamic);
        QVERIFY(doc.state().nodes.front().transform == doc::NodeTransform {});
        // Saved, it lists every node, keeps the bunny's resource path and reopens the same.
        const QString saved = testDir(QStringLiteral("sponza-saved")) + QStringLiteral("/sponza.vctproj");
        QVERIFY2(doc.saveProject(saved, &error), qPrintable(error));
        Document reopened;
        reopened.setModelRoot(root);
        QVERIFY2(reopened.openProject(saved, &error), qPrintable(error));
        QVERIFY(doc::sameDocument(doc.state(), reopened.state()));
        QCOMPARE(doc.state().lights.size(), std::size_t(1));
        QVERIFY(doc.state().lights[0].type == doc::LightType::Directional);
        QCOMPARE(doc.state().lights[0].angularDiameterDeg, 0.53f);
        QCOMPARE(doc.state().settings.voxelResolution, 128);
        const render::Aabb bounds = doc.sourceScene(0).bounds();
        QVERIFY(glm::length(bounds.size()) < 0.05f); // the 2 m stand-in, read as centimetres
    }
};

QTEST_GUILESS_MAIN(tst_ProjectSources)
#include "tst_ProjectSources.moc"
