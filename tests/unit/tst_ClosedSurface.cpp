#include "core/ClosedSurface.h"
#include "core/MeshClusters.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <QtTest>

#include <cmath>
#include <limits>
#include <optional>
#include <random>

using namespace vct::render;

namespace {

struct TestMesh {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
};

/**
 * The cube [lo, lo + size]^3, 12 triangles counter-clockwise seen from outside. Split: 4 vertices per face
 * (24), as a mesh with per-face normals has them, so only welding by position can close it.
 */
TestMesh cube(const glm::vec3& lo = glm::vec3(0.0f), float size = 1.0f, bool split = false)
{
    // Each face's corners counter-clockwise seen from outside, as corner numbers with bit 0 = x, 1 = y, 2 =
    // z.
    static const int kFaces[6][4] = {
        { 0, 2, 3, 1 }, // z = 0, seen from -z
        { 4, 5, 7, 6 }, // z = 1
        { 0, 1, 5, 4 }, // y = 0
        { 2, 6, 7, 3 }, // y = 1
        { 0, 4, 6, 2 }, // x = 0
        { 1, 3, 7, 5 }, // x = 1
    };
    const auto corner = [&](int c) {
        return lo + size * glm::vec3(float(c & 1), float((c >> 1) & 1), float((c >> 2) & 1));
    };
    TestMesh mesh;
    if (!split)
        for (int c = 0; c < 8; ++c)
            mesh.positions.push_back(corner(c));
    for (const auto& face : kFaces) {
        std::uint32_t v[4];
        for (int k = 0; k < 4; ++k) {
            if (split) {
                v[k] = std::uint32_t(mesh.positions.size());
                mesh.positions.push_back(corner(face[k]));
            } else {
                v[k] = std::uint32_t(face[k]);
            }
        }
        mesh.indices.insert(mesh.indices.end(), { v[0], v[1], v[2], v[0], v[2], v[3] });
    }
    return mesh;
}

/** Both meshes in one, the second's indices moved past the first's vertices. */
TestMesh merged(TestMesh a, const TestMesh& b)
{
    const std::uint32_t base = std::uint32_t(a.positions.size());
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    for (std::uint32_t i : b.indices)
        a.indices.push_back(base + i);
    return a;
}

/** Every triangle with its own three vertices: the surface holds together only through welding. */
TestMesh unshared(const TestMesh& mesh)
{
    TestMesh out;
    for (std::uint32_t i : mesh.indices) {
        out.indices.push_back(std::uint32_t(out.positions.size()));
        out.positions.push_back(mesh.positions[i]);
    }
    return out;
}

/**
 * A UV sphere of radius 1 around the origin: one vertex at each pole and rings of @p segments vertices, the
 * last segment wrapping to the first by index, so it is closed without welding. Counter-clockwise outside.
 */
TestMesh uvSphere(int segments, int rings)
{
    TestMesh mesh;
    mesh.positions.push_back({ 0, 0, 1 });
    for (int r = 1; r < rings; ++r) {
        const double theta = glm::pi<double>() * r / rings;
        for (int s = 0; s < segments; ++s) {
            const double phi = glm::two_pi<double>() * s / segments;
            mesh.positions.push_back(glm::vec3(glm::dvec3(
                std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta))));
        }
    }
    const std::uint32_t south = std::uint32_t(mesh.positions.size());
    mesh.positions.push_back({ 0, 0, -1 });
    const auto at = [&](int r, int s) { return std::uint32_t(1 + (r - 1) * segments + (s % segments)); };
    for (int s = 0; s < segments; ++s) {
        mesh.indices.insert(mesh.indices.end(), { 0u, at(1, s), at(1, s + 1) });
        for (int r = 1; r + 1 < rings; ++r)
            mesh.indices.insert(mesh.indices.end(),
                { at(r, s), at(r + 1, s), at(r + 1, s + 1), at(r, s), at(r + 1, s + 1), at(r, s + 1) });
        mesh.indices.insert(mesh.indices.end(), { at(rings - 1, s), south, at(rings - 1, s + 1) });
    }
    return mesh;
}

/** The mesh as the renderer builds it: clustered first, the surface over the clusters' index order. */
ClosedSurface surface(const TestMesh& mesh, std::size_t maxTriangles = MeshClusters::kDefaultMaxTriangles)
{
    const MeshClusters clusters(mesh.positions, mesh.indices, maxTriangles);
    return ClosedSurface(mesh.positions, clusters.indices(), clusters.clusters());
}

QString describe(const std::optional<int>& w)
{
    return w ? QString::number(*w) : QStringLiteral("none");
}

} // namespace

namespace QTest {
template <> char* toString(const std::optional<int>& w)
{
    return qstrdup(qPrintable(describe(w)));
}
} // namespace QTest

class ClosedSurfaceTest : public QObject {
    Q_OBJECT

private slots:
    void solidity_data();
    void solidity();
    void windingInsideAndOutsideCube_data();
    void windingInsideAndOutsideCube();
    void windingOfTwoDisjointCubes();
    void windingCountsOverlappingCubes();
    void sphereIsSolid_data();
    void sphereIsSolid();
};

void ClosedSurfaceTest::solidity_data()
{
    QTest::addColumn<std::vector<glm::vec3>>("positions");
    QTest::addColumn<std::vector<std::uint32_t>>("indices");
    QTest::addColumn<bool>("solid");
    const auto row = [](const char* name, const TestMesh& mesh, bool solid) {
        QTest::newRow(name) << mesh.positions << mesh.indices << solid;
    };
    row("cube", cube(), true);
    row("split cube", cube(glm::vec3(0.0f), 1.0f, true), true);
    row("unshared cube", unshared(cube()), true);
    // Welding must see -0 and +0 as one position, or half the split cube's edges stay open.
    TestMesh signedZero = cube(glm::vec3(0.0f), 1.0f, true);
    for (std::size_t i = 0; i < signedZero.positions.size(); i += 2)
        for (int axis = 0; axis < 3; ++axis)
            if (signedZero.positions[i][axis] == 0.0f)
                signedZero.positions[i][axis] = -0.0f;
    row("signed zeros", signedZero, true);

    TestMesh holed = cube();
    holed.indices.resize(holed.indices.size() - 3);
    row("triangle missing", holed, false);
    row(
        "split cube, triangle missing",
        [] {
            TestMesh m = cube(glm::vec3(0.0f), 1.0f, true);
            m.indices.erase(m.indices.begin() + 9, m.indices.begin() + 12);
            return m;
        }(),
        false);
    // Turned inside out: closed and consistent, but it encloses negative volume.
    TestMesh inward = cube();
    for (std::size_t t = 0; t < inward.indices.size(); t += 3)
        std::swap(inward.indices[t + 1], inward.indices[t + 2]);
    row("inward cube", inward, false);
    // One face flipped: closed, but its edges run the same way as their neighbours'.
    TestMesh oneFlipped = cube();
    std::swap(oneFlipped.indices[1], oneFlipped.indices[2]);
    std::swap(oneFlipped.indices[4], oneFlipped.indices[5]);
    row("one face flipped", oneFlipped, false);
    row("open quad",
        TestMesh { { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } }, { 0, 1, 2, 0, 2, 3 } }, false);
    // A quad and its back, split along the other diagonal so no directed edge repeats: closed and
    // consistent, but it encloses nothing.
    row("two-sided quad",
        TestMesh {
            { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } }, { 0, 1, 2, 0, 2, 3, 1, 0, 3, 1, 3, 2 } },
        false);
    TestMesh degenerate = cube();
    degenerate.indices.insert(degenerate.indices.end(), { 0, 0, 7 });
    row("degenerate triangle", degenerate, false);
    // Degenerate only once welded: two distinct vertices at one position.
    TestMesh weldedDegenerate = cube();
    weldedDegenerate.positions.push_back(weldedDegenerate.positions[0]);
    weldedDegenerate.indices.insert(weldedDegenerate.indices.end(), { 0, 8, 7 });
    row("degenerate after welding", weldedDegenerate, false);
    // The same cube twice: every edge has four triangles, so the surface is no 2-manifold.
    row("doubled cube", merged(cube(), cube()), false);
    row("two disjoint cubes", merged(cube(), cube(glm::vec3(3.0f, 0.5f, -2.0f), 0.5f)), true);
    row("two overlapping cubes", merged(cube(), cube(glm::vec3(0.5f), 1.0f, true)), true);
    // Each part must be outward on its own: a positive total would hide the inward one.
    TestMesh smallInward = cube(glm::vec3(3.0f), 0.5f);
    for (std::size_t t = 0; t < smallInward.indices.size(); t += 3)
        std::swap(smallInward.indices[t + 1], smallInward.indices[t + 2]);
    row("outward cube and inward cube", merged(cube(), smallInward), false);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    TestMesh withNan = cube();
    withNan.positions[5].y = nan;
    row("nan vertex", withNan, false);
    TestMesh withInf = cube();
    withInf.positions[3].z = std::numeric_limits<float>::infinity();
    row("infinite vertex", withInf, false);
    row("empty", TestMesh {}, false);
}

void ClosedSurfaceTest::solidity()
{
    QFETCH(std::vector<glm::vec3>, positions);
    QFETCH(std::vector<std::uint32_t>, indices);
    QFETCH(bool, solid);
    const TestMesh mesh { positions, indices };
    // One cluster, and several: the verdict is about the mesh, not how it was cut.
    for (const std::size_t maxTriangles :
        { MeshClusters::kDefaultMaxTriangles, std::size_t(4), std::size_t(1) }) {
        const ClosedSurface s = surface(mesh, maxTriangles);
        QCOMPARE(s.isSolid(), solid);
        // A mesh that is not solid has no inside to be in.
        if (!solid)
            QCOMPARE(s.windingNumber(glm::vec3(0.5f, 0.45f, 0.55f)), std::optional<int>());
    }
}

void ClosedSurfaceTest::windingInsideAndOutsideCube_data()
{
    QTest::addColumn<bool>("split");
    QTest::addColumn<int>("maxTriangles");
    QTest::newRow("shared") << false << 512;
    QTest::newRow("shared, clusters of 4") << false << 4;
    QTest::newRow("split, clusters of 4") << true << 4;
    QTest::newRow("split, clusters of 1") << true << 1;
}

void ClosedSurfaceTest::windingInsideAndOutsideCube()
{
    QFETCH(bool, split);
    QFETCH(int, maxTriangles);
    const ClosedSurface s = surface(cube(glm::vec3(0.0f), 1.0f, split), std::size_t(maxTriangles));
    QVERIFY(s.isSolid());
    QCOMPARE(s.windingNumber(glm::vec3(0.5f)), std::optional<int>(1));

    // Points level with the cube's faces, edges and corners (coordinates on its planes or its centre lines),
    // where a ray may run through an edge or a vertex. Answering "none" there is allowed; a wrong count is
    // not.
    const float levels[] = { -1.0f, 0.0f, 0.5f, 1.0f, 2.0f };
    int answered = 0, asked = 0;
    for (float x : levels)
        for (float y : levels)
            for (float z : levels) {
                const glm::vec3 p(x, y, z);
                const bool outside = x < 0.0f || x > 1.0f || y < 0.0f || y > 1.0f || z < 0.0f || z > 1.0f;
                const bool onSurface = !outside
                    && (x == 0.0f || x == 1.0f || y == 0.0f || y == 1.0f || z == 0.0f || z == 1.0f);
                if (onSurface) {
                    // Either side is as right as the other on the surface itself, but nothing else is.
                    const std::optional<int> w = s.windingNumber(p);
                    QVERIFY2(!w || *w == 0 || *w == 1,
                        qPrintable(QStringLiteral("(%1, %2, %3): %4").arg(x).arg(y).arg(z).arg(describe(w))));
                }
                if (!outside)
                    continue;
                ++asked;
                const std::optional<int> w = s.windingNumber(p);
                QVERIFY2(!w || *w == 0,
                    qPrintable(QStringLiteral("(%1, %2, %3): %4").arg(x).arg(y).arg(z).arg(describe(w))));
                answered += w ? 1 : 0;
            }
    // Several directions are tried before giving up, so most of these must get an answer.
    QVERIFY2(answered * 2 > asked, qPrintable(QStringLiteral("%1 of %2 answered").arg(answered).arg(asked)));

    // Points near the cube in every direction, then inside it, off any special line: each has one answer.
    std::mt19937 random(7u);
    std::uniform_real_distribution<float> coord(-1.0f, 2.0f), unit(0.02f, 0.98f);
    for (int n = 0; n < 500; ++n) {
        const glm::vec3 p(coord(random), coord(random), coord(random));
        const bool outside = glm::any(glm::lessThan(p, glm::vec3(-0.01f)))
            || glm::any(glm::greaterThan(p, glm::vec3(1.01f)));
        const bool inside
            = glm::all(glm::greaterThan(p, glm::vec3(0.01f))) && glm::all(glm::lessThan(p, glm::vec3(0.99f)));
        if (!outside && !inside)
            continue;
        QVERIFY2(s.windingNumber(p) == std::optional<int>(inside ? 1 : 0),
            qPrintable(QStringLiteral("(%1, %2, %3): %4")
                           .arg(p.x)
                           .arg(p.y)
                           .arg(p.z)
                           .arg(describe(s.windingNumber(p)))));
        const glm::vec3 q(unit(random), unit(random), unit(random));
        QVERIFY2(s.windingNumber(q) == std::optional<int>(1),
            qPrintable(QStringLiteral("(%1, %2, %3): %4")
                           .arg(q.x)
                           .arg(q.y)
                           .arg(q.z)
                           .arg(describe(s.windingNumber(q)))));
    }
    // A hair off the faces through the origin, closer than the ray test's tolerances: it may give up, but a
    // point outside must never count as inside, nor one inside as outside.
    for (const float hair : { 1e-12f, 1e-20f, 1e-30f })
        for (int axis = 0; axis < 3; ++axis) {
            glm::vec3 p(0.37f, 0.61f, 0.43f);
            p[axis] = -hair;
            const std::optional<int> out = s.windingNumber(p);
            QVERIFY2(
                !out || *out == 0, qPrintable(QStringLiteral("%1 outside: %2").arg(hair).arg(describe(out))));
            p[axis] = hair;
            const std::optional<int> in = s.windingNumber(p);
            QVERIFY2(
                !in || *in == 1, qPrintable(QStringLiteral("%1 inside: %2").arg(hair).arg(describe(in))));
        }
    // Far away, where a ray crosses nothing, and just off each face.
    QCOMPARE(s.windingNumber(glm::vec3(1000.0f, -2000.0f, 500.0f)), std::optional<int>(0));
    for (int axis = 0; axis < 3; ++axis) {
        glm::vec3 below(0.37f, 0.61f, 0.43f), above = below;
        below[axis] = -1e-3f;
        above[axis] = 1.0f + 1e-3f;
        QCOMPARE(s.windingNumber(below), std::optional<int>(0));
        QCOMPARE(s.windingNumber(above), std::optional<int>(0));
        below[axis] = 1e-3f;
        above[axis] = 1.0f - 1e-3f;
        QCOMPARE(s.windingNumber(below), std::optional<int>(1));
        QCOMPARE(s.windingNumber(above), std::optional<int>(1));
    }
}

void ClosedSurfaceTest::windingOfTwoDisjointCubes()
{
    const ClosedSurface s = surface(merged(cube(), cube(glm::vec3(3.0f, 0.5f, -2.0f), 0.5f)), 4);
    QVERIFY(s.isSolid());
    QCOMPARE(s.windingNumber(glm::vec3(0.4f, 0.3f, 0.6f)), std::optional<int>(1));
    QCOMPARE(s.windingNumber(glm::vec3(3.2f, 0.8f, -1.7f)), std::optional<int>(1));
    // Between the two, and beyond each: the rays from here cross one cube or the other, or both.
    QCOMPARE(s.windingNumber(glm::vec3(2.0f, 0.6f, -0.9f)), std::optional<int>(0));
    QCOMPARE(s.windingNumber(glm::vec3(-0.7f, 0.1f, 0.2f)), std::optional<int>(0));
    QCOMPARE(s.windingNumber(glm::vec3(4.1f, 0.2f, -2.3f)), std::optional<int>(0));
}

void ClosedSurfaceTest::windingCountsOverlappingCubes()
{
    // [0, 1]^3 and [0.5, 1.5]^3 in one mesh, each closed on its own; the second split to need welding.
    const TestMesh mesh = merged(cube(), cube(glm::vec3(0.5f), 1.0f, true));
    for (const std::size_t maxTriangles : { std::size_t(512), std::size_t(4) }) {
        const ClosedSurface s = surface(mesh, maxTriangles);
        QVERIFY(s.isSolid());
        QCOMPARE(s.windingNumber(glm::vec3(0.8f, 0.7f, 0.9f)), std::optional<int>(2));
        QCOMPARE(s.windingNumber(glm::vec3(0.6f, 0.95f, 0.55f)), std::optional<int>(2));
        QCOMPARE(s.windingNumber(glm::vec3(0.3f, 0.2f, 0.35f)), std::optional<int>(1)); // the first only
        QCOMPARE(s.windingNumber(glm::vec3(0.8f, 0.7f, 0.2f)), std::optional<int>(1));
        QCOMPARE(s.windingNumber(glm::vec3(1.3f, 1.2f, 1.4f)), std::optional<int>(1)); // the second only
        QCOMPARE(s.windingNumber(glm::vec3(1.2f, 0.7f, 0.8f)), std::optional<int>(1));
        // Inside the union's bounds but in neither cube.
        QCOMPARE(s.windingNumber(glm::vec3(1.3f, 0.2f, 0.25f)), std::optional<int>(0));
        QCOMPARE(s.windingNumber(glm::vec3(0.2f, 1.3f, 1.2f)), std::optional<int>(0));
        QCOMPARE(s.windingNumber(glm::vec3(2.0f, 1.0f, -0.5f)), std::optional<int>(0));
    }
}

void ClosedSurfaceTest::sphereIsSolid_data()
{
    QTest::addColumn<bool>("unshare");
    QTest::addColumn<int>("maxTriangles");
    QTest::newRow("shared") << false << 512;
    QTest::newRow("shared, clusters of 4") << false << 4;
    QTest::newRow("unshared, clusters of 16") << true << 16;
}

void ClosedSurfaceTest::sphereIsSolid()
{
    QFETCH(bool, unshare);
    QFETCH(int, maxTriangles);
    TestMesh sphere = uvSphere(32, 16);
    QCOMPARE(sphere.indices.size(), std::size_t(3 * (2 * 32 + 2 * 32 * 14)));
    // The helper's own promise, checked before the class relies on it: every triangle faces away from the
    // centre.
    for (std::size_t t = 0; t < sphere.indices.size(); t += 3) {
        const glm::vec3 a = sphere.positions[sphere.indices[t]], b = sphere.positions[sphere.indices[t + 1]],
                        c = sphere.positions[sphere.indices[t + 2]];
        QVERIFY(glm::dot(glm::cross(b - a, c - a), a + b + c) > 0.0f);
    }
    if (unshare)
        sphere = unshared(sphere);
    const ClosedSurface s = surface(sphere, std::size_t(maxTriangles));
    QVERIFY(s.isSolid());
    QCOMPARE(s.windingNumber(glm::vec3(0.0f)), std::optional<int>(1));
    // The facets come no closer to the centre than cos(pi/16) * cos(pi/32) > 0.97 of the radius.
    std::mt19937 random(11u);
    std::normal_distribution<float> gauss;
    for (int n = 0; n < 200; ++n) {
        const glm::vec3 dir = glm::normalize(glm::vec3(gauss(random), gauss(random), gauss(random)));
        QCOMPARE(s.windingNumber(0.9f * dir), std::optional<int>(1));
        QCOMPARE(s.windingNumber(0.3f * dir), std::optional<int>(1));
        QCOMPARE(s.windingNumber(1.05f * dir), std::optional<int>(0));
        QCOMPARE(s.windingNumber(4.0f * dir), std::optional<int>(0));
    }
    // Level with the poles, where 32 triangles meet in one vertex, and in the equator's plane.
    for (const glm::vec3& p :
        { glm::vec3(0, 0, 2), glm::vec3(0, 0, -2), glm::vec3(2, 0, 0), glm::vec3(0, -2, 0) }) {
        const std::optional<int> w = s.windingNumber(p);
        QVERIFY2(!w || *w == 0, qPrintable(describe(w)));
    }
}

QTEST_GUILESS_MAIN(ClosedSurfaceTest)
#include "tst_ClosedSurface.moc"
