#include "scene/DirectionalStackLayout.h"

#include <QtTest>

using vct::render::DirectionalStackLayout;

/**
 * The directional chains' shared texture (scene/DirectionalStackLayout.h): half-tile gaps while the stack
 * fits the depth every GL 4.5 allows, narrower gaps where it would not (512^3), and levels only down to tiles
 * whose gap is still one texel, so no trilinear lookup reaches a neighbouring tile.
 */
class DirectionalStackLayoutTest : public QObject {
    Q_OBJECT

private slots:
    void halfTileGapsWhereTheyFit();
    void narrowerGapsWhereHalfWouldNotFit();
    void everyLevelKeepsAGapOfOneTexel();
};

void DirectionalStackLayoutTest::halfTileGapsWhereTheyFit()
{
    const DirectionalStackLayout layout = DirectionalStackLayout::of(128);
    QCOMPARE(layout.size, 64);
    QCOMPARE(layout.gapShift, 1);
    QCOMPARE(layout.depth(), 6 * 64 + 5 * 32);
    QCOMPARE(layout.levels, 6); // tiles 64, 32, 16, 8, 4 and 2 wide
    QCOMPARE(layout.stride(0), 96);
    QCOMPARE(layout.stride(5), 3);
    // rgba16f over every level: 8.5 tiles' worth of each level's texels.
    std::uint64_t expected = 0;
    for (std::uint64_t side = 64; side >= 2; side /= 2)
        expected += side * side * (17 * side / 2) * 8;
    QCOMPARE(layout.bytes(8), expected);
    QCOMPARE(DirectionalStackLayout::of(256).gapShift, 1); // 1088 deep
}

void DirectionalStackLayoutTest::narrowerGapsWhereHalfWouldNotFit()
{
    // Half-tile gaps would make the 512^3 stack 2176 deep, over the 2048 GL guarantees.
    const DirectionalStackLayout layout = DirectionalStackLayout::of(512);
    QCOMPARE(layout.gapShift, 2);
    QVERIFY(layout.depth() <= DirectionalStackLayout::kMaxDepth);
    QCOMPARE(layout.depth(), 6 * 256 + 5 * 64);
    QCOMPARE(layout.levels, 7); // tiles 256 down to 4 wide
}

void DirectionalStackLayoutTest::everyLevelKeepsAGapOfOneTexel()
{
    for (const int resolution : { 4, 8, 16, 32, 64, 128, 256, 512 }) {
        const DirectionalStackLayout layout = DirectionalStackLayout::of(resolution);
        QVERIFY2(layout.levels >= 1, qPrintable(QString::number(resolution)));
        for (int level = 0; level < layout.levels; ++level) {
            const int side = layout.size >> level;
            QVERIFY2((side >> layout.gapShift) >= 1,
                qPrintable(QString("%1^3, level %2: no gap").arg(resolution).arg(level)));
            QCOMPARE(layout.stride(level), side + (side >> layout.gapShift));
            // The levels halve the whole stack exactly, so tiles line up at every level.
            QCOMPARE(layout.depth() >> level, 6 * side + 5 * (side >> layout.gapShift));
        }
    }
    QCOMPARE(DirectionalStackLayout::of(2).levels, 0); // a grid of one level above its voxels has no chains
}

QTEST_GUILESS_MAIN(DirectionalStackLayoutTest)
#include "tst_DirectionalStackLayout.moc"
