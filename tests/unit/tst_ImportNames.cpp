#include "TestSupport.h"

#include "document/Document.h"
#include "import/ModelImporter.h"

#include <QDir>
#include <QtTest>

using namespace vct;

namespace {

QString outputPath(const QString& name)
{
    return QDir(test::outputDir()).filePath(QStringLiteral("import-names/") + name);
}

std::vector<std::string> meshNames(const QString& path)
{
    render::Scene scene;
    QString error;
    if (!doc::ModelImporter::importModel(path, scene, &error))
        qFatal("cannot import %s: %s", qPrintable(path), qPrintable(error));
    std::vector<std::string> names;
    for (const render::Mesh& mesh : scene.meshes)
        names.push_back(mesh.name);
    return names;
}

} // namespace

/** The names imported geometry gets: what the file says, else the file's own name (issue 20, item 10). */
class ImportNamesTest : public QObject {
    Q_OBJECT

private slots:
    void objWithoutGroupsIsNamedAfterItsFile();
    void namesTheFileGivesAreSaidOnce();
    void unnamedMeshesAreNumberedOnlyWhenTheyWouldCollide();
    void unnamedStlIsNamedAfterItsFile();
};

// Assimp calls the geometry of an OBJ without o/g lines "defaultobject"; the outliner showed
// "defaultobject/defaultobject" for the bunny. The document's node carries the file's name.
void ImportNamesTest::objWithoutGroupsIsNamedAfterItsFile()
{
    const QString bunny = test::sourceDir() + QStringLiteral("/resources/scenes/bunny/bunny.obj");
    QCOMPARE(meshNames(bunny), std::vector<std::string> { "bunny" });

    doc::Document document;
    QString error;
    QVERIFY2(document.newFromScene(QStringLiteral("builtin:cornell_point"), &error), qPrintable(error));
    const std::size_t before = document.state().nodes.size();
    QVERIFY2(document.importModel(bunny, &error), qPrintable(error));
    QCOMPARE(document.state().nodes.size(), before + 1);
    QCOMPARE(document.state().nodes.back().name, QStringLiteral("bunny"));
    // The name is the document's own: it is what a saved project stores, not a display-time rewrite.
    document.undoStack()->undo();
    document.undoStack()->redo();
    QCOMPARE(document.state().nodes.back().name, QStringLiteral("bunny"));
}

// "o floor" made node "floor" holding mesh "floor", shown as "floor/floor".
void ImportNamesTest::namesTheFileGivesAreSaidOnce()
{
    const std::vector<std::string> cornell
        = meshNames(test::sourceDir() + QStringLiteral("/resources/scenes/cornell/cornell_point.obj"));
    QVERIFY(std::find(cornell.begin(), cornell.end(), "floor") != cornell.end());
    QVERIFY(std::find(cornell.begin(), cornell.end(), "shortbox") != cornell.end());
    for (const std::string& name : cornell)
        QVERIFY2(name.find('/') == std::string::npos, name.c_str());
}

// Faces before the first "o" line land in Assimp's default object: it takes the file's name, and a second
// "thing" (the one the file names) would collide with it, so the unnamed one becomes "thing 2".
void ImportNamesTest::unnamedMeshesAreNumberedOnlyWhenTheyWouldCollide()
{
    const QString path = test::writeFile(outputPath(QStringLiteral("thing.obj")),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\no thing\nf 1 3 4\no other\nf 1 2 4\n");
    std::vector<std::string> names = meshNames(path);
    std::sort(names.begin(), names.end());
    QCOMPARE(names, (std::vector<std::string> { "other", "thing", "thing 2" }));

    const QString single = test::writeFile(outputPath(QStringLiteral("single.obj")),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\no other\nf 1 3 4\n");
    names = meshNames(single);
    std::sort(names.begin(), names.end());
    QCOMPARE(names, (std::vector<std::string> { "other", "single" }));
}

// STL and PLY files carry no names at all: before, the document called such a node "mesh 1".
void ImportNamesTest::unnamedStlIsNamedAfterItsFile()
{
    const QString path = test::writeFile(outputPath(QStringLiteral("wedge.stl")),
        "solid\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
        "endsolid\n");
    QCOMPARE(meshNames(path), std::vector<std::string> { "wedge" });
}

QTEST_GUILESS_MAIN(ImportNamesTest)
#include "tst_ImportNames.moc"
