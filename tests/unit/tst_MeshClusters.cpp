#include "core/MeshClusters.h"

#include <QtTest>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

using namespace vct::render;

class MeshClustersTest : public QObject {
    Q_OBJECT

private slots:
    void gridIsSplitIntoCompactClusters_data();
    void gridIsSplitIntoCompactClusters();
    void smallMeshIsOneCluster();
    void sharedCentroidTerminates_data();
    void sharedCentroidTerminates();
    void nonFinitePositionsKeepEveryTriangle();
    void emptyInputGivesNoClusters();
};

namespace {

using Triangle = std::array<std::uint32_t, 3>;

std::vector<Triangle> triangles(const std::vector<std::uint32_t>& indices)
{
    std::vector<Triangle> out;
    for (std::size_t i = 0; i + 2 < indices.size(); i += 3)
        out.push_back({ indices[i], indices[i + 1], indices[i + 2] });
    std::sort(out.begin(), out.end());
    return out;
}

/**
 * Every property the clusters must have whatever the geometry. Triangles are compared with their corners in
 * the input order, not just the same rotation class: a changed first corner moves the provoking vertex, and a
 * reversed one flips the winding that back-face culling relies on.
 */
void verifyPartition(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& input,
    const MeshClusters& clusters, std::size_t maxTriangles)
{
    const std::vector<std::uint32_t>& out = clusters.indices();
    QCOMPARE(out.size(), input.size());
    QVERIFY(triangles(out) == triangles(input));

    // The clusters, in index order, must tile the buffer from its start to its end.
    std::vector<MeshCluster> sorted = clusters.clusters();
    std::sort(sorted.begin(), sorted.end(),
        [](const MeshCluster& a, const MeshCluster& b) { return a.firstIndex < b.firstIndex; });
    std::size_t next = 0;
    for (const MeshCluster& c : sorted) {
        QCOMPARE(std::size_t(c.firstIndex), next);
        QVERIFY2(c.indexCount > 0, "an empty cluster costs a draw for nothing");
        QCOMPARE(c.indexCount % 3, 0u); // a cluster never cuts a triangle in two
        QVERIFY2(c.indexCount / 3 <= maxTriangles,
            qPrintable(QStringLiteral("%1 triangles, at most %2").arg(c.indexCount / 3).arg(maxTriangles)));
        next += c.indexCount;
        for (std::uint32_t i = c.firstIndex; i < c.firstIndex + c.indexCount; ++i) {
            const glm::vec3 p = positions[out[i]];
            // A non-finite corner cannot be bounded; culling must still see the finite rest.
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                continue;
            for (int axis = 0; axis < 3; ++axis)
                QVERIFY2(c.bounds.min[axis] <= p[axis] && p[axis] <= c.bounds.max[axis],
                    qPrintable(QStringLiteral("vertex %1 outside its cluster's bounds on axis %2")
                                   .arg(out[i])
                                   .arg(axis)));
        }
    }
    QCOMPARE(next, out.size());
}

/** A planar grid of cells x cells2, two triangles a cell, counter-clockwise, in the plane of axes u and v. */
void grid(int cells, int cells2, int u, int v, std::vector<glm::vec3>& positions,
    std::vector<std::uint32_t>& indices)
{
    for (int j = 0; j <= cells2; ++j)
        for (int i = 0; i <= cells; ++i) {
            glm::vec3 p(0.0f);
            p[u] = float(i);
            p[v] = float(j);
            positions.push_back(p);
        }
    const auto at = [&](int i, int j) { return std::uint32_t(j * (cells + 1) + i); };
    for (int j = 0; j < cells2; ++j)
        for (int i = 0; i < cells; ++i) {
            indices.insert(indices.end(), { at(i, j), at(i + 1, j), at(i + 1, j + 1) });
            indices.insert(indices.end(), { at(i, j), at(i + 1, j + 1), at(i, j + 1) });
        }
}

} // namespace

void MeshClustersTest::gridIsSplitIntoCompactClusters_data()
{
    QTest::addColumn<int>("u");
    QTest::addColumn<int>("v");
    // Every orientation, so a split hard-wired to one axis shows up as long thin clusters.
    QTest::newRow("xy") << 0 << 1;
    QTest::newRow("yz") << 1 << 2;
    QTest::newRow("zx") << 2 << 0;
}

void MeshClustersTest::gridIsSplitIntoCompactClusters()
{
    QFETCH(int, u);
    QFETCH(int, v);
    // 40 x 25 cells: not powers of two, so medians fall inside columns of triangles rather than between them.
    const int cellsU = 40, cellsV = 25;
    const std::size_t maxTriangles = 64;
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
    grid(cellsU, cellsV, u, v, positions, indices);
    const std::size_t triangleCount = indices.size() / 3;
    const MeshClusters clusters(positions, indices, maxTriangles);
    verifyPartition(positions, indices, clusters, maxTriangles);

    // A cluster with more than maxTriangles is halved, so no leaf holds fewer than half of maxTriangles + 1.
    const std::size_t count = clusters.clusters().size();
    QVERIFY(count >= (triangleCount + maxTriangles - 1) / maxTriangles);
    QVERIFY2(count <= triangleCount / ((maxTriangles + 1) / 2), qPrintable(QString::number(count)));

    // 2000 triangles in 32 or more pieces of a 40 x 25 rectangle, each piece cut across its longest side: a
    // compact piece is about 6 cells across (area 32 cells). A piece spanning 30% of the grid, or pieces
    // overlapping by half the grid's area, would be strips, which a frustum can rarely skip.
    double boundsArea = 0.0;
    for (const MeshCluster& c : clusters.clusters()) {
        const glm::vec3 size = c.bounds.size();
        QVERIFY2(size[u] <= 0.3f * float(cellsU) && size[v] <= 0.3f * float(cellsU),
            qPrintable(QStringLiteral("cluster of %1 x %2 cells").arg(size[u]).arg(size[v])));
        QCOMPARE(size[3 - u - v], 0.0f); // flat like the grid
        boundsArea += double(size[u]) * double(size[v]);
    }
    QVERIFY2(boundsArea <= 1.5 * cellsU * cellsV, qPrintable(QString::number(boundsArea)));
}

void MeshClustersTest::smallMeshIsOneCluster()
{
    // A mesh already within the limit has nothing to gain from a split: one cluster, all of it.
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
    grid(4, 3, 0, 1, positions, indices);
    const MeshClusters clusters(positions, indices, 24);
    verifyPartition(positions, indices, clusters, 24);
    QCOMPARE(clusters.clusters().size(), std::size_t(1));
    QCOMPARE(clusters.clusters()[0].bounds.min, glm::vec3(0.0f));
    QCOMPARE(clusters.clusters()[0].bounds.max, glm::vec3(4.0f, 3.0f, 0.0f));
}

void MeshClustersTest::sharedCentroidTerminates_data()
{
    QTest::addColumn<std::vector<glm::vec3>>("positions");
    QTest::addColumn<std::vector<std::uint32_t>>("indices");
    const std::vector<glm::vec3> triangle = { { 0, 0, 0 }, { 3, 0, 0 }, { 0, 3, 0 } };
    std::vector<std::uint32_t> copies, orders, degenerate, allButOne;
    for (int n = 0; n < 100; ++n) {
        copies.insert(copies.end(), { 0, 1, 2 });
        // All six corner orders: the same centroid, summed in different orders, so maybe a few ulps apart.
        static const std::uint32_t kOrders[6][3]
            = { { 0, 1, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 0, 2, 1 }, { 2, 1, 0 }, { 1, 0, 2 } };
        orders.insert(orders.end(), std::begin(kOrders[n % 6]), std::end(kOrders[n % 6]));
        allButOne.insert(allButOne.end(), { 0, 1, 2 });
    }
    // Triangles collapsed to one point, each with its own vertices.
    std::vector<glm::vec3> point(300, glm::vec3(1.5f, -2.0f, 7.0f));
    for (std::uint32_t i = 0; i < 300; ++i)
        degenerate.push_back(i);
    // One outlier lets the first split happen; both halves then hold a single centroid.
    std::vector<glm::vec3> withOutlier = triangle;
    withOutlier.insert(withOutlier.end(), { { 10, 0, 0 }, { 13, 0, 0 }, { 10, 3, 0 } });
    allButOne.insert(allButOne.end(), { 3, 4, 5 });
    QTest::newRow("copies") << triangle << copies;
    QTest::newRow("corner orders") << triangle << orders;
    QTest::newRow("points") << point << degenerate;
    QTest::newRow("all but one") << withOutlier << allButOne;
}

void MeshClustersTest::sharedCentroidTerminates()
{
    QFETCH(std::vector<glm::vec3>, positions);
    QFETCH(std::vector<std::uint32_t>, indices);
    // No median separates equal centroids; the split must still stop and hand back clusters within the limit.
    const std::size_t maxTriangles = 7;
    const MeshClusters clusters(positions, indices, maxTriangles);
    verifyPartition(positions, indices, clusters, maxTriangles);
    QVERIFY(clusters.clusters().size() >= (indices.size() / 3 + maxTriangles - 1) / maxTriangles);
}

void MeshClustersTest::nonFinitePositionsKeepEveryTriangle()
{
    // Hostile models reach this with NaN or infinite vertices; dropping their triangles would change the
    // mesh, and a NaN in the median's comparison is undefined behaviour for nth_element.
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
    grid(12, 10, 0, 1, positions, indices);
    const std::uint32_t first = std::uint32_t(positions.size());
    positions.insert(positions.end(),
        { { nan, 0, 0 }, { 0, nan, nan }, { inf, 1, 1 }, { -inf, 2, 2 }, { 5, 5, inf }, { nan, nan, nan } });
    // Bad corners mixed into good triangles, and triangles of nothing but bad corners.
    for (std::uint32_t k = 0; k < 6; ++k) {
        indices.insert(indices.end(), { first + k, 3 * k, 3 * k + 1 });
        indices.insert(indices.end(), { first + k, first + (k + 1) % 6, first + (k + 2) % 6 });
    }
    for (std::size_t maxTriangles : { std::size_t(1), std::size_t(5), std::size_t(32), std::size_t(1000) }) {
        const MeshClusters clusters(positions, indices, maxTriangles);
        verifyPartition(positions, indices, clusters, maxTriangles);
        if (QTest::currentTestFailed())
            return;
    }
}

void MeshClustersTest::emptyInputGivesNoClusters()
{
    const MeshClusters none({}, {});
    QVERIFY(none.indices().empty());
    QVERIFY(none.clusters().empty());
    // Vertices but no triangles are just as empty.
    const MeshClusters pointsOnly({ { 0, 0, 0 }, { 1, 2, 3 } }, {}, 4);
    QVERIFY(pointsOnly.indices().empty());
    QVERIFY(pointsOnly.clusters().empty());
}

QTEST_GUILESS_MAIN(MeshClustersTest)
#include "tst_MeshClusters.moc"
