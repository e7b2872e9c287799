#include "TestSupport.h"

#include "document/AtriumGenerator.h"
#include "document/BuiltinScenes.h"
#include "document/CameraFile.h"
#include "document/LightsFile.h"
#include "document/SceneLoader.h"
#include "import/ModelImporter.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <QDir>
#include <QFile>
#include <QSet>
#include <QTest>

#include <cmath>
#include <cstring>
#include <vector>

using namespace vct;

namespace {

QString writeFile(const QString& name, const QByteArray& contents)
{
    const QString path = QDir(test::outputDir()).filePath(name);
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        qFatal("cannot write %s", qPrintable(path));
    file.write(contents);
    return path;
}

QByteArray readFile(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        qFatal("cannot read %s", qPrintable(path));
    return file.readAll();
}

bool near(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-5f)
{
    return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::vec3(tolerance)));
}

QByteArray describe(const glm::vec3& v)
{
    return QStringLiteral("(%1, %2, %3)").arg(v.x).arg(v.y).arg(v.z).toUtf8();
}

const render::Material* findMaterial(const render::Scene& scene, const std::string& name)
{
    for (const render::Material& m : scene.materials)
        if (m.name == name)
            return &m;
    return nullptr;
}

/** Triangles an OBJ file's faces make (an n-gon is n - 2 triangles). */
std::size_t objTriangleCount(const QString& path)
{
    std::size_t triangles = 0;
    for (const QByteArray& line : readFile(path).split('\n')) {
        const QList<QByteArray> words = line.simplified().split(' ');
        if (words.size() >= 4 && words[0] == "f")
            triangles += std::size_t(words.size() - 3);
    }
    return triangles;
}

render::Aabb meshBounds(const render::Mesh& mesh)
{
    render::Aabb box;
    for (const glm::vec3& p : mesh.positions)
        box.extend(glm::vec3(mesh.transform * glm::vec4(p, 1.0f)));
    return box;
}

/** Every triangle's winding agrees with its vertex normals, every normal is unit length and every value
 * finite. */
void checkGeometry(const render::Scene& scene)
{
    for (const render::Mesh& mesh : scene.meshes) {
        QCOMPARE(mesh.normals.size(), mesh.positions.size());
        QVERIFY(mesh.uvs.empty() || mesh.uvs.size() == mesh.positions.size());
        QVERIFY(mesh.material >= 0 && std::size_t(mesh.material) < scene.materials.size());
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            QVERIFY(std::isfinite(mesh.positions[i].x) && std::isfinite(mesh.positions[i].y)
                && std::isfinite(mesh.positions[i].z));
            QVERIFY2(std::abs(glm::length(mesh.normals[i]) - 1.0f) < 1e-3f, mesh.name.c_str());
        }
        int disagreeing = 0;
        for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
            const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
            QVERIFY(a < mesh.positions.size() && b < mesh.positions.size() && c < mesh.positions.size());
            const glm::vec3 face
                = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
            if (glm::dot(face, mesh.normals[a] + mesh.normals[b] + mesh.normals[c]) <= 0.0f)
                ++disagreeing;
        }
        QVERIFY2(disagreeing == 0,
            QByteArray(mesh.name.c_str()) + ": " + QByteArray::number(disagreeing)
                + " triangles wound against their normals");
    }
}

/** Whether a world point is inside the camera's view, with vertical fov from the camera and the given aspect.
 */
bool inView(const render::Camera& camera, const glm::vec3& point, float aspect)
{
    const glm::mat4 view = glm::lookAt(camera.position, camera.lookAt, camera.up);
    const glm::mat4 projection
        = glm::perspective(glm::radians(camera.fovYDeg), aspect, camera.nearPlane, 1000.0f);
    const glm::vec4 clip = projection * view * glm::vec4(point, 1.0f);
    if (clip.w <= 0.0f)
        return false;
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return std::abs(ndc.x) < 1.0f && std::abs(ndc.y) < 1.0f;
}

} // namespace

class TestSceneLoading : public QObject {
    Q_OBJECT

private slots:
    void cornellMaterialsGeometryAndCamera();
    void cornellPointLight();
    void atriumGeometry();
    void bunnyScene();
    void unknownBuiltinListsNames();
    void missingAndGarbageFilesFail();
    void brokenGeometryIsDroppedAndReported();
    void textureIsDecodedTopToBottom();
    void gltfEmissiveStrength();
    void siblingFilesAndFraming();
    void cameraFileRoundTrip();
    void cameraFileErrorsNameTheField();
    void lightsFileErrorsNameTheField();
};

void TestSceneLoading::cornellMaterialsGeometryAndCamera()
{
    render::Scene scene;
    QString error;
    QVERIFY2(doc::SceneLoader::load(QStringLiteral("builtin:cornell"), scene, &error), qPrintable(error));

    QCOMPARE(scene.materials.size(), std::size_t(5));
    struct Expected {
        const char* name;
        glm::vec3 kd;
        glm::vec3 ke;
    };
    const Expected expected[] = {
        { "red", { 0.63f, 0.065f, 0.05f }, glm::vec3(0.0f) },
        { "green", { 0.14f, 0.45f, 0.091f }, glm::vec3(0.0f) },
        { "white", { 0.725f, 0.71f, 0.68f }, glm::vec3(0.0f) },
        { "light", glm::vec3(0.0f), { 17.0f, 12.0f, 4.0f } },
        { "emitblock", { 0.725f, 0.71f, 0.68f }, { 1.0f, 2.5f, 4.0f } },
    };
    for (const Expected& e : expected) {
        const render::Material* m = findMaterial(scene, e.name);
        QVERIFY2(m, e.name);
        QVERIFY2(near(m->albedo, e.kd, 1e-6f), e.name + describe(m->albedo));
        QVERIFY2(near(m->emission, e.ke, 1e-6f), e.name + describe(m->emission));
        QCOMPARE(m->specular, glm::vec3(0.0f));
        QVERIFY(!m->isGlossy());
    }

    QCOMPARE(scene.triangleCount(), objTriangleCount(QStringLiteral(":/scenes/cornell/cornell.obj")));
    QCOMPARE(scene.triangleCount(), std::size_t(48));
    const render::Aabb bounds = scene.bounds();
    QVERIFY2(near(bounds.min, glm::vec3(-1.0f), 1e-4f) && near(bounds.max, glm::vec3(1.0f), 1e-4f),
        describe(bounds.min) + describe(bounds.max));
    QVERIFY(scene.pointLights.empty());
    QVERIFY(scene.hasEmissiveMaterial());
    checkGeometry(scene);

    QCOMPARE(scene.camera.position, glm::vec3(0.0f, 0.0f, 3.8f));
    QCOMPARE(scene.camera.lookAt, glm::vec3(0.0f));
    QCOMPARE(scene.camera.up, glm::vec3(0.0f, 1.0f, 0.0f));
    QCOMPARE(scene.camera.fovYDeg, 40.0f);
}

void TestSceneLoading::cornellPointLight()
{
    render::Scene scene;
    QString error;
    QVERIFY2(
        doc::SceneLoader::load(QStringLiteral("builtin:cornell_point"), scene, &error), qPrintable(error));
    QCOMPARE(scene.pointLights.size(), std::size_t(1));
    QVERIFY(scene.directionalLights.empty());
    QCOMPARE(scene.pointLights[0].position, glm::vec3(0.0f, 0.75f, 0.1f));
    QCOMPARE(scene.pointLights[0].intensity, glm::vec3(4.0f));
    QVERIFY(!scene.hasEmissiveMaterial());
    QCOMPARE(scene.triangleCount(), objTriangleCount(QStringLiteral(":/scenes/cornell/cornell_point.obj")));
    QCOMPARE(scene.camera.position, glm::vec3(0.0f, 0.0f, 3.8f));
}

void TestSceneLoading::atriumGeometry()
{
    render::Scene scene;
    QString error;
    QVERIFY2(doc::SceneLoader::load(QStringLiteral("builtin:atrium"), scene, &error), qPrintable(error));
    qInfo("atrium: %zu triangles, %zu meshes", scene.triangleCount(), scene.meshes.size());
    QVERIFY(scene.triangleCount() >= 20000);
    QVERIFY(scene.triangleCount() <= 80000);
    checkGeometry(scene);

    const render::Aabb staticBounds = scene.bounds(false);
    qInfo("atrium static bounds %s - %s", describe(staticBounds.min).constData(),
        describe(staticBounds.max).constData());
    QVERIFY(staticBounds.size().x >= 30.0f && staticBounds.size().x < 32.0f);
    QVERIFY(staticBounds.size().z >= 14.0f && staticBounds.size().z < 16.0f);
    QCOMPARE(staticBounds.max.y, doc::AtriumGenerator::kHeight);

    float floorTop = -1e9f;
    for (const render::Mesh& mesh : scene.meshes)
        if (mesh.name == "atrium_floor")
            floorTop = meshBounds(mesh).max.y;
    QCOMPARE(floorTop, doc::AtriumGenerator::kFloorY);

    int dynamicMeshes = 0;
    for (const render::Mesh& mesh : scene.meshes) {
        if (!mesh.dynamic)
            continue;
        ++dynamicMeshes;
        const render::Aabb box = meshBounds(mesh);
        QVERIFY2(std::abs(box.min.y - floorTop) < 0.01f, describe(box.min));
        QVERIFY2(std::abs(box.size().y - doc::BuiltinScenes::kBunnyHeight) < 0.01f, describe(box.size()));
        const glm::vec3 centre = box.center();
        QVERIFY(glm::length(glm::vec2(centre.x, centre.z)) > 2.0f);
        QVERIFY(std::abs(centre.x) < 12.0f && std::abs(centre.z) < 3.0f); // In the open courtyard.
        const render::Material& material = scene.materials[std::size_t(mesh.material)];
        QVERIFY(material.albedo.x > 0.5f && material.albedo.x == material.albedo.y
            && material.albedo.y == material.albedo.z);
        QVERIFY2(inView(scene.camera, centre, 1.0f), "the default camera sees the bunny");
    }
    QCOMPARE(dynamicMeshes, 1);

    QSet<QString> clothColours;
    for (const render::Mesh& mesh : scene.meshes) {
        const render::Material& material = scene.materials[std::size_t(mesh.material)];
        QVERIFY(!material.isEmissive());
        QVERIFY(glm::all(glm::lessThanEqual(material.albedo + material.specular, glm::vec3(1.0f))));
        if (material.name.rfind("cloth", 0) == 0) {
            QVERIFY(glm::all(glm::lessThanEqual(material.albedo, glm::vec3(0.8f))));
            clothColours.insert(QString::fromUtf8(describe(material.albedo)));
            QVERIFY2(inView(scene.camera, meshBounds(mesh).center(), 1.0f), mesh.name.c_str());
        }
    }
    QVERIFY(clothColours.size() >= 3);

    QCOMPARE(scene.pointLights.size(), std::size_t(1));
    const render::PointLight& light = scene.pointLights[0];
    QVERIFY(light.castsShadows);
    QVERIFY(light.intensity.x > light.intensity.z); // Warm.
    const float floorAlbedo = findMaterial(scene, "atrium_floor")->albedo.x;
    const float radianceBelow
        = floorAlbedo / 3.14159265f * light.intensity.x / (light.position.y * light.position.y);
    QVERIFY2(radianceBelow > 0.5f && radianceBelow < 2.0f, QByteArray::number(radianceBelow));
    QCOMPARE(scene.camera.fovYDeg, 60.0f);

    render::Scene alias;
    QVERIFY2(doc::SceneLoader::load(QStringLiteral("builtin:default"), alias, &error), qPrintable(error));
    QCOMPARE(alias.triangleCount(), scene.triangleCount());
    // Deterministic: the same positions every time.
    QCOMPARE(alias.meshes[1].positions, scene.meshes[1].positions);
}

void TestSceneLoading::bunnyScene()
{
    render::Scene scene;
    QString error;
    QVERIFY2(doc::BuiltinScenes::load(QStringLiteral("bunny"), scene, &error), qPrintable(error));
    QCOMPARE(scene.pointLights.size(), std::size_t(1));
    const render::Aabb bunny = scene.bounds(true);
    QVERIFY(std::abs(bunny.min.y) < 0.01f);
    QVERIFY(std::abs(bunny.size().y - doc::BuiltinScenes::kBunnyHeight) < 0.01f);
    QVERIFY(scene.triangleCount() > objTriangleCount(QStringLiteral(":/scenes/bunny/bunny.obj")));
    QVERIFY(inView(scene.camera, bunny.center(), 1.0f));
    checkGeometry(scene);
}

void TestSceneLoading::unknownBuiltinListsNames()
{
    render::Scene scene;
    QString error;
    QVERIFY(!doc::SceneLoader::load(QStringLiteral("builtin:nope"), scene, &error));
    QVERIFY2(error.contains(QLatin1String("nope")) && error.contains(QLatin1String("cornell_point"))
            && error.contains(QLatin1String("atrium")),
        qPrintable(error));
    QVERIFY(doc::BuiltinScenes::names().contains(QLatin1String("default")));
}

void TestSceneLoading::missingAndGarbageFilesFail()
{
    render::Scene scene;
    QString error;
    const QString missing = QDir(test::outputDir()).filePath(QStringLiteral("does_not_exist.obj"));
    QVERIFY(!doc::SceneLoader::load(missing, scene, &error));
    QVERIFY2(error.contains(missing) && error.contains(QLatin1String("not found")), qPrintable(error));

    QByteArray noise;
    for (int i = 0; i < 4096; ++i)
        noise.append(char((i * 7919 + 13) % 251));
    for (const char* name : { "garbage.obj", "garbage.gltf", "garbage.ply" }) {
        const QString path = writeFile(QString::fromLatin1(name), noise);
        error.clear();
        QVERIFY2(!doc::SceneLoader::load(path, scene, &error), name);
        QVERIFY2(error.contains(path), qPrintable(error));
        qInfo("%s", qPrintable(error));
    }
    QVERIFY(scene.meshes.empty());
}

void TestSceneLoading::brokenGeometryIsDroppedAndReported()
{
    const QString path = writeFile(QStringLiteral("broken/broken.obj"),
        "v 0 0 0\n"
        "v 1 0 0\n"
        "v 1 1 0\n"
        "v 0 1 0\n"
        "v nan 0.5 0\n"
        "v 2 0 0\n"
        "vn 0 0 1\n"
        "vn nan nan nan\n"
        "f 1//1 2//1 3//1\n"
        "f 1//2 3//2 4//2\n" // good triangle, NaN normals
        "f 1//1 2//1 5//1\n" // NaN vertex
        "f 1//1 2//1 6//1\n"); // collinear: zero area
    render::Scene scene;
    QString error;
    doc::ImportReport report;
    QVERIFY2(doc::ModelImporter::importModel(path, scene, &error, &report), qPrintable(error));
    QCOMPARE(report.triangles, 2);
    QCOMPARE(report.droppedTriangles, 2);
    QCOMPARE(report.nonFiniteTriangles, 1);
    QCOMPARE(report.zeroAreaTriangles, 1);
    QVERIFY2(report.warnings.join(QLatin1Char('\n'))
                 .contains(QStringLiteral("1 for a non-finite vertex, 1 for zero area")),
        qPrintable(report.warnings.join(QLatin1Char('\n'))));
    // JoinIdenticalVertices merges corners whose normals compare unordered (NaN), so fewer than 3 may remain.
    QVERIFY(report.repairedNormals >= 1);
    QCOMPARE(report.meshes, 1);
    QVERIFY(!report.warnings.isEmpty());
    QCOMPARE(scene.triangleCount(), std::size_t(2));
    checkGeometry(scene);
    for (const glm::vec3& n : scene.meshes[0].normals)
        QVERIFY(near(n, glm::vec3(0.0f, 0.0f, 1.0f), 1e-5f));
    const render::Aabb bounds = scene.bounds();
    QVERIFY(near(bounds.min, glm::vec3(0.0f)) && near(bounds.max, glm::vec3(1.0f, 1.0f, 0.0f)));

    // Nothing usable at all is an error that leaves the scene alone.
    const QString empty
        = writeFile(QStringLiteral("broken/degenerate.obj"), "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
    QVERIFY(!doc::ModelImporter::importModel(empty, scene, &error));
    QVERIFY2(error.contains(empty) && error.contains(QLatin1String("triangles")), qPrintable(error));
    QCOMPARE(scene.triangleCount(), std::size_t(2));
}

void TestSceneLoading::textureIsDecodedTopToBottom()
{
    // A 2x2 RGBA PNG, first row red, green; second row blue, white (this test links no Qt Gui to write one).
    writeFile(QStringLiteral("textured/checker.png"),
        QByteArray::fromBase64("iVBORw0KGgoAAAANSUhEUgAAAAIAAAACCAYAAABytg0kAAAAEklEQVR4nGP4z8DwHwyBNBgAAEnIC"
                               "ff5q7YNAAAAAElFTkSuQmCC"));
    writeFile(QStringLiteral("textured/textured.mtl"),
        "newmtl tex\nKd 1 1 1\nKs 0.5 0.5 0.5\nNs 64\nmap_Kd checker.png\n");
    const QString path = writeFile(QStringLiteral("textured/textured.obj"),
        "mtllib textured.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n"
        "usemtl tex\nf 1/1 2/2 3/3\n");
    render::Scene scene;
    QString error;
    doc::ImportReport report;
    QVERIFY2(doc::ModelImporter::importModel(path, scene, &error, &report), qPrintable(error));
    QCOMPARE(scene.textures.size(), std::size_t(1));
    const render::TextureImage& texture = scene.textures[0];
    QCOMPARE(texture.width, 2);
    QCOMPARE(texture.height, 2);
    QCOMPARE(texture.rgba,
        (std::vector<std::uint8_t> { 255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255 }));
    QCOMPARE(scene.materials.size(), std::size_t(1));
    const render::Material& material = scene.materials[0];
    QCOMPARE(material.albedoTexture, 0);
    // Kd 1 + Ks 0.5 reflects more than it receives: scaled to sum 1.
    QCOMPARE(report.clampedMaterials, 1);
    QVERIFY(near(material.albedo + material.specular, glm::vec3(1.0f)));
    QCOMPARE(material.shininess, 64.0f);
    // v is flipped so that v = 0 is the top row: the OBJ's bottom-left corner (vt 0 0) samples the last row.
    QCOMPARE(scene.meshes[0].uvs.size(), std::size_t(3));
    QVERIFY(std::abs(scene.meshes[0].uvs[0].y - 1.0f) < 1e-6f);
}

void TestSceneLoading::gltfEmissiveStrength()
{
    const float positions[9] = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
    const QByteArray buffer(reinterpret_cast<const char*>(positions), sizeof positions);
    const QByteArray gltf = R"({
  "asset": {"version": "2.0"},
  "extensionsUsed": ["KHR_materials_emissive_strength"],
  "scene": 0,
  "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0, "translation": [0, 0, -2]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
  "materials": [{
    "name": "glow",
    "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 0, "roughnessFactor": 1},
    "emissiveFactor": [1, 0.5, 0.25],
    "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 10}}
  }],
  "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,)"
        + buffer.toBase64() + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 1, 0]}]
})";
    const QString path = writeFile(QStringLiteral("gltf/emissive.gltf"), gltf);
    render::Scene scene;
    QString error;
    doc::ImportReport report;
    QVERIFY2(doc::ModelImporter::importModel(path, scene, &error, &report), qPrintable(error));
    QCOMPARE(scene.triangleCount(), std::size_t(1));
    QCOMPARE(scene.materials.size(), std::size_t(1));
    const render::Material& material = scene.materials[0];
    QVERIFY2(near(material.emission, glm::vec3(10.0f, 5.0f, 2.5f), 1e-5f), describe(material.emission));
    // Dielectric, roughness 1: not glossy, the 4% specular folded into the albedo.
    QVERIFY2(near(material.albedo, glm::vec3(0.54f), 1e-5f), describe(material.albedo));
    QVERIFY(!material.isGlossy());
    QVERIFY(near(scene.bounds().max, glm::vec3(1.0f, 1.0f, -2.0f)));
    checkGeometry(scene);
}

void TestSceneLoading::siblingFilesAndFraming()
{
    for (const char* name : { "cornell_point.obj", "cornell_point.mtl", "cornell_point.lights.json" })
        writeFile(QStringLiteral("siblings/") + QLatin1String(name),
            readFile(QStringLiteral(":/scenes/cornell/") + QLatin1String(name)));
    const QString model = QDir(test::outputDir()).filePath(QStringLiteral("siblings/cornell_point.obj"));

    render::Scene scene;
    QString error;
    doc::SceneLoadInfo info;
    QFile::remove(QDir(test::outputDir()).filePath(QStringLiteral("siblings/cornell_point.camera.json")));
    QVERIFY2(doc::SceneLoader::load(model, scene, &error, &info), qPrintable(error));
    QCOMPARE(scene.pointLights.size(), std::size_t(1));
    QVERIFY(!info.hasCameraFile);
    QCOMPARE(info.files.size(), 2);
    // Framed: on +z, looking at the centre, the bounding sphere inside 40 degrees.
    const render::Aabb bounds = scene.bounds();
    QVERIFY(near(scene.camera.lookAt, bounds.center(), 1e-4f));
    const float distance = glm::length(scene.camera.position - scene.camera.lookAt);
    QVERIFY(scene.camera.position.z > bounds.max.z);
    QVERIFY(std::abs(distance * std::sin(glm::radians(20.0f)) - 0.5f * glm::length(bounds.size())) < 1e-3f);
    QCOMPARE(scene.camera.fovYDeg, 40.0f);

    writeFile(QStringLiteral("siblings/cornell_point.camera.json"),
        readFile(QStringLiteral(":/scenes/cornell/cornell.camera.json")));
    QVERIFY2(doc::SceneLoader::load(model, scene, &error, &info), qPrintable(error));
    QVERIFY(info.hasCameraFile);
    QCOMPARE(info.width, 256);
    QCOMPARE(info.height, 256);
    QCOMPARE(scene.camera.position, glm::vec3(0.0f, 0.0f, 3.8f));

    // A broken sibling is an error, not silently ignored.
    writeFile(QStringLiteral("siblings/cornell_point.lights.json"), "{\"lights\": [{\"type\": \"point\"}]}");
    QVERIFY(!doc::SceneLoader::load(model, scene, &error));
    QVERIFY2(error.contains(QLatin1String("lights[0].position")), qPrintable(error));
}

void TestSceneLoading::cameraFileRoundTrip()
{
    doc::CameraSetup setup;
    setup.camera.position = { 1.5f, -2.25f, 3.125f };
    setup.camera.lookAt = { 0.1f, 0.2f, 0.3f };
    setup.camera.up = { 0.0f, 0.0f, 1.0f };
    setup.camera.fovYDeg = 55.5f;
    setup.width = 640;
    setup.height = 360;
    const QString path = QDir(test::outputDir()).filePath(QStringLiteral("roundtrip.camera.json"));
    QString error;
    QVERIFY2(doc::CameraFile::write(path, setup, &error), qPrintable(error));
    doc::CameraSetup back;
    QVERIFY2(doc::CameraFile::read(path, back, &error), qPrintable(error));
    QCOMPARE(back.camera.position, setup.camera.position);
    QCOMPARE(back.camera.lookAt, setup.camera.lookAt);
    QCOMPARE(back.camera.up, setup.camera.up);
    QCOMPARE(back.camera.fovYDeg, setup.camera.fovYDeg);
    QCOMPARE(back.width, 640);
    QCOMPARE(back.height, 360);

    const QString reference = test::referenceDir() + QStringLiteral("/cornell.camera.json");
    if (QFileInfo::exists(reference)) {
        QVERIFY2(doc::CameraFile::read(reference, back, &error), qPrintable(error));
        QCOMPARE(back.camera.position, glm::vec3(0.0f, 0.0f, 3.8f));
        QCOMPARE(back.width, 256);
    }
}

void TestSceneLoading::cameraFileErrorsNameTheField()
{
    struct Case {
        const char* json;
        const char* field;
    };
    const Case cases[] = {
        { R"({"position": [0,0,1], "look_at": [0,0,0], "fov_y_deg": "wide", "width": 4, "height": 4})",
            "fov_y_deg" },
        { R"({"position": [0,0], "look_at": [0,0,0], "fov_y_deg": 40, "width": 4, "height": 4})",
            "position" },
        { R"({"position": [0,0,1], "look_at": [0,0,0], "fov_y_deg": 40, "width": 4.5, "height": 4})",
            "width" },
        { R"({"position": [0,0,1], "look_at": [0,0,0], "fov_y_deg": 40, "width": 4})", "height" },
        { R"({"position": [0,0,1], "look_at": [0,0,1], "fov_y_deg": 40, "width": 4, "height": 4})",
            "look_at" },
    };
    for (const Case& c : cases) {
        const QString path = writeFile(QStringLiteral("bad.camera.json"), c.json);
        doc::CameraSetup setup;
        QString error;
        QVERIFY(!doc::CameraFile::read(path, setup, &error));
        QVERIFY2(error.contains(path) && error.contains(QLatin1String(c.field)), qPrintable(error));
        QCOMPARE(setup.width, 256); // Untouched.
    }
}

void TestSceneLoading::lightsFileErrorsNameTheField()
{
    const QString good = writeFile(QStringLiteral("good.lights.json"),
        R"({"shadows": false, "lights": [
                                       {"type": "point", "position": [0, 1, 0], "intensity": [1, 2, 3]},
                                       {"type": "directional", "direction": [0, -1, 0], "irradiance": [4, 4, 4],
                                        "shadows": true}]})");
    render::Scene scene;
    QString error;
    QVERIFY2(doc::LightsFile::read(good, scene, &error), qPrintable(error));
    QCOMPARE(scene.pointLights.size(), std::size_t(1));
    QCOMPARE(scene.directionalLights.size(), std::size_t(1));
    QVERIFY(!scene.pointLights[0].castsShadows);
    QVERIFY(scene.directionalLights[0].castsShadows);
    QCOMPARE(scene.pointLights[0].intensity, glm::vec3(1.0f, 2.0f, 3.0f));
    QCOMPARE(scene.directionalLights[0].irradiance, glm::vec3(4.0f));

    struct Case {
        const char* json;
        const char* field;
    };
    const Case cases[] = {
        { R"({"lights": [{"type": "point", "position": [0,1,0], "intensity": [1,1,1]}, {"type": 7}]})",
            "lights[1].type" },
        { R"({"lights": [{"type": "laser", "position": [0,1,0], "intensity": [1,1,1]}]})", "lights[0].type" },
        { R"({"lights": [{"type": "point", "position": [0,1,0], "intensity": [1,"x",1]}]})",
            "lights[0].intensity" },
        { R"({"lights": [{"type": "directional", "direction": [0,0,0], "irradiance": [1,1,1]}]})",
            "lights[0].direction" },
        { R"({"lights": {}})", "lights" },
        { R"({"shadows": 1, "lights": []})", "shadows" },
    };
    for (const Case& c : cases) {
        const QString path = writeFile(QStringLiteral("bad.lights.json"), c.json);
        QVERIFY(!doc::LightsFile::read(path, scene, &error));
        QVERIFY2(error.contains(path) && error.contains(QLatin1String(c.field)), qPrintable(error));
    }
    QCOMPARE(scene.pointLights.size(), std::size_t(1)); // Nothing appended by the failures.

    const QString notJson = writeFile(QStringLiteral("notjson.lights.json"), "{lights: oops");
    QVERIFY(!doc::LightsFile::read(notJson, scene, &error));
    QVERIFY2(error.contains(notJson) && error.contains(QLatin1String("JSON")), qPrintable(error));
}

QTEST_GUILESS_MAIN(TestSceneLoading)
#include "tst_SceneLoading.moc"
