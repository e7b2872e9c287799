#include "core/BrickPool.h"

#include <QtTest>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <vector>

using vct::render::BrickPool;

namespace {

constexpr int kResolution = 64;
constexpr int kBricks = kResolution / BrickPool::kBrickVoxels;

/** Brick 3's voxels are [24, 32): coordinates in [26.1, 30.9] reach no other brick's stored voxels. */
constexpr float kMidBrick3 = 28.0f;

int brickIndex(const glm::ivec3& brick)
{
    return brick.x + kBricks * (brick.y + kBricks * brick.z);
}

std::set<int> allocatedSet(const BrickPool& pool)
{
    std::set<int> bricks;
    for (int z = 0; z < kBricks; ++z)
        for (int y = 0; y < kBricks; ++y)
            for (int x = 0; x < kBricks; ++x)
                if (pool.allocated(glm::ivec3(x, y, z)))
                    bricks.insert(brickIndex(glm::ivec3(x, y, z)));
    return bricks;
}

/** A small triangle in the plane where @p axis is @p coordinate, the other axes in brick 3's middle. */
std::array<glm::vec3, 3> triangleAt(int axis, float coordinate)
{
    std::array<glm::vec3, 3> corners
        = { glm::vec3(27.0f, 27.0f, 27.0f), glm::vec3(29.5f, 27.5f, 29.5f), glm::vec3(27.5f, 29.5f, 28.0f) };
    for (glm::vec3& corner : corners)
        corner[axis] = coordinate;
    return corners;
}

/**
 * The bricks a triangle needs, found the slow way: points sampled every @p step voxels over it, each marking
 * the voxels whose box lies within @p reach of it (k - reach <= p < k + 1 + reach on every axis, inside the
 * grid), each voxel marking the bricks that store it (v >> 3, and the brick below too when v is a brick's
 * first voxel, held in that brick's border). Per axis, as a point's voxels are a box of them and a voxel's
 * bricks the product of its axes' bricks.
 */
std::set<int> referenceBricks(
    const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, double reach, double step)
{
    std::vector<char> marked(std::size_t(kBricks * kBricks * kBricks), 0);
    const double longest = std::max({ glm::length(b - a), glm::length(c - b), glm::length(a - c) });
    const int steps = std::max(1, int(std::ceil(longest / step)));
    for (int i = 0; i <= steps; ++i)
        for (int j = 0; i + j <= steps; ++j) {
            const glm::dvec3 p = a + (b - a) * (double(i) / steps) + (c - a) * (double(j) / steps);
            unsigned brickMask[3] = { 0, 0, 0 };
            for (int axis = 0; axis < 3; ++axis) {
                const int lo = std::max(int(std::floor(p[axis] - 1.0 - reach)) + 1, 0);
                const int hi = std::min(int(std::floor(p[axis] + reach)), kResolution - 1);
                for (int voxel = lo; voxel <= hi; ++voxel) {
                    brickMask[axis] |= 1u << (voxel >> 3);
                    if (voxel % 8 == 0 && voxel > 0)
                        brickMask[axis] |= 1u << ((voxel >> 3) - 1);
                }
            }
            for (int z = 0; z < kBricks; ++z) {
                if (!(brickMask[2] >> z & 1u))
                    continue;
                for (int y = 0; y < kBricks; ++y) {
                    if (!(brickMask[1] >> y & 1u))
                        continue;
                    for (int x = 0; x < kBricks; ++x)
                        if (brickMask[0] >> x & 1u)
                            marked[std::size_t(brickIndex(glm::ivec3(x, y, z)))] = 1;
                }
            }
        }
    std::set<int> bricks;
    for (std::size_t i = 0; i < marked.size(); ++i)
        if (marked[i])
            bricks.insert(int(i));
    return bricks;
}

QString brickName(int index)
{
    return QString("(%1, %2, %3)")
        .arg(index % kBricks)
        .arg(index / kBricks % kBricks)
        .arg(index / (kBricks * kBricks));
}

} // namespace

/**
 * Which bricks of a sparse voxel grid geometry can reach, and where they sit in the pool (core/BrickPool):
 * never a brick missed that the voxelizer writes, few allocated that it does not, slots that stay put while
 * bricks are added, and an indirection table that finds each brick's slot.
 */
class BrickPoolTest : public QObject {
    Q_OBJECT

private slots:
    void triangleInsideABrickAllocatesOnlyIt();
    void bricksSharingAFaceFollowTheBorderAndReach_data();
    void bricksSharingAFaceFollowTheBorderAndReach();
    void neverMissesABrickTheVoxelizerReaches();
    void slotsStayPutAsBricksAreAdded();
    void degenerateTrianglesMarkWhatTheyTouch();
    void nonFiniteTrianglesAreSkippedAndCounted();
    void onlyBricksInsideTheGridAreAllocated();
    void meshesAllocateAsTheirTriangles();
    void poolShapeHoldsEverySlot();
    void tableFindsEachBricksSlot();
};

void BrickPoolTest::triangleInsideABrickAllocatesOnlyIt()
{
    BrickPool pool(kResolution);
    QCOMPARE(pool.bricksPerSide(), kBricks);
    QCOMPARE(pool.allocatedBricks(), std::size_t(0));
    const std::array<glm::vec3, 3> t = triangleAt(0, kMidBrick3);
    QCOMPARE(pool.addTriangle(t[0], t[1], t[2]), 1);
    QCOMPARE(pool.allocatedBricks(), std::size_t(1));
    QCOMPARE(pool.slot(glm::ivec3(3)), 1u);
    QCOMPARE(allocatedSet(pool), std::set<int>({ brickIndex(glm::ivec3(3)) }));
}

void BrickPoolTest::bricksSharingAFaceFollowTheBorderAndReach_data()
{
    // Brick 3 holds voxels [24, 32) and stores [24, 32] with its border; brick 2 stores [16, 24] and brick 4
    // [32, 40]. A triangle at coordinate x writes voxels whose box [k, k + 1] is within reach of x.
    QTest::addColumn<float>("coordinate");
    QTest::addColumn<float>("reach");
    QTest::addColumn<QList<int>>("bricks");
    // Brick 3's low face, x = 24: voxel 24 is brick 2's border.
    QTest::newRow("in voxel 24, brick 2's border") << 24.5f << 1.0f << QList<int> { 2, 3 };
    QTest::newRow("voxel 24 just within reach") << 25.9f << 1.0f << QList<int> { 2, 3 };
    QTest::newRow("voxel 24 just out of reach") << 26.1f << 1.0f << QList<int> { 3 };
    QTest::newRow("in voxel 23, voxel 24 within reach") << 23.5f << 1.0f << QList<int> { 2, 3 };
    QTest::newRow("in brick 2, voxel 24 out of reach") << 22.9f << 1.0f << QList<int> { 2 };
    // Brick 3's high face, x = 32: voxel 32 is brick 4's first and brick 3's border.
    QTest::newRow("in voxel 31, voxel 32 within reach") << 31.5f << 1.0f << QList<int> { 3, 4 };
    QTest::newRow("voxel 32 just out of reach") << 30.9f << 1.0f << QList<int> { 3 };
    QTest::newRow("in voxel 32, brick 3's border") << 32.5f << 1.0f << QList<int> { 3, 4 };
    QTest::newRow("in brick 4, voxel 32 just within reach") << 33.9f << 1.0f << QList<int> { 3, 4 };
    QTest::newRow("in brick 4, voxel 32 just out of reach") << 34.1f << 1.0f << QList<int> { 4 };
    // Without reach only the voxel a triangle lies in is written.
    QTest::newRow("reach 0 in voxel 24") << 24.5f << 0.0f << QList<int> { 2, 3 };
    QTest::newRow("reach 0 in voxel 23") << 23.5f << 0.0f << QList<int> { 2 };
    QTest::newRow("reach 0 in voxel 25") << 25.5f << 0.0f << QList<int> { 3 };
    QTest::newRow("reach 0 in voxel 31") << 31.5f << 0.0f << QList<int> { 3 };
    QTest::newRow("reach 0 in voxel 32") << 32.5f << 0.0f << QList<int> { 3, 4 };
    QTest::newRow("reach 0 in voxel 33") << 33.5f << 0.0f << QList<int> { 4 };
    // A wider reach takes in voxels further off: 22.5 is within 1.5 of voxel 24.
    QTest::newRow("reach 1.5 from voxel 22") << 22.6f << 1.5f << QList<int> { 2, 3 };
}

void BrickPoolTest::bricksSharingAFaceFollowTheBorderAndReach()
{
    QFETCH(float, coordinate);
    QFETCH(float, reach);
    QFETCH(QList<int>, bricks);
    for (int axis = 0; axis < 3; ++axis) {
        BrickPool pool(kResolution);
        const std::array<glm::vec3, 3> t = triangleAt(axis, coordinate);
        pool.addTriangle(t[0], t[1], t[2], reach);
        std::set<int> expected;
        for (int along : bricks) {
            glm::ivec3 brick(3);
            brick[axis] = along;
            expected.insert(brickIndex(brick));
        }
        QVERIFY2(allocatedSet(pool) == expected, qPrintable(QString("axis %1").arg(axis)));
    }
}

void BrickPoolTest::neverMissesABrickTheVoxelizerReaches()
{
    std::mt19937 random(20240611u);
    std::uniform_real_distribution<float> inGrid(-4.0f, float(kResolution) + 4.0f);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    const float sizes[] = { 1.5f, 6.0f, 20.0f };
    const float reaches[] = { 0.0f, 0.5f, 1.0f, 1.0f, 1.5f };
    std::size_t referenceTotal = 0, extraTotal = 0;
    for (int n = 0; n < 200; ++n) {
        const float size = sizes[n % 3];
        const float reach = reaches[n % 5];
        const glm::vec3 a(inGrid(random), inGrid(random), inGrid(random));
        const glm::vec3 b = a + size * glm::vec3(unit(random), unit(random), unit(random));
        glm::vec3 c = a + size * glm::vec3(unit(random), unit(random), unit(random));
        // Every seventh a sliver: c close to the line through a and b.
        if (n % 7 == 0)
            c = a + 0.37f * (b - a) + 0.01f * glm::vec3(unit(random), unit(random), unit(random));
        BrickPool pool(kResolution);
        pool.addTriangle(a, b, c, reach);
        const std::set<int> allocated = allocatedSet(pool);
        const std::set<int> reference = referenceBricks(a, b, c, reach, 0.05);
        for (int brick : reference)
            QVERIFY2(allocated.count(brick) == 1,
                qPrintable(QString("triangle %1 (reach %2) misses brick %3")
                               .arg(n)
                               .arg(reach)
                               .arg(brickName(brick))));
        referenceTotal += reference.size();
        extraTotal += allocated.size() - reference.size();
    }
    QVERIFY(referenceTotal > 500);
    const double extraShare = double(extraTotal) / double(referenceTotal);
    qInfo("%zu bricks reached, %zu more allocated (%.2f%%)", referenceTotal, extraTotal, 100.0 * extraShare);
    QVERIFY2(extraShare <= 0.10, qPrintable(QString("%1% extra bricks").arg(100.0 * extraShare)));
}

void BrickPoolTest::slotsStayPutAsBricksAreAdded()
{
    BrickPool pool(kResolution);
    const std::array<glm::vec3, 3> first = triangleAt(0, kMidBrick3);
    pool.addTriangle(first[0], first[1], first[2]);
    const std::uint32_t firstSlot = pool.slot(glm::ivec3(3));
    QCOMPARE(firstSlot, 1u);
    // Across bricks 5 and 6 on x, elsewhere on y and z.
    const int added = pool.addTriangle(
        glm::vec3(44.0f, 12.0f, 52.0f), glm::vec3(52.0f, 12.5f, 52.5f), glm::vec3(50.0f, 13.0f, 51.0f));
    QVERIFY(added >= 2);
    QCOMPARE(pool.allocatedBricks(), std::size_t(1 + added));
    QCOMPARE(pool.slot(glm::ivec3(3)), firstSlot);
    // The new bricks take the next slots, each once.
    std::set<std::uint32_t> taken;
    for (int index : allocatedSet(pool)) {
        const glm::ivec3 brick(index % kBricks, index / kBricks % kBricks, index / (kBricks * kBricks));
        if (brick != glm::ivec3(3))
            QVERIFY(pool.slot(brick) > firstSlot);
        taken.insert(pool.slot(brick));
    }
    QCOMPARE(taken.size(), pool.allocatedBricks());
    QCOMPARE(*taken.begin(), 1u);
    QCOMPARE(*taken.rbegin(), std::uint32_t(pool.allocatedBricks()));
    // A triangle over bricks already there allocates nothing and moves nothing.
    const std::vector<std::uint32_t> before = pool.table(glm::ivec3(16));
    QCOMPARE(pool.addTriangle(first[0], first[1], first[2]), 0);
    QVERIFY(pool.table(glm::ivec3(16)) == before);
    pool.clear();
    QCOMPARE(pool.allocatedBricks(), std::size_t(0));
    QVERIFY(!pool.allocated(glm::ivec3(3)));
    pool.addTriangle(glm::vec3(12.0f), glm::vec3(12.5f), glm::vec3(12.0f, 13.0f, 12.0f));
    QCOMPARE(pool.slot(glm::ivec3(1)), 1u);
}

void BrickPoolTest::degenerateTrianglesMarkWhatTheyTouch()
{
    {
        BrickPool pool(kResolution);
        const glm::vec3 p(28.3f, 28.6f, 27.9f);
        QCOMPARE(pool.addTriangle(p, p, p), 1);
        QCOMPARE(allocatedSet(pool), std::set<int>({ brickIndex(glm::ivec3(3)) }));
    }
    {
        // In voxel (24, 24, 24), which bricks 2 and 3 both store on every axis.
        BrickPool pool(kResolution);
        const glm::vec3 p(24.5f);
        QCOMPARE(pool.addTriangle(p, p, p), 8);
        for (int index : allocatedSet(pool)) {
            const glm::ivec3 brick(index % kBricks, index / kBricks % kBricks, index / (kBricks * kBricks));
            QVERIFY(glm::all(glm::greaterThanEqual(brick, glm::ivec3(2))));
            QVERIFY(glm::all(glm::lessThanEqual(brick, glm::ivec3(3))));
        }
    }
    // The segment x + y = 24 from (4, 20) to (20, 4) at z = 4: its bounds overlap the grown boxes of bricks
    // (0..2, 0..2, 0), but bricks (0, 0, 0) (x + y <= 20 there) and (2, 2, 0) (x + y >= 30) lie off it, and
    // only the segment's own separating axes can tell.
    const glm::vec3 from(4.0f, 20.0f, 4.0f), to(20.0f, 4.0f, 4.0f);
    for (const std::array<glm::vec3, 3>& segment : { std::array<glm::vec3, 3> { from, to, from },
             std::array<glm::vec3, 3> { from, 0.5f * (from + to), to } }) {
        BrickPool pool(kResolution);
        pool.addTriangle(segment[0], segment[1], segment[2]);
        std::set<int> expected;
        for (int y = 0; y <= 2; ++y)
            for (int x = 0; x <= 2; ++x)
                if (x + y != 0 && x + y != 4)
                    expected.insert(brickIndex(glm::ivec3(x, y, 0)));
        QCOMPARE(allocatedSet(pool), expected);
    }
}

void BrickPoolTest::nonFiniteTrianglesAreSkippedAndCounted()
{
    BrickPool pool(kResolution);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const glm::vec3 inside(kMidBrick3);
    QCOMPARE(pool.addTriangle(inside, glm::vec3(nan, 28.0f, 28.0f), inside + 1.0f), 0);
    QCOMPARE(pool.addTriangle(glm::vec3(-inf, 0.0f, 0.0f), glm::vec3(inf, 0.0f, 0.0f), inside), 0);
    QCOMPARE(pool.addTriangle(inside, inside + 1.0f, inside + glm::vec3(0.0f, 1.0f, 0.0f), nan), 0);
    QCOMPARE(pool.skippedTriangles(), std::size_t(3));
    QCOMPARE(pool.allocatedBricks(), std::size_t(0));
    QVERIFY(allocatedSet(pool).empty());
    pool.clear();
    QCOMPARE(pool.skippedTriangles(), std::size_t(0));
}

void BrickPoolTest::onlyBricksInsideTheGridAreAllocated()
{
    struct Case {
        const char* name;
        float x; // the triangle's plane along x, y and z in brick 3's middle
        int brickX; // -1: none
    };
    // Voxel 63 is the grid's last: a triangle at 64.5 reaches it, one at 65.5 reaches no voxel of the grid.
    const Case cases[] = { { "left of the grid, out of reach", -1.5f, -1 },
        { "left, within reach", -0.5f, 0 }, { "right, within reach", 64.5f, 7 },
        { "right, out of reach", 65.5f, -1 }, { "far off", -20.0f, -1 } };
    for (const Case& c : cases) {
        BrickPool pool(kResolution);
        const std::array<glm::vec3, 3> t = triangleAt(0, c.x);
        pool.addTriangle(t[0], t[1], t[2]);
        const std::set<int> expected
            = c.brickX < 0 ? std::set<int>() : std::set<int>({ brickIndex(glm::ivec3(c.brickX, 3, 3)) });
        QVERIFY2(allocatedSet(pool) == expected, c.name);
        QCOMPARE(pool.skippedTriangles(), std::size_t(0));
    }
    {
        // A plane through the whole grid at z = 30: every brick of layer 3, none else.
        BrickPool pool(kResolution);
        QCOMPARE(pool.addTriangle(glm::vec3(-1000.0f, -1000.0f, 30.0f), glm::vec3(1000.0f, -1000.0f, 30.0f),
                     glm::vec3(0.0f, 1000.0f, 30.0f)),
            kBricks * kBricks);
        for (int index : allocatedSet(pool))
            QCOMPARE(index / (kBricks * kBricks), 3);
    }
    {
        // Finite but enormous coordinates neither overflow the brick range nor lose the bricks crossed.
        BrickPool pool(kResolution);
        pool.addTriangle(
            glm::vec3(-3e38f, 30.0f, 30.0f), glm::vec3(3e38f, 30.0f, 30.0f), glm::vec3(0.0f, 30.5f, 30.0f));
        std::set<int> expected;
        for (int x = 0; x < kBricks; ++x)
            expected.insert(brickIndex(glm::ivec3(x, 3, 3)));
        QCOMPARE(allocatedSet(pool), expected);
        pool.clear();
        QCOMPARE(pool.addTriangle(glm::vec3(1e30f), glm::vec3(2e30f), glm::vec3(1e30f, 2e30f, 1e30f)), 0);
    }
    BrickPool pool(kResolution);
    pool.addTriangle(
        glm::vec3(-100.0f), glm::vec3(200.0f, -100.0f, -100.0f), glm::vec3(-100.0f, 200.0f, 200.0f));
    QVERIFY(pool.allocatedBricks() > 0);
    for (const glm::ivec3& outside : { glm::ivec3(-1, 0, 0), glm::ivec3(0, kBricks, 0), glm::ivec3(0, 0, -1),
             glm::ivec3(kBricks, kBricks, kBricks) }) {
        QVERIFY(!pool.allocated(outside));
        QCOMPARE(pool.slot(outside), 0u);
    }
    // A pool without a grid allocates nothing, and still has a one-brick table.
    BrickPool empty;
    QCOMPARE(empty.addTriangle(glm::vec3(1.0f), glm::vec3(2.0f), glm::vec3(1.0f, 2.0f, 3.0f)), 0);
    QCOMPARE(empty.table(glm::ivec3(1)).size(), std::size_t(1));
}

void BrickPoolTest::meshesAllocateAsTheirTriangles()
{
    // A cube's twelve triangles, [-1, 1]^3 taken to [22, 42]^3 in the grid.
    const std::vector<glm::vec3> positions = { { -1, -1, -1 }, { 1, -1, -1 }, { 1, 1, -1 }, { -1, 1, -1 },
        { -1, -1, 1 }, { 1, -1, 1 }, { 1, 1, 1 }, { -1, 1, 1 } };
    std::vector<std::uint32_t> indices = { 0, 1, 2, 0, 2, 3, 4, 6, 5, 4, 7, 6, 0, 4, 5, 0, 5, 1, 3, 2, 6, 3,
        6, 7, 0, 3, 7, 0, 7, 4, 1, 5, 6, 1, 6, 2 };
    const glm::mat4 toGrid = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(32.0f)), glm::vec3(10.0f));
    BrickPool byTriangle(kResolution);
    for (std::size_t i = 0; i < indices.size(); i += 3)
        byTriangle.addTriangle(glm::vec3(toGrid * glm::vec4(positions[indices[i]], 1.0f)),
            glm::vec3(toGrid * glm::vec4(positions[indices[i + 1]], 1.0f)),
            glm::vec3(toGrid * glm::vec4(positions[indices[i + 2]], 1.0f)));
    // One triangle naming a vertex the mesh lacks, and two indices that make no triangle.
    indices.insert(indices.end(), { 0, 1, 99, 2, 3 });
    BrickPool byMesh(kResolution);
    const int added = byMesh.addMesh(positions, indices, toGrid);
    QCOMPARE(std::size_t(added), byMesh.allocatedBricks());
    QCOMPARE(byMesh.skippedTriangles(), std::size_t(1));
    QVERIFY(byMesh.table(glm::ivec3(16)) == byTriangle.table(glm::ivec3(16)));
    // The surface, not the inside: brick 3's grown box [23, 34]^3 lies between the faces at 22 and 42.
    QVERIFY(byMesh.allocated(glm::ivec3(2)));
    QVERIFY(byMesh.allocated(glm::ivec3(5)));
    QVERIFY(!byMesh.allocated(glm::ivec3(3)));
    QVERIFY(!byMesh.allocated(glm::ivec3(1)));
    QVERIFY(!byMesh.allocated(glm::ivec3(6)));
}

void BrickPoolTest::poolShapeHoldsEverySlot()
{
    const std::size_t most = std::size_t(BrickPool::kMaxPoolBricksPerAxis) * BrickPool::kMaxPoolBricksPerAxis
        * BrickPool::kMaxPoolBricksPerAxis;
    for (const std::size_t bricks :
        { std::size_t(0), std::size_t(1), std::size_t(7), std::size_t(8), std::size_t(26), std::size_t(27),
            std::size_t(1000), std::size_t(12345), std::size_t(2097152), most - 1 }) {
        const glm::ivec3 pool = BrickPool::poolBricksFor(bricks);
        const std::size_t side = std::size_t(pool.x);
        const std::size_t capacity = side * std::size_t(pool.y) * std::size_t(pool.z);
        const QByteArray name = QByteArray::number(qulonglong(bricks));
        QVERIFY2(capacity >= bricks + 1, name);
        QVERIFY2(pool.x == pool.y && pool.z >= 1 && pool.z <= pool.x, name);
        QVERIFY2(pool.x <= BrickPool::kMaxPoolBricksPerAxis, name);
        // The smallest such cube side, and no layer more than needed.
        QVERIFY2(side == 1 || (side - 1) * (side - 1) * (side - 1) < bricks + 1, name);
        QVERIFY2((std::size_t(pool.z) - 1) * side * side < bricks + 1, name);
    }
    QCOMPARE(BrickPool::poolBricksFor(0), glm::ivec3(1));
    QCOMPARE(BrickPool::poolBricksFor(most), glm::ivec3(0));
    QCOMPARE(BrickPool::poolBricksFor(std::numeric_limits<std::size_t>::max()), glm::ivec3(0));

    for (const std::size_t bricks : { std::size_t(0), std::size_t(30), std::size_t(1000) }) {
        const glm::ivec3 pool = BrickPool::poolBricksFor(bricks);
        const std::uint32_t capacity = std::uint32_t(pool.x * pool.y * pool.z);
        std::set<int> cells;
        for (std::uint32_t slot = 0; slot < capacity; ++slot) {
            const glm::ivec3 p = BrickPool::slotPosition(slot, pool);
            QVERIFY(glm::all(glm::greaterThanEqual(p, glm::ivec3(0))) && glm::all(glm::lessThan(p, pool)));
            cells.insert(p.x + pool.x * (p.y + pool.y * p.z));
        }
        QCOMPARE(cells.size(), std::size_t(capacity));
    }
    // x fastest, then y, then z.
    QCOMPARE(BrickPool::slotPosition(0, glm::ivec3(3, 4, 5)), glm::ivec3(0));
    QCOMPARE(BrickPool::slotPosition(1, glm::ivec3(3, 4, 5)), glm::ivec3(1, 0, 0));
    QCOMPARE(BrickPool::slotPosition(3, glm::ivec3(3, 4, 5)), glm::ivec3(0, 1, 0));
    QCOMPARE(BrickPool::slotPosition(12, glm::ivec3(3, 4, 5)), glm::ivec3(0, 0, 1));
}

void BrickPoolTest::tableFindsEachBricksSlot()
{
    BrickPool pool(kResolution);
    std::mt19937 random(7u);
    std::uniform_real_distribution<float> inGrid(0.0f, float(kResolution));
    for (int n = 0; n < 20; ++n) {
        const glm::vec3 a(inGrid(random), inGrid(random), inGrid(random));
        pool.addTriangle(a, a + glm::vec3(9.0f, 1.0f, 0.0f), a + glm::vec3(0.0f, 3.0f, 9.0f));
    }
    QVERIFY(pool.allocatedBricks() > 30);
    const glm::ivec3 poolBricks = BrickPool::poolBricksFor(pool.allocatedBricks());
    const std::vector<std::uint32_t> table = pool.table(poolBricks);
    QCOMPARE(table.size(), std::size_t(kBricks * kBricks * kBricks));
    const std::uint32_t positionMask = (1u << BrickPool::kPositionBits) - 1u;
    std::size_t allocatedWords = 0;
    for (int z = 0; z < kBricks; ++z)
        for (int y = 0; y < kBricks; ++y)
            for (int x = 0; x < kBricks; ++x) {
                const glm::ivec3 brick(x, y, z);
                const std::uint32_t word = table[std::size_t(brickIndex(brick))];
                const std::uint32_t slot = pool.slot(brick);
                if (slot == 0) {
                    QCOMPARE(word, 0u);
                    continue;
                }
                ++allocatedWords;
                QVERIFY(word & BrickPool::kAllocatedBit);
                const glm::ivec3 decoded(int(word & positionMask),
                    int(word >> BrickPool::kPositionBits & positionMask),
                    int(word >> (2 * BrickPool::kPositionBits) & positionMask));
                QCOMPARE(decoded, BrickPool::slotPosition(slot, poolBricks));
                // Slot 0's position, the zero brick, is never a real brick's.
                QVERIFY(decoded != glm::ivec3(0));
            }
    QCOMPARE(allocatedWords, pool.allocatedBricks());
    // A pool too small for every slot: the bricks it cannot hold read as empty, not as a cell outside it.
    const std::vector<std::uint32_t> small = pool.table(glm::ivec3(2, 2, 2));
    std::size_t kept = 0;
    for (std::size_t i = 0; i < small.size(); ++i)
        if (small[i] != 0) {
            ++kept;
            QVERIFY(pool.slot(glm::ivec3(
                        int(i) % kBricks, int(i) / kBricks % kBricks, int(i) / (kBricks * kBricks)))
                < 8u);
        }
    QCOMPARE(kept, std::size_t(7));
}

QTEST_APPLESS_MAIN(BrickPoolTest)
#include "tst_BrickPool.moc"
