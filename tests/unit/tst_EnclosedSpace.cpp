#include "core/EnclosedSpace.h"

#include <QtTest>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>
#include <vector>

using vct::render::EnclosedSpace;

namespace {

constexpr int kResolution = 16;

/** The twelve triangles of the box [lo, hi], each face split at its diagonal; @p skipFace (0..5) left out. */
void addBox(EnclosedSpace& space, glm::vec3 lo, glm::vec3 hi, int skipFace = -1)
{
    const glm::vec3 c[8]
        = { { lo.x, lo.y, lo.z }, { hi.x, lo.y, lo.z }, { hi.x, hi.y, lo.z }, { lo.x, hi.y, lo.z },
              { lo.x, lo.y, hi.z }, { hi.x, lo.y, hi.z }, { hi.x, hi.y, hi.z }, { lo.x, hi.y, hi.z } };
    const int faces[6][4]
        = { { 0, 1, 2, 3 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 }, { 3, 2, 6, 7 }, { 0, 3, 7, 4 }, { 1, 2, 6, 5 } };
    for (int f = 0; f < 6; ++f) {
        if (f == skipFace)
            continue;
        space.addTriangle(c[faces[f][0]], c[faces[f][1]], c[faces[f][2]]);
        space.addTriangle(c[faces[f][0]], c[faces[f][2]], c[faces[f][3]]);
    }
}

} // namespace

/** Which empty cells no light can leave: the map the diffuse gathers scale their cones by (no GL). */
class EnclosedSpaceTest : public QObject {
    Q_OBJECT

private slots:
    void closedBoxEnclosesItsInside_data();
    void closedBoxEnclosesItsInside();
    void anOpenFaceOpensTheBox();
    void aHoleWiderThanACellOpensTheBox();
    void facesMeetingWithinRoundingStayClosed();
    void slantedClosedMeshEnclosesItsCentre();
    void texelsMarkOnlyEnclosedCells();
    void badTrianglesAreSkippedAndCounted();
    void resolutionIsClamped();
};

void EnclosedSpaceTest::closedBoxEnclosesItsInside_data()
{
    QTest::addColumn<float>("lo");
    QTest::addColumn<float>("hi");
    QTest::addColumn<int>("first"); // the first and last cells inside that no wall touches
    QTest::addColumn<int>("last");
    // Walls on cell faces touch the cells on both sides.
    QTest::newRow("on cell faces") << 4.0f << 12.0f << 5 << 10;
    QTest::newRow("inside cells") << 4.3f << 11.7f << 5 << 10;
    QTest::newRow("grid-filling") << 0.5f << 15.5f << 1 << 14;
}

void EnclosedSpaceTest::closedBoxEnclosesItsInside()
{
    QFETCH(float, lo);
    QFETCH(float, hi);
    QFETCH(int, first);
    QFETCH(int, last);
    EnclosedSpace space(kResolution);
    addBox(space, glm::vec3(lo), glm::vec3(hi));
    space.solve();
    const int side = last - first + 1;
    QCOMPARE(space.enclosedCells(), std::size_t(side * side * side));
    QVERIFY(space.enclosed(glm::ivec3(first)));
    QVERIFY(space.enclosed(glm::ivec3(last)));
    QVERIFY(space.enclosed(glm::ivec3(first, last, first)));
    QVERIFY(!space.enclosed(glm::ivec3(first - 1))); // a wall's cell
    QVERIFY(space.occupied(glm::ivec3(first - 1, first + 1, first + 1)));
    QVERIFY(!space.enclosed(glm::ivec3(0, 0, 0))); // outside the box, or a wall's cell
    QVERIFY(!space.enclosed(glm::ivec3(-1, 5, 5))); // outside the grid
    QVERIFY(!space.enclosed(glm::ivec3(5, kResolution, 5)));
}

void EnclosedSpaceTest::anOpenFaceOpensTheBox()
{
    for (int face = 0; face < 6; ++face) {
        EnclosedSpace space(kResolution);
        addBox(space, glm::vec3(4.3f), glm::vec3(11.7f), face);
        space.solve();
        QCOMPARE(space.enclosedCells(), std::size_t(0));
    }
}

void EnclosedSpaceTest::aHoleWiderThanACellOpensTheBox()
{
    // The top face (y = 11.7) in two parts with a gap from x = 6.9 to 9.1: cells x = 7 and 8 lie wholly in
    // it.
    EnclosedSpace space(kResolution);
    addBox(space, glm::vec3(4.3f), glm::vec3(11.7f), 3);
    const float y = 11.7f;
    space.addTriangle({ 4.3f, y, 4.3f }, { 6.9f, y, 4.3f }, { 6.9f, y, 11.7f });
    space.addTriangle({ 4.3f, y, 4.3f }, { 6.9f, y, 11.7f }, { 4.3f, y, 11.7f });
    space.addTriangle({ 9.1f, y, 4.3f }, { 11.7f, y, 4.3f }, { 11.7f, y, 11.7f });
    space.addTriangle({ 9.1f, y, 4.3f }, { 11.7f, y, 11.7f }, { 9.1f, y, 11.7f });
    space.solve();
    QCOMPARE(space.enclosedCells(), std::size_t(0));
}

void EnclosedSpaceTest::facesMeetingWithinRoundingStayClosed()
{
    // The same top face split at x = 8 with a gap of 1e-5 cells, narrower than any path between cells.
    EnclosedSpace space(kResolution);
    addBox(space, glm::vec3(4.3f), glm::vec3(11.7f), 3);
    const float y = 11.7f, a = 8.0f, b = 8.00001f;
    space.addTriangle({ 4.3f, y, 4.3f }, { a, y, 4.3f }, { a, y, 11.7f });
    space.addTriangle({ 4.3f, y, 4.3f }, { a, y, 11.7f }, { 4.3f, y, 11.7f });
    space.addTriangle({ b, y, 4.3f }, { 11.7f, y, 4.3f }, { 11.7f, y, 11.7f });
    space.addTriangle({ b, y, 4.3f }, { 11.7f, y, 11.7f }, { b, y, 11.7f });
    space.solve();
    QCOMPARE(space.enclosedCells(), std::size_t(216));
}

void EnclosedSpaceTest::slantedClosedMeshEnclosesItsCentre()
{
    // An octahedron turned about two axes, through a mesh and a transform as the renderer passes them.
    const std::vector<glm::vec3> positions
        = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
    const std::vector<std::uint32_t> indices
        = { 0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5 };
    glm::mat4 toGrid = glm::translate(glm::mat4(1.0f), glm::vec3(8.0f));
    toGrid = glm::rotate(toGrid, 0.4f, glm::vec3(1, 0, 0));
    toGrid = glm::rotate(toGrid, 0.7f, glm::vec3(0, 1, 0));
    toGrid = glm::scale(toGrid, glm::vec3(6.5f));
    EnclosedSpace space(kResolution);
    space.addMesh(positions, indices, toGrid);
    space.solve();
    QVERIFY(space.enclosed(glm::ivec3(8)));
    QVERIFY(space.enclosed(glm::ivec3(7)));
    QVERIFY(!space.enclosed(glm::ivec3(1)));
    // Every enclosed cell lies inside the octahedron (|x| + |y| + |z| < 1 in its own space).
    const glm::mat4 toObject = glm::inverse(toGrid);
    glm::ivec3 cell;
    for (cell.z = 0; cell.z < kResolution; ++cell.z)
        for (cell.y = 0; cell.y < kResolution; ++cell.y)
            for (cell.x = 0; cell.x < kResolution; ++cell.x)
                if (space.enclosed(cell)) {
                    const glm::vec3 p = glm::vec3(toObject * glm::vec4(glm::vec3(cell) + 0.5f, 1.0f));
                    QVERIFY2(std::abs(p.x) + std::abs(p.y) + std::abs(p.z) < 1.0f,
                        qPrintable(QString("cell %1 %2 %3").arg(cell.x).arg(cell.y).arg(cell.z)));
                }
}

void EnclosedSpaceTest::texelsMarkOnlyEnclosedCells()
{
    EnclosedSpace space(kResolution);
    addBox(space, glm::vec3(4.3f), glm::vec3(11.7f));
    space.solve();
    const std::vector<std::uint8_t> texels = space.texels();
    QCOMPARE(texels.size(), std::size_t(kResolution * kResolution * kResolution));
    std::size_t marked = 0;
    for (int i = 0; i < int(texels.size()); ++i) {
        const glm::ivec3 cell(
            i % kResolution, (i / kResolution) % kResolution, i / (kResolution * kResolution));
        QCOMPARE(texels[std::size_t(i)], std::uint8_t(space.enclosed(cell) ? 255 : 0));
        marked += texels[std::size_t(i)] != 0 ? 1 : 0;
    }
    QCOMPARE(marked, space.enclosedCells());
}

void EnclosedSpaceTest::badTrianglesAreSkippedAndCounted()
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    EnclosedSpace space(kResolution);
    addBox(space, glm::vec3(4.3f), glm::vec3(11.7f));
    space.addTriangle({ nan, 5, 5 }, { 6, 5, 5 }, { 6, 6, 5 });
    space.addTriangle({ 5, 5, 5 }, { inf, 5, 5 }, { 6, 6, 5 });
    space.addMesh({ { 5, 5, 5 }, { 6, 5, 5 }, { 6, 6, 5 } }, { 0, 1, 7 }, glm::mat4(1.0f));
    // Far outside the grid, and a point: nothing marked, nothing skipped.
    space.addTriangle({ 1e30f, 5, 5 }, { 2e30f, 5, 5 }, { 2e30f, 6, 5 });
    space.addTriangle({ 8, 8, 8 }, { 8, 8, 8 }, { 8, 8, 8 });
    space.solve();
    QCOMPARE(space.skippedTriangles(), std::size_t(3));
    // The point marks its cells, which are then not enclosed; the rest of the inside still is.
    QVERIFY(space.occupied(glm::ivec3(8)));
    QVERIFY(space.enclosed(glm::ivec3(5)));
    QVERIFY(space.enclosedCells() < std::size_t(216) && space.enclosedCells() >= std::size_t(216 - 8));
}

void EnclosedSpaceTest::resolutionIsClamped()
{
    QCOMPARE(EnclosedSpace(0).resolution(), 1);
    QCOMPARE(EnclosedSpace(-5).resolution(), 1);
    QCOMPARE(EnclosedSpace(4096).resolution(), EnclosedSpace::kMaxResolution);
    EnclosedSpace one(1);
    addBox(one, glm::vec3(0.2f), glm::vec3(0.8f));
    one.solve();
    QCOMPARE(one.enclosedCells(), std::size_t(0)); // the only cell is a wall's
}

QTEST_GUILESS_MAIN(EnclosedSpaceTest)
#include "tst_EnclosedSpace.moc"
