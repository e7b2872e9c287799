#include "cli/SceneSubdivider.h"

#include <glm/geometric.hpp>

#include <QtTest>

#include <cmath>

using namespace vct;

class SceneSubdividerTest : public QObject {
    Q_OBJECT

private slots:
    void factorsMultiplyTrianglesAndKeepArea_data();
    void factorsMultiplyTrianglesAndKeepArea();
    void windingAndNormalsAreKept();
    void sharedEdgesShareMidpoints();
    void longestEdgeIsSplit();
    void rejectsFactorsThatAreNotPowersOfTwo();
};

namespace {

/** Sum of triangle areas, object space. */
double area(const render::Mesh& mesh)
{
    double total = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::dvec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]],
                         c = mesh.positions[mesh.indices[t + 2]];
        total += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    return total;
}

double area(const render::Scene& scene)
{
    double total = 0.0;
    for (const render::Mesh& mesh : scene.meshes)
        total += area(mesh);
    return total;
}

/** A unit cube of 12 triangles (8 shared corners) and a lone skewed triangle with uvs. */
render::Scene testScene()
{
    render::Scene scene;
    render::Mesh cube;
    cube.name = "cube";
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 p(float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1));
        cube.positions.push_back(p);
        cube.normals.push_back(glm::normalize(p - glm::vec3(0.5f)));
    }
    cube.indices = { 0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6,
        1, 3, 5, 3, 7, 5 };
    scene.meshes.push_back(cube);
    render::Mesh skewed;
    skewed.name = "skewed";
    skewed.positions = { { 0, 0, 0 }, { 5, 0, 0 }, { 1, 2, 0 } };
    skewed.normals = { { 0, 0, 1 }, { 0, 0, 1 }, { 0, 0, 1 } };
    skewed.uvs = { { 0, 0 }, { 1, 0 }, { 0, 1 } };
    skewed.indices = { 0, 1, 2 };
    skewed.dynamic = true;
    scene.meshes.push_back(skewed);
    return scene;
}

} // namespace

void SceneSubdividerTest::factorsMultiplyTrianglesAndKeepArea_data()
{
    QTest::addColumn<int>("factor");
    for (int f : { 1, 2, 4, 8, 16 })
        QTest::newRow(qPrintable(QStringLiteral("x%1").arg(f))) << f;
}

void SceneSubdividerTest::factorsMultiplyTrianglesAndKeepArea()
{
    QFETCH(int, factor);
    const render::Scene scene = testScene();
    const render::Scene split = cli::SceneSubdivider::subdivide(scene, factor);
    QCOMPARE(split.triangleCount(), scene.triangleCount() * std::size_t(factor));
    QCOMPARE(split.meshes.size(), scene.meshes.size());
    QVERIFY2(
        std::abs(area(split) - area(scene)) < 1e-4 * area(scene), qPrintable(QString::number(area(split))));
    for (std::size_t m = 0; m < split.meshes.size(); ++m) {
        const render::Mesh& mesh = split.meshes[m];
        QCOMPARE(mesh.normals.size(), mesh.positions.size());
        QVERIFY(mesh.uvs.empty() || mesh.uvs.size() == mesh.positions.size());
        QCOMPARE(mesh.dynamic, scene.meshes[m].dynamic);
        QCOMPARE(mesh.name, scene.meshes[m].name);
        for (std::uint32_t i : mesh.indices)
            QVERIFY(i < mesh.positions.size());
    }
    // The bounds (and so the voxel grid) do not move.
    QCOMPARE(split.bounds().min, scene.bounds().min);
    QCOMPARE(split.bounds().max, scene.bounds().max);
}

void SceneSubdividerTest::windingAndNormalsAreKept()
{
    const render::Mesh skewed = testScene().meshes[1];
    for (const render::Mesh& split :
        { cli::SceneSubdivider::splitInFour(skewed), cli::SceneSubdivider::splitInTwo(skewed) }) {
        // Every child faces +z like its parent: counter-clockwise seen from the front.
        for (std::size_t t = 0; t + 2 < split.indices.size(); t += 3) {
            const glm::vec3 a = split.positions[split.indices[t]], b = split.positions[split.indices[t + 1]],
                            c = split.positions[split.indices[t + 2]];
            QVERIFY(glm::cross(b - a, c - a).z > 0.0f);
        }
        for (const glm::vec3& n : split.normals)
            QCOMPARE(n, glm::vec3(0, 0, 1));
        QCOMPARE(split.uvs[3], glm::vec2(0.5f, 0.0f)); // both split the first edge first
    }
}

void SceneSubdividerTest::sharedEdgesShareMidpoints()
{
    const render::Mesh cube = testScene().meshes[0];
    // 12 edges of the cube plus 6 face diagonals: 18 edges, each split once.
    QCOMPARE(cli::SceneSubdivider::splitInFour(cube).positions.size(), std::size_t(8 + 18));
}

void SceneSubdividerTest::longestEdgeIsSplit()
{
    const render::Mesh split = cli::SceneSubdivider::splitInTwo(testScene().meshes[1]);
    QCOMPARE(split.positions.size(), std::size_t(4));
    // Longest edge of (0,0,0) (5,0,0) (1,2,0) is the first: 5 against sqrt(20) and sqrt(5).
    QCOMPARE(split.positions[3], glm::vec3(2.5f, 0.0f, 0.0f));
    QCOMPARE(split.uvs[3], glm::vec2(0.5f, 0.0f));
}

void SceneSubdividerTest::rejectsFactorsThatAreNotPowersOfTwo()
{
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, cli::SceneSubdivider::subdivide(testScene(), 3));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, cli::SceneSubdivider::subdivide(testScene(), 0));
}

QTEST_GUILESS_MAIN(SceneSubdividerTest)
#include "tst_SceneSubdivider.moc"
