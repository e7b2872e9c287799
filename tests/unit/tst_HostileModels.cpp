#include "TestSupport.h"

#include "document/ImportReport.h"
#include "import/ModelImporter.h"
#include "import/ModelPreflight.h"

#include <QDir>
#include <QFile>
#include <QtTest>

using vct::doc::ImportReport;
using vct::doc::ModelImporter;
using vct::doc::ModelPreflight;

namespace {

const QByteArray kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n";

QByteArray binaryPly(int claimedVertices, int writtenVertices)
{
    QByteArray bytes = "ply\nformat binary_little_endian 1.0\nelement vertex "
        + QByteArray::number(claimedVertices)
        + "\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
          "property list uchar int vertex_indices\nend_header\n";
    for (int i = 0; i < writtenVertices * 3; ++i) {
        const float value = float(i % 2);
        bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
    }
    return bytes;
}

QByteArray gltfWithBuffer(const QByteArray& uri)
{
    return R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","max":[1,1,0],"min":[0,0,0]}],
"bufferViews":[{"buffer":0,"byteLength":36}],"buffers":[{"uri":")"
        + uri + R"(","byteLength":36}]})";
}

bool writeFile(const QString& path, const QByteArray& bytes)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile file(path);
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(bytes) == bytes.size();
}

QString caseDir(const QString& name)
{
    const QString dir = vct::test::outputDir() + QStringLiteral("/hostile-models/") + name;
    QDir(dir).removeRecursively();
    QDir().mkpath(dir);
    return dir;
}

/** A scene that already holds something, to check a failed import leaves it exactly as it was. */
vct::render::Scene sceneWithOneMesh()
{
    vct::render::Scene scene;
    QString error;
    const QString path = caseDir(QStringLiteral("base")) + QStringLiteral("/base.obj");
    if (!writeFile(path, kTriangleObj) || !ModelImporter::importModel(path, scene, &error))
        qFatal("cannot build the base scene: %s", qPrintable(error));
    return scene;
}

} // namespace

/**
 * Model files from anywhere: truncated, wrong-typed, hostile (huge counts, deep nesting, references outside
 * the model's folder or to devices, invalid UTF-8). Each gives an error naming the file and the problem or,
 * where the model is still usable, imports with a warning; a failed import leaves the scene untouched.
 */
class HostileModelsTest : public QObject {
    Q_OBJECT

private slots:
    void refusedWithAClearError_data();
    void refusedWithAClearError();
    void referencesOutsideTheFolderAreNotRead();
    void texturePointingAtADeviceIsNotRead();
    void invalidUtf8NamesImport();
    void preflightAcceptsValidHeaders();
};

void HostileModelsTest::refusedWithAClearError_data()
{
    QTest::addColumn<QString>("fileName");
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QString>("expected"); // part of the message besides the file name

    QTest::newRow("empty OBJ") << "empty.obj" << QByteArray() << "";
    QTest::newRow("OBJ of text") << "words.obj" << QByteArray("this is not a model\n") << "";
    QTest::newRow("truncated OBJ") << "cut.obj" << kTriangleObj.left(30) << "";
    QTest::newRow("OBJ face indices out of range")
        << "range.obj" << QByteArray("v 0 0 0\nv 1 0 0\nf 1 2 99999999\n") << "";
    QTest::newRow("truncated binary PLY") << "cut.ply" << binaryPly(3, 2) << "more than the";
    QTest::newRow("PLY claiming 2^31-1 vertices")
        << "huge.ply" << binaryPly(0x7fffffff, 3) << "2147483647 instances";
    QTest::newRow("PLY count beyond 2^31")
        << "beyond.ply" << binaryPly(3, 3).replace("vertex 3", "vertex 99999999999") << "count from 0";
    QTest::newRow("PLY count negative")
        << "negative.ply" << binaryPly(3, 3).replace("vertex 3", "vertex -3") << "count from 0";
    QTest::newRow("PLY without end_header")
        << "open.ply" << QByteArray("ply\nformat ascii 1.0\nelement vertex 3\n") << "end_header";
    QTest::newRow("PLY with a bad property type")
        << "type.ply" << binaryPly(3, 3).replace("float x", "quaternion x") << "not a valid property";
    QTest::newRow("PLY with NUL in header")
        << "nul.ply" << binaryPly(3, 3).replace("float z", QByteArray("fl\0at z", 7)) << "not printable";
    QTest::newRow("PLY element without properties")
        << "bare.ply" << QByteArray("ply\nformat ascii 1.0\nelement vertex 100000\nend_header\n")
        << "no properties";
    QTest::newRow("PLY property before element")
        << "order.ply" << QByteArray("ply\nformat ascii 1.0\nproperty float x\nend_header\n")
        << "before any element";
    QTest::newRow("PLY of an unknown format")
        << "format.ply"
        << QByteArray("ply\nformat ebcdic 1.0\nelement vertex 1\nproperty float x\nend_header\n1\n")
        << "unknown format";
    QTest::newRow("truncated glTF") << "cut.gltf" << gltfWithBuffer("data.bin").left(120) << "";
    QTest::newRow("glTF of wrong types")
        << "types.gltf" << gltfWithBuffer("data.bin").replace(R"("count":3)", R"("count":"three")") << "";
    QTest::newRow("deeply nested glTF") << "deep.gltf"
                                        << QByteArray("{\"asset\":{\"version\":\"2.0\"},\"extras\":"
                                               + QByteArray(100000, '[') + QByteArray(100000, ']') + "}")
                                        << "nests deeper than 64";
    QTest::newRow("truncated GLB") << "cut.glb" << QByteArray("glTF\x02\0\0\0\x40\0\0\0\xff\xff\0\0JSON{", 21)
                                   << "JSON chunk claims";
    QTest::newRow("GLB without JSON")
        << "nojson.glb" << QByteArray("glTF\x02\0\0\0\x20\0\0\0\x04\0\0\0BIN\0abcd", 24) << "JSON chunk";
    QTest::newRow("binary noise as FBX") << "noise.fbx" << QByteArray(4096, '\x9c') << "";
}

void HostileModelsTest::refusedWithAClearError()
{
    QFETCH(QString, fileName);
    QFETCH(QByteArray, content);
    QFETCH(QString, expected);

    const QString path
        = caseDir(QString::fromLatin1(QTest::currentDataTag()).replace(QLatin1Char(' '), QLatin1Char('-')))
        + QLatin1Char('/') + fileName;
    QVERIFY(writeFile(path, content));
    vct::render::Scene scene = sceneWithOneMesh();
    const std::size_t meshes = scene.meshes.size(), materials = scene.materials.size();
    const std::size_t vertices = scene.meshes.front().positions.size();
    QString error;
    ImportReport report;
    QVERIFY2(!ModelImporter::importModel(path, scene, &error, &report), "a broken file must not import");
    QVERIFY2(error.contains(fileName), qPrintable(error));
    QVERIFY2(error.contains(expected), qPrintable(error));
    QCOMPARE(scene.meshes.size(), meshes);
    QCOMPARE(scene.materials.size(), materials);
    QCOMPARE(scene.meshes.front().positions.size(), vertices);
}

// A glTF whose buffer lies outside its folder, and an OBJ whose material library does: neither is read.
void HostileModelsTest::referencesOutsideTheFolderAreNotRead()
{
    const QString dir = caseDir(QStringLiteral("outside"));
    QVERIFY(writeFile(dir + QStringLiteral("/secret.bin"), QByteArray(36, '\0')));
    QVERIFY(writeFile(dir + QStringLiteral("/secret.mtl"), "newmtl Stolen\nKd 1 0 0\n"));
    const QString gltf = dir + QStringLiteral("/model/escape.gltf");
    QVERIFY(writeFile(gltf, gltfWithBuffer("../secret.bin")));
    vct::render::Scene scene;
    QString error;
    QVERIFY(!ModelImporter::importModel(gltf, scene, &error));
    QVERIFY2(error.contains(QStringLiteral("escape.gltf"))
            && error.contains(QStringLiteral("outside the model's folder")),
        qPrintable(error));
    QVERIFY(scene.meshes.empty());

    const QString obj = dir + QStringLiteral("/model/escape.obj");
    QVERIFY(writeFile(obj, "mtllib ../secret.mtl\nusemtl Stolen\n" + kTriangleObj));
    ImportReport report;
    QVERIFY2(ModelImporter::importModel(obj, scene, &error, &report), qPrintable(error));
    QVERIFY2(report.warnings.join('\n').contains(QStringLiteral("outside the model's folder")),
        qPrintable(report.warnings.join('\n')));
    // Assimp still names a material after "usemtl Stolen"; its red Kd would only come from the library.
    for (const auto& material : scene.materials)
        QVERIFY2(material.albedo != glm::vec3(1.0f, 0.0f, 0.0f),
            "the material library outside the folder must not be read");
}

void HostileModelsTest::texturePointingAtADeviceIsNotRead()
{
    const QString dir = caseDir(QStringLiteral("device"));
    QVERIFY(QDir().mkpath(dir));
    // A link inside the folder to a device outside it: resolving links is what keeps it out.
    QVERIFY(QFile::link(QStringLiteral("/dev/zero"), dir + QStringLiteral("/zero.png")));
    QVERIFY(writeFile(dir + QStringLiteral("/m.mtl"), "newmtl M\nKd 0.5 0.5 0.5\nmap_Kd zero.png\n"));
    QVERIFY(writeFile(dir + QStringLiteral("/m.obj"), "mtllib m.mtl\nusemtl M\nvt 0 0\n" + kTriangleObj));
    vct::render::Scene scene;
    QString error;
    ImportReport report;
    QVERIFY2(ModelImporter::importModel(dir + QStringLiteral("/m.obj"), scene, &error, &report),
        qPrintable(error));
    QVERIFY2(report.warnings.join('\n').contains(QStringLiteral("zero.png was not read")),
        qPrintable(report.warnings.join('\n')));
    QVERIFY(scene.textures.empty());
    QCOMPARE(scene.triangleCount(), std::size_t(1));
}

void HostileModelsTest::invalidUtf8NamesImport()
{
    const QString path = caseDir(QStringLiteral("utf8")) + QStringLiteral("/names.obj");
    QVERIFY(writeFile(path, "o Ob\xff\xfeject\nmtllib missing\xc3.mtl\nusemtl M\xe2\x82\n" + kTriangleObj));
    vct::render::Scene scene;
    QString error;
    QVERIFY2(ModelImporter::importModel(path, scene, &error), qPrintable(error));
    QCOMPARE(scene.triangleCount(), std::size_t(1));
    for (const auto& material : scene.materials)
        QVERIFY(!QString::fromUtf8(material.name.c_str()).isNull());
}

void HostileModelsTest::preflightAcceptsValidHeaders()
{
    QVERIFY(ModelPreflight::checkPly(binaryPly(3, 3) + QByteArray(7, '\0'), binaryPly(3, 3).size() + 7)
                .isEmpty());
    const QByteArray ascii
        = "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\nelement vertex 3\r\nproperty float x\r\n"
          "property float y\r\nproperty float z\r\nelement face 1\r\nproperty list uchar uint "
          "vertex_indices\r\n"
          "end_header\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n";
    QVERIFY2(ModelPreflight::checkPly(ascii, ascii.size()).isEmpty(),
        qPrintable(ModelPreflight::checkPly(ascii, ascii.size())));
    QVERIFY(ModelPreflight::checkJsonNesting(gltfWithBuffer("data.bin")).isEmpty());
    QVERIFY(ModelPreflight::checkJsonNesting(
        R"({"a":"[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[["})")
                .isEmpty());
    QVERIFY(!ModelPreflight::checkJsonNesting("{]}").isEmpty());
}

QTEST_GUILESS_MAIN(HostileModelsTest)
#include "tst_HostileModels.moc"
