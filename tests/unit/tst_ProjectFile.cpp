#include "FileSizeLimit.h"
#include "TestSupport.h"

#include "Document.h"
#include "ProjectFile.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include <csignal>
#include <sys/resource.h>

using vct::doc::Document;
using vct::doc::DocumentState;
using vct::doc::LightNode;
using vct::doc::LightType;
using vct::doc::ProjectFile;
using vct::doc::sameDocument;

namespace {

QString testDir(const QString& name)
{
    const QString dir = vct::test::outputDir() + QStringLiteral("/project/") + name;
    QDir(dir).removeRecursively();
    QDir().mkpath(dir);
    return dir;
}

bool writeFile(const QString& path, const QByteArray& bytes)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

QByteArray readFile(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

/** A one-triangle OBJ. */
QString writeTriangleObj(const QString& path)
{
    return writeFile(path, "o Wedge\nv 0 0 0\nv 0.5 0 0\nv 0 0.5 0\nf 1 2 3\n") ? path : QString();
}

/** builtin:cornell with one edit of every kind a project keeps. */
bool makeEditedCornell(Document& doc)
{
    QString error;
    if (!doc.newFromScene(QStringLiteral("builtin:cornell"), &error))
        return false;
    doc.setNodeTransform(1, { { 0.1f, -0.25f, 0.3f }, { 10.0f, 33.3f, -7.0f }, { 1.0f, 1.5f, 0.75f } });
    doc.setNodeName(2, QStringLiteral("Tall box \u00e9"));
    doc.setNodeVisible(3, false);
    doc.setNodeDynamic(1, true);
    auto material = doc.state().materials[1];
    material.albedo = { 0.123f, 0.456f, 0.789f };
    material.specular = glm::vec3(0.1f);
    material.shininess = 64.0f;
    material.doubleSided = false;
    doc.setMaterial(1, material);
    LightNode light;
    light.name = QStringLiteral("Sun");
    light.type = LightType::Directional;
    light.direction = { 0.3f, -1.0f, 0.1f };
    light.color = { 1.0f, 0.9f, 0.7f };
    light.intensity = 2.5f;
    light.castsShadows = false;
    doc.addLight(light);
    auto settings = doc.state().settings;
    if (!settings.set("voxel_res", "64").empty() || !settings.set("exposure", "1.75").empty()
        || !settings.set("view", "ao").empty() || !settings.set("anisotropic", "on").empty())
        return false;
    doc.setSettings(settings);
    auto camera = doc.state().camera;
    camera.position += glm::vec3(0.1f, 0.2f, -0.3f);
    camera.fovYDeg = 35.5f;
    doc.setCamera(camera);
    doc.addBookmark(QStringLiteral("Near the tall box"));
    camera.position.x -= 0.5f;
    doc.setCamera(camera);
    doc.addBookmark();
    return true;
}

} // namespace

class tst_ProjectFile : public QObject {
    Q_OBJECT

private slots:
    void saveThenOpenGivesTheSameDocument()
    {
        Document doc;
        QVERIFY(makeEditedCornell(doc));
        const QString path = testDir("roundtrip") + QStringLiteral("/edited.vctproj");
        QString error;
        QVERIFY2(doc.saveProject(path, &error), qPrintable(error));

        Document reopened;
        QVERIFY2(reopened.openProject(path, &error), qPrintable(error));
        QVERIFY(sameDocument(doc.state(), reopened.state()));
        QCOMPARE(reopened.filePath(), QFileInfo(path).absoluteFilePath());
        QVERIFY(!reopened.isModified());
        QCOMPARE(reopened.undoStack()->count(), 0);
        QCOMPARE(reopened.buildRenderScene().triangleCount(), doc.buildRenderScene().triangleCount());

        const QJsonObject root = QJsonDocument::fromJson(readFile(path)).object();
        QCOMPARE(root.value("format").toString(), QStringLiteral("vct-studio-project"));
        QCOMPARE(root.value("version").toInt(), 1);
        QCOMPARE(root.value("settings").toObject().value("voxel_res").toString(), QStringLiteral("64"));
        QCOMPARE(root.value("lights").toArray().last().toObject().value("type").toString(),
            QStringLiteral("directional"));
        QCOMPARE(reopened.state().bookmarks.size(), std::size_t(2));
        QCOMPARE(reopened.state().bookmarks[0].name, QStringLiteral("Near the tall box"));
        QCOMPARE(reopened.state().bookmarks[1].name, QStringLiteral("View 2"));
        QCOMPARE(reopened.state().bookmarks[1].camera.position, doc.state().camera.position);

        // Projects from before bookmarks have none, and open.
        QJsonObject old = root;
        old.remove(QStringLiteral("bookmarks"));
        DocumentState state;
        QVERIFY2(ProjectFile::fromJson(QJsonDocument(old).toJson(), QDir::tempPath(),
                     QStringLiteral("old.vctproj"), &state, &error),
            qPrintable(error));
        QVERIFY(state.bookmarks.empty());
    }

    void jsonRoundTrip()
    {
        Document doc;
        QVERIFY(makeEditedCornell(doc));
        const QByteArray json = ProjectFile::toJson(doc.state(), QDir::tempPath());
        DocumentState state;
        QString error;
        QVERIFY2(
            ProjectFile::fromJson(json, QDir::tempPath(), QStringLiteral("memory.vctproj"), &state, &error),
            qPrintable(error));
        QVERIFY(sameDocument(doc.state(), state));
        state.nodes[0].transform.scale.y = 2.0f;
        QVERIFY(!sameDocument(doc.state(), state));
    }

    // Projects saved before materials could be single-sided have no "double_sided": their materials load as
    // double-sided, as they were drawn then; a wrong type is refused with the field named.
    void doubleSidedDefaultsToBothSides()
    {
        Document doc;
        QVERIFY(makeEditedCornell(doc));
        QVERIFY(!doc.state().materials[1].doubleSided);
        QJsonObject root
            = QJsonDocument::fromJson(ProjectFile::toJson(doc.state(), QDir::tempPath())).object();
        QJsonArray materials = root.value("materials").toArray();
        for (qsizetype i = 0; i < materials.size(); ++i) {
            QJsonObject m = materials[i].toObject();
            QVERIFY(m.contains("double_sided"));
            m.remove("double_sided");
            materials[i] = m;
        }
        root["materials"] = materials;
        DocumentState state;
        QString error;
        QVERIFY2(ProjectFile::fromJson(QJsonDocument(root).toJson(), QDir::tempPath(),
                     QStringLiteral("old.vctproj"), &state, &error),
            qPrintable(error));
        for (const vct::render::Material& m : state.materials)
            QVERIFY(m.doubleSided);

        QJsonObject wrong = materials[1].toObject();
        wrong["double_sided"] = QStringLiteral("no");
        materials[1] = wrong;
        root["materials"] = materials;
        QVERIFY(!ProjectFile::fromJson(
            QJsonDocument(root).toJson(), QDir::tempPath(), QStringLiteral("bad.vctproj"), &state, &error));
        QVERIFY2(error.contains(QStringLiteral("materials[1].double_sided")), qPrintable(error));
    }

    void modelPathsAreStoredRelative()
    {
        const QString dir = testDir("relative");
        const QString obj = writeTriangleObj(dir + QStringLiteral("/models/wedge.obj"));
        QVERIFY(!obj.isEmpty());
        Document doc;
        QString error;
        QVERIFY(doc.newFromScene(QStringLiteral("builtin:cornell"), &error));
        QVERIFY2(doc.importModel(obj, &error), qPrintable(error));
        doc.setNodeTransform(
            int(doc.state().nodes.size()) - 1, { { 0.0f, 0.5f, 0.0f }, glm::vec3(0.0f), glm::vec3(1.0f) });
        const QString path = dir + QStringLiteral("/scene.vctproj");
        QVERIFY2(doc.saveProject(path, &error), qPrintable(error));

        const QByteArray text = readFile(path);
        QVERIFY(text.contains("\"models/wedge.obj\""));
        QVERIFY(!text.contains(QDir(dir).absolutePath().toUtf8()));

        // The project and its models move together.
        const QString moved = testDir("relative-moved");
        QVERIFY(QFile::copy(path, moved + QStringLiteral("/scene.vctproj")));
        QVERIFY(!writeTriangleObj(moved + QStringLiteral("/models/wedge.obj")).isEmpty());
        Document reopened;
        QVERIFY2(reopened.openProject(moved + QStringLiteral("/scene.vctproj"), &error), qPrintable(error));
        QCOMPARE(reopened.state().sources.size(), std::size_t(2));
        QCOMPARE(reopened.state().sources[1].spec,
            QDir(moved).absoluteFilePath(QStringLiteral("models/wedge.obj")));
        QCOMPARE(reopened.state().nodes, doc.state().nodes);
        QCOMPARE(reopened.buildRenderScene().triangleCount(), doc.buildRenderScene().triangleCount());
    }

    void corruptFilesAreRefused_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("expected"); // a part of the error message besides the file name

        Document doc;
        QVERIFY(makeEditedCornell(doc));
        const QByteArray valid = ProjectFile::toJson(doc.state(), QDir::tempPath());
        const QJsonObject root = QJsonDocument::fromJson(valid).object();
        auto edited = [&](const std::function<void(QJsonObject&)>& edit) {
            QJsonObject copy = root;
            edit(copy);
            return QJsonDocument(copy).toJson();
        };
        auto editNode0 = [&](const QString& key, const QJsonValue& value) {
            return edited([&](QJsonObject& o) {
                QJsonArray nodes = o.value("nodes").toArray();
                QJsonObject node = nodes[0].toObject();
                node.insert(key, value);
                nodes[0] = node;
                o.insert("nodes", nodes);
            });
        };

        QTest::newRow("empty") << QByteArray() << QStringLiteral("invalid JSON");
        QTest::newRow("truncated") << valid.left(valid.size() / 2)
                                   << QStringLiteral("invalid JSON at offset");
        QTest::newRow("top-level array") << QByteArray("[1, 2]") << QStringLiteral("JSON object");
        QTest::newRow("other format") << edited([](QJsonObject& o) { o.insert("format", "something-else"); })
                                      << QStringLiteral("not a VCT Studio project");
        QTest::newRow("newer version")
            << edited([](QJsonObject& o) { o.insert("version", 7); })
            << QStringLiteral("was saved by a newer VCT Studio (version 7); this one reads version 1");
        QTest::newRow("version as text")
            << edited([](QJsonObject& o) { o.insert("version", "1"); }) << QStringLiteral("'version'");
        QTest::newRow("nodes not an array")
            << edited([](QJsonObject& o) { o.insert("nodes", 5); })
            << QStringLiteral("field 'nodes': expected an array, found a number");
        QTest::newRow("node not an object")
            << edited([](QJsonObject& o) { o.insert("nodes", QJsonArray { 1 }); })
            << QStringLiteral("nodes[0]");
        QTest::newRow("translation of strings") << editNode0("translation", QJsonArray { "a", "b", "c" })
                                                << QStringLiteral("nodes[0].translation");
        QTest::newRow("scale of two")
            << editNode0("scale", QJsonArray { 1, 2 }) << QStringLiteral("nodes[0].scale");
        QTest::newRow("visible as number") << editNode0("visible", 1) << QStringLiteral("nodes[0].visible");
        QTest::newRow("material out of range")
            << editNode0("material", 5) << QStringLiteral("nodes[0].material");
        QTest::newRow("negative source") << editNode0("source", -1) << QStringLiteral("nodes[0].source");
        QTest::newRow("source out of range") << editNode0("source", 1) << QStringLiteral("nodes[0].source");
        QTest::newRow("mesh out of range") << editNode0("mesh", 999) << QStringLiteral("nodes[0].mesh");
        QTest::newRow("fractional material")
            << editNode0("material", 1.5) << QStringLiteral("nodes[0].material");
        QTest::newRow("missing name") << edited([](QJsonObject& o) {
            QJsonArray nodes = o.value("nodes").toArray();
            QJsonObject node = nodes[0].toObject();
            node.remove("name");
            nodes[0] = node;
            o.insert("nodes", nodes);
        }) << QStringLiteral("nodes[0].name");
        QTest::newRow("duplicate id")
            << editNode0("id", root.value("nodes").toArray()[1].toObject().value("id"))
            << QStringLiteral("used twice");
        QByteArray overflow = valid;
        overflow.replace("\"translation\": [", "\"translation\": [1e999, ");
        // JSON has no infinities; Qt's parser refuses the overflowing literal with its offset.
        QTest::newRow("non-finite number") << overflow << QStringLiteral("invalid JSON at offset");
        QByteArray floatOverflow = valid;
        floatOverflow.replace("\"intensity\": ", "\"intensity\": 1e300, \"unused\": ");
        QTest::newRow("number beyond float") << floatOverflow << QStringLiteral("lights[0].intensity");
        QTest::newRow("light type") << edited([](QJsonObject& o) {
            QJsonArray lights = o.value("lights").toArray();
            QJsonObject light = lights[0].toObject();
            light.insert("type", "laser");
            lights[0] = light;
            o.insert("lights", lights);
        }) << QStringLiteral("lights[0].type");
        QTest::newRow("unknown setting") << edited([](QJsonObject& o) {
            QJsonObject s = o.value("settings").toObject();
            s.insert("warp_drive", "on");
            o.insert("settings", s);
        }) << QStringLiteral("settings.warp_drive");
        QTest::newRow("bad setting value") << edited([](QJsonObject& o) {
            QJsonObject s = o.value("settings").toObject();
            s.insert("voxel_res", "100");
            o.insert("settings", s);
        }) << QStringLiteral("settings.voxel_res");
        QTest::newRow("setting as number") << edited([](QJsonObject& o) {
            QJsonObject s = o.value("settings").toObject();
            s.insert("voxel_res", 64);
            o.insert("settings", s);
        }) << QStringLiteral("settings.voxel_res");
        QTest::newRow("camera fov") << edited([](QJsonObject& o) {
            QJsonObject c = o.value("camera").toObject();
            c.insert("fov_y_deg", 0);
            o.insert("camera", c);
        }) << QStringLiteral("camera.fov_y_deg");
        QTest::newRow("next id too small")
            << edited([](QJsonObject& o) { o.insert("next_id", 2); }) << QStringLiteral("next_id");
        QTest::newRow("missing model file") << edited([](QJsonObject& o) {
            QJsonArray sources = o.value("sources").toArray();
            sources.append(QJsonObject { { "spec", "models/gone_missing.obj" } });
            o.insert("sources", sources);
        }) << QStringLiteral("gone_missing.obj");
        // A hostile project naming a device outside the project folder: reading it would never end.
        QTest::newRow("model is a device") << edited([](QJsonObject& o) {
            QJsonArray sources = o.value("sources").toArray();
            sources.append(QJsonObject { { "spec", "/dev/zero" } });
            o.insert("sources", sources);
        }) << QStringLiteral("'/dev/zero' is not a regular file");
        QByteArray badUtf8 = valid;
        badUtf8.replace("Tall box", "Tall \xff\xfe box");
        QTest::newRow("invalid UTF-8") << badUtf8 << QStringLiteral("UTF-8");
        QByteArray nested = valid;
        nested.replace(
            "\"nodes\": [", "\"nodes\": [" + QByteArray(100000, '[') + QByteArray(100000, ']') + ",");
        QTest::newRow("deeply nested arrays") << nested << QStringLiteral("nest deeper");
        QByteArray huge = valid;
        QByteArray zeros;
        zeros.reserve(2 * (ProjectFile::kMaxNodes + 1));
        for (int i = 0; i <= ProjectFile::kMaxNodes; ++i)
            zeros += "0,";
        huge.replace("\"nodes\": [", "\"nodes\": [" + zeros);
        QTest::newRow("huge node count") << huge << QStringLiteral("more than 1000000 are refused");
        QTest::newRow("bookmark with a bad field of view") << edited([](QJsonObject& o) {
            QJsonArray bookmarks = o.value("bookmarks").toArray();
            QJsonObject first = bookmarks[0].toObject();
            first.insert("fov_y_deg", 200.0);
            bookmarks[0] = first;
            o.insert("bookmarks", bookmarks);
        }) << QStringLiteral("bookmarks[0].fov_y_deg");
        QTest::newRow("bookmark without a name") << edited([](QJsonObject& o) {
            QJsonArray bookmarks = o.value("bookmarks").toArray();
            QJsonObject first = bookmarks[0].toObject();
            first.remove("name");
            bookmarks[0] = first;
            o.insert("bookmarks", bookmarks);
        }) << QStringLiteral("bookmarks[0].name");
    }

    void corruptFilesAreRefused()
    {
        QFETCH(QByteArray, content);
        QFETCH(QString, expected);

        // A document that is open with a file, to check nothing of it changes.
        const QString dir = testDir(QStringLiteral("corrupt"));
        Document doc;
        QVERIFY(makeEditedCornell(doc));
        QString error;
        const QString good = dir + QStringLiteral("/good.vctproj");
        QVERIFY2(doc.saveProject(good, &error), qPrintable(error));
        doc.setNodeName(0, QStringLiteral("Unsaved edit"));
        const DocumentState before = doc.state();
        const int undoCount = doc.undoStack()->count();

        const QString bad = dir + QStringLiteral("/broken.vctproj");
        QVERIFY(writeFile(bad, content));
        QVERIFY(!doc.openProject(bad, &error));
        QVERIFY2(error.contains(QStringLiteral("broken.vctproj")), qPrintable(error));
        QVERIFY2(error.contains(expected), qPrintable(error));
        QVERIFY(sameDocument(before, doc.state()));
        QCOMPARE(doc.filePath(), QFileInfo(good).absoluteFilePath());
        QCOMPARE(doc.undoStack()->count(), undoCount);
        QVERIFY(doc.isModified());

        DocumentState state;
        QVERIFY(!ProjectFile::load(bad, &state, &error) || expected.contains(QStringLiteral("mesh")));
    }

    void missingAndOversizedFilesAreRefused()
    {
        const QString dir = testDir(QStringLiteral("oversized"));
        Document doc;
        QVERIFY(makeEditedCornell(doc));
        const DocumentState before = doc.state();
        QString error;
        QVERIFY(!doc.openProject(dir + QStringLiteral("/nothing_here.vctproj"), &error));
        QVERIFY2(error.contains(QStringLiteral("nothing_here.vctproj"))
                && error.contains(QStringLiteral("not found")),
            qPrintable(error));
        QVERIFY(!doc.openProject(dir, &error));
        QVERIFY2(error.contains(QStringLiteral("oversized")), qPrintable(error));

        // Sparse: the size is there without writing 65 MiB.
        const QString big = dir + QStringLiteral("/big.vctproj");
        QFile file(big);
        QVERIFY(file.open(QIODevice::WriteOnly));
        QVERIFY(file.resize(ProjectFile::kMaxFileBytes + 1));
        file.close();
        QVERIFY(!doc.openProject(big, &error));
        QVERIFY2(error.contains(QStringLiteral("big.vctproj")) && error.contains(QStringLiteral("64 MiB")),
            qPrintable(error));
        QVERIFY(sameDocument(before, doc.state()));
        QVERIFY(doc.filePath().isEmpty());
    }

    void savingIntoAMissingFolderFails()
    {
        Document doc;
        QVERIFY(makeEditedCornell(doc));
        QVERIFY(doc.isModified());
        const QString path = testDir(QStringLiteral("nofolder")) + QStringLiteral("/not/there/x.vctproj");
        QString error;
        QVERIFY(!doc.saveProject(path, &error));
        QVERIFY2(
            error.contains(QStringLiteral("x.vctproj")) && error.contains(QStringLiteral("does not exist")),
            qPrintable(error));
        QVERIFY(doc.isModified());
        QVERIFY(doc.filePath().isEmpty());
        QVERIFY(!QFileInfo::exists(path));
    }

    void savingOntoAFolderFails()
    {
        const QString dir = testDir(QStringLiteral("ontofolder"));
        const QString path = dir + QStringLiteral("/taken.vctproj");
        QVERIFY(QDir().mkpath(path));
        Document doc;
        QVERIFY(makeEditedCornell(doc));
        QString error;
        QVERIFY(!doc.saveProject(path, &error));
        QVERIFY2(error.contains(QStringLiteral("taken.vctproj")), qPrintable(error));
        QVERIFY(QFileInfo(path).isDir());
        QVERIFY(doc.isModified());
        QVERIFY(QDir(dir).entryList(QDir::Files | QDir::Hidden).isEmpty()); // no temporary left behind
    }

    void failedSaveLeavesTheOldFileWhole()
    {
        const QString dir = testDir(QStringLiteral("failedsave"));
        const QString path = dir + QStringLiteral("/kept.vctproj");
        Document doc;
        QString error;
        QVERIFY(doc.newFromScene(QStringLiteral("builtin:cornell"), &error));
        QVERIFY2(doc.saveProject(path, &error), qPrintable(error));
        const QByteArray original = readFile(path);
        QVERIFY(!original.isEmpty());

        QVERIFY(makeEditedCornell(doc));
        QVERIFY(doc.isModified());
        {
            vct::test::FileSizeLimit limit(rlim_t(original.size() / 4));
            if (!limit.isActive())
                QSKIP("setrlimit(RLIMIT_FSIZE) is not available");
            QVERIFY(!doc.saveProject(path, &error));
        }
        QVERIFY2(
            error.contains(QStringLiteral("kept.vctproj")) && error.contains(QStringLiteral("cannot save")),
            qPrintable(error));
        QCOMPARE(readFile(path), original);
        QVERIFY(doc.isModified());
        QCOMPARE(
            QDir(dir).entryList(QDir::Files | QDir::Hidden), QStringList { QStringLiteral("kept.vctproj") });

        QVERIFY2(doc.saveProject(path, &error), qPrintable(error));
        QVERIFY(readFile(path) != original);
    }
};

QTEST_GUILESS_MAIN(tst_ProjectFile)
#include "tst_ProjectFile.moc"
