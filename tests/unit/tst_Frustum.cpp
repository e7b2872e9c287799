#include "core/Frustum.h"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <random>

using namespace vct::render;

namespace {

// A 90 degree square frustum: its side planes are |right| = forward and |up| = forward, so which boxes touch
// it can be worked out by hand. Near is a power of two so it survives an offset of 1e5 exactly.
constexpr float kNear = 0.125f, kFar = 100.0f;

/** A camera looking along an axis, so a box given in its own frame is still axis-aligned in the world. */
struct Camera {
    glm::vec3 position, forward, up;
    glm::vec3 right() const { return glm::cross(forward, up); }
    glm::mat4 projection() const { return glm::perspective(glm::radians(90.0f), 1.0f, kNear, kFar); }
    /** The matrix of world points minus the position, which Frustum asks for. */
    glm::mat4 relativeViewProjection() const
    {
        return projection() * glm::lookAt(glm::vec3(0.0f), forward, up);
    }
    glm::mat4 worldViewProjection() const
    {
        return projection() * glm::lookAt(position, position + forward, up);
    }

    glm::vec3 toWorld(const glm::vec3& local) const
    {
        return position + local.x * right() + local.y * up + local.z * forward;
    }
    /** A box given as (right, up, forward) ranges in front of the camera. */
    Aabb box(const glm::vec3& localMin, const glm::vec3& localMax) const
    {
        Aabb b;
        b.extend(toWorld(localMin));
        b.extend(toWorld(localMax));
        return b;
    }
};

Camera camera(int view, const glm::vec3& offset)
{
    // The base position is off the world origin so a frustum that ignored its origin fails even unshifted.
    const glm::vec3 base(3.0f, 2.0f, 5.0f);
    switch (view) {
    case 0:
        return { base + offset, { 0, 0, -1 }, { 0, 1, 0 } };
    case 1:
        return { base + offset, { 1, 0, 0 }, { 0, 1, 0 } };
    default:
        return { base + offset, { 0, -1, 0 }, { 0, 0, 1 } };
    }
}

} // namespace

class FrustumTest : public QObject {
    Q_OBJECT

private slots:
    void classifiesBoxes_data();
    void classifiesBoxes();
    void emptyBoxFails();
    void conservativeOnRandomBoxes_data();
    void conservativeOnRandomBoxes();
};

void FrustumTest::classifiesBoxes_data()
{
    QTest::addColumn<int>("view");
    QTest::addColumn<glm::vec3>("offset");
    QTest::addColumn<bool>("worldMatrix");
    QTest::addColumn<glm::vec3>("localMin");
    QTest::addColumn<glm::vec3>("localMax");
    QTest::addColumn<bool>("expected");

    struct Case {
        const char* name;
        glm::vec3 min, max;
        bool expected;
    };
    // Boxes in the camera's (right, up, forward) frame. The "touches" and "misses" pairs sit 1/16 (a 64th of
    // their 4 unit size) inside or outside one plane, where a plane computed far from the origin in single
    // precision would be off by more than that: 1e5 has an ulp of 1/128.
    const float e = 1.0f / 16.0f;
    const Case cases[] = {
        { "in front", { -1, -1, 9 }, { 1, 1, 11 }, true },
        { "behind", { -1, -1, -6 }, { 1, 1, -4 }, false },
        { "before near plane", { -e / 4, -e / 4, e / 4 }, { e / 4, e / 4, e }, false },
        { "beyond far plane", { -1, -1, 200 }, { 1, 1, 210 }, false },
        { "far right", { 50, -1, 9 }, { 52, 1, 11 }, false },
        { "far left", { -52, -1, 9 }, { -50, 1, 11 }, false },
        { "far above", { -1, 50, 9 }, { 1, 52, 11 }, false },
        { "far below", { -1, -52, 9 }, { 1, -50, 11 }, false },
        { "across right plane", { 8, -1, 9 }, { 14, 1, 11 }, true },
        { "across near plane", { -e, -e, -1 }, { e, e, 1 }, true },
        { "around camera", { -1000, -1000, -1000 }, { 1000, 1000, 1000 }, true },
        // Corner (12 - e, 12) inside right <= forward, or (12 + e, 12) outside it.
        { "touches right", { 12 - e, -1, 8 }, { 16 - e, 1, 12 }, true },
        { "misses right", { 12 + e, -1, 8 }, { 16 + e, 1, 12 }, false },
        { "touches left", { -16 + e, -1, 8 }, { -12 + e, 1, 12 }, true },
        { "misses left", { -16 - e, -1, 8 }, { -12 - e, 1, 12 }, false },
        { "touches top", { -1, 12 - e, 8 }, { 1, 16 - e, 12 }, true },
        { "misses top", { -1, 12 + e, 8 }, { 1, 16 + e, 12 }, false },
        { "touches far", { -1, -1, kFar - e }, { 1, 1, kFar + 4 - e }, true },
        { "misses far", { -1, -1, kFar + e }, { 1, 1, kFar + 4 + e }, false },
        { "touches near", { -e / 2, -e / 2, kNear + e - 4 }, { e / 2, e / 2, kNear + e }, true },
        { "misses near", { -e / 2, -e / 2, kNear - e - 4 }, { e / 2, e / 2, kNear - e }, false },
    };
    const char* views[] = { "-z", "+x", "-y" };
    for (int view = 0; view < 3; ++view)
        for (const glm::vec3& offset : { glm::vec3(0.0f), glm::vec3(1e5f, 0.0f, -1e5f) })
            for (const bool worldMatrix : { false, true }) {
                // A world-space matrix with origin 0 is only as precise as its float translation: near 0
                // only.
                if (worldMatrix && offset != glm::vec3(0.0f))
                    continue;
                for (const Case& c : cases)
                    QTest::newRow(qPrintable(QStringLiteral("%1 %2%3 %4")
                                                 .arg(views[view])
                                                 .arg(offset == glm::vec3(0.0f) ? "origin" : "offset")
                                                 .arg(worldMatrix ? " world" : "")
                                                 .arg(c.name)))
                        << view << offset << worldMatrix << c.min << c.max << c.expected;
            }
}

void FrustumTest::classifiesBoxes()
{
    QFETCH(int, view);
    QFETCH(glm::vec3, offset);
    QFETCH(bool, worldMatrix);
    QFETCH(glm::vec3, localMin);
    QFETCH(glm::vec3, localMax);
    QFETCH(bool, expected);
    const Camera cam = camera(view, offset);
    const Frustum frustum = worldMatrix ? Frustum(cam.worldViewProjection(), glm::vec3(0.0f))
                                        : Frustum(cam.relativeViewProjection(), cam.position);
    const Aabb box = cam.box(localMin, localMax);
    QVERIFY(!box.isEmpty());
    QCOMPARE(frustum.mayContain(box), expected);
}

void FrustumTest::emptyBoxFails()
{
    // An empty box is what a mesh with no finite vertex gets: nothing to draw, whatever the view.
    const Camera cam = camera(0, glm::vec3(0.0f));
    const Frustum frustum(cam.relativeViewProjection(), cam.position);
    QVERIFY(!frustum.mayContain(Aabb {}));
    // Empty along one axis only, though its other extents would cover the camera.
    Aabb flatEmpty;
    flatEmpty.min = glm::vec3(-100.0f, 1.0f, -100.0f);
    flatEmpty.max = glm::vec3(100.0f, -1.0f, 100.0f);
    QVERIFY(flatEmpty.isEmpty());
    QVERIFY(!frustum.mayContain(flatEmpty));
}

void FrustumTest::conservativeOnRandomBoxes_data()
{
    QTest::addColumn<glm::vec3>("offset");
    QTest::newRow("origin") << glm::vec3(0.0f);
    QTest::newRow("offset") << glm::vec3(1e5f, 0.0f, -1e5f);
}

// Checks both promises against the frustum's exact shape, in the camera's frame: a box with a point clearly
// inside must pass, and a box clearly beyond one plane must fail. Boxes beyond no single plane but still
// outside (across an edge of the frustum) may go either way.
void FrustumTest::conservativeOnRandomBoxes()
{
    QFETCH(glm::vec3, offset);
    std::mt19937 random(20240611u);
    // Multiples of 1/64, so the boxes are exact at an offset of 1e5 and the reference sees the same box.
    const auto grid = [](double x) { return float(std::round(x * 64.0) / 64.0); };
    std::uniform_real_distribution<double> across(-60.0, 60.0), along(-20.0, 130.0), extent(0.05, 15.0),
        unit(0.0, 1.0);
    const double margin = 0.02;
    const auto inside = [&](const glm::dvec3& p) {
        return std::abs(p.x) < p.z - margin && std::abs(p.y) < p.z - margin && p.z > kNear + margin
            && p.z < kFar - margin;
    };
    // Signed distances (scaled) beyond each of the six planes, positive outside.
    const auto beyond = [](const glm::dvec3& p, int plane) {
        switch (plane) {
        case 0:
            return p.x - p.z;
        case 1:
            return -p.x - p.z;
        case 2:
            return p.y - p.z;
        case 3:
            return -p.y - p.z;
        case 4:
            return kNear - p.z;
        default:
            return p.z - kFar;
        }
    };
    int mustPass = 0, mustFail = 0;
    for (int view = 0; view < 3; ++view) {
        const Camera cam = camera(view, offset);
        const Frustum frustum(cam.relativeViewProjection(), cam.position);
        for (int n = 0; n < 3000; ++n) {
            const glm::vec3 lo(grid(across(random)), grid(across(random)), grid(along(random)));
            const glm::vec3 hi
                = lo + glm::vec3(grid(extent(random)), grid(extent(random)), grid(extent(random)));
            const Aabb box = cam.box(lo, hi);
            bool anyInside = false;
            for (int s = 0; s < 64 && !anyInside; ++s) {
                // The corners first, then points within.
                const glm::dvec3 f = s < 8 ? glm::dvec3(s & 1, (s >> 1) & 1, (s >> 2) & 1)
                                           : glm::dvec3(unit(random), unit(random), unit(random));
                anyInside = inside(glm::dvec3(lo) + f * glm::dvec3(hi - lo));
            }
            bool whollyBeyondOne = false;
            for (int plane = 0; plane < 6 && !whollyBeyondOne; ++plane) {
                bool allBeyond = true;
                for (int c = 0; c < 8; ++c) {
                    const glm::dvec3 corner(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z);
                    allBeyond = allBeyond && beyond(corner, plane) > margin;
                }
                whollyBeyondOne = allBeyond;
            }
            const bool result = frustum.mayContain(box);
            const QString where = QStringLiteral("view %1, local box (%2 %3 %4)-(%5 %6 %7)")
                                      .arg(view)
                                      .arg(lo.x)
                                      .arg(lo.y)
                                      .arg(lo.z)
                                      .arg(hi.x)
                                      .arg(hi.y)
                                      .arg(hi.z);
            if (anyInside) {
                ++mustPass;
                QVERIFY2(result, qPrintable("culled a box with a point inside: " + where));
            } else if (whollyBeyondOne) {
                ++mustFail;
                QVERIFY2(!result, qPrintable("kept a box beyond one plane: " + where));
            }
        }
    }
    // Both kinds must have come up often, or the loop proved little.
    QVERIFY2(
        mustPass > 1000 && mustFail > 1000, qPrintable(QStringLiteral("%1 %2").arg(mustPass).arg(mustFail)));
}

QTEST_GUILESS_MAIN(FrustumTest)
#include "tst_Frustum.moc"
