#include "core/ClipmapLayout.h"

#include <QtTest>

#include <cmath>
#include <limits>

using vct::render::ClipmapLayout;
using vct::render::VoxelGridFrame;

namespace {

VoxelGridFrame sceneGrid()
{
    VoxelGridFrame scene;
    scene.origin = glm::vec3(-20.0f, -3.0f, 5.0f);
    scene.extent = 40.0f;
    scene.resolution = 64;
    return scene;
}

/** Whole steps of @p step (within float error) from @p from to @p to. */
bool onSteps(float from, float to, float step)
{
    const float steps = (to - from) / step;
    return std::abs(steps - std::round(steps)) < 1e-3f;
}

} // namespace

/**
 * Where a clipmap's levels sit (core/ClipmapLayout): the coarsest is the grid around the scene, each finer
 * one half as wide around the camera, on its own grid of two-voxel steps, so it moves only when the camera
 * has moved a step and always lines up with the level around it.
 */
class ClipmapLayoutTest : public QObject {
    Q_OBJECT

private slots:
    void coarsestIsTheSceneGrid();
    void finerLevelsHalveAroundTheCamera();
    void levelsMoveInStepsOfTwoVoxels();
    void levelsStayInsideTheScene();
};

void ClipmapLayoutTest::coarsestIsTheSceneGrid()
{
    const VoxelGridFrame scene = sceneGrid();
    QVERIFY(ClipmapLayout::level(scene, 3, 2, glm::vec3(0.0f)) == scene);
    // A dense grid is a clipmap of one level.
    QVERIFY(ClipmapLayout::level(scene, 1, 0, glm::vec3(7.0f)) == scene);
}

void ClipmapLayoutTest::finerLevelsHalveAroundTheCamera()
{
    const VoxelGridFrame scene = sceneGrid();
    const glm::vec3 camera(1.3f, 14.2f, 26.9f);
    for (int level = 0; level < 3; ++level) {
        const VoxelGridFrame frame = ClipmapLayout::level(scene, 4, level, camera);
        QCOMPARE(frame.resolution, scene.resolution);
        QCOMPARE(frame.extent, scene.extent / float(1 << (3 - level)));
        const float step = 2.0f * frame.voxelSize();
        for (int axis = 0; axis < 3; ++axis) {
            const float centre = frame.origin[axis] + 0.5f * frame.extent;
            QVERIFY2(std::abs(centre - camera[axis]) <= 0.5f * step + 1e-4f,
                qPrintable(QString("level %1 axis %2: centre %3, camera %4")
                               .arg(level)
                               .arg(axis)
                               .arg(centre)
                               .arg(camera[axis])));
            // Its corner lies on the grid of its own two-voxel steps, and so on the coarser level's voxels.
            QVERIFY(onSteps(scene.origin[axis], frame.origin[axis], step));
        }
    }
}

void ClipmapLayoutTest::levelsMoveInStepsOfTwoVoxels()
{
    const VoxelGridFrame scene = sceneGrid();
    const glm::vec3 camera(0.0f, 17.0f, 25.0f);
    const VoxelGridFrame before = ClipmapLayout::level(scene, 3, 0, camera);
    const float step = 2.0f * before.voxelSize();
    // A camera move well under a step leaves the level where it is, when the camera is mid-step.
    const glm::vec3 midStep = before.origin + glm::vec3(0.5f * before.extent);
    QVERIFY(ClipmapLayout::level(scene, 3, 0, midStep + glm::vec3(0.3f * step))
        == ClipmapLayout::level(scene, 3, 0, midStep));
    // A move of three steps along x moves it three steps along x, and nothing else.
    const VoxelGridFrame after
        = ClipmapLayout::level(scene, 3, 0, midStep + glm::vec3(3.0f * step, 0.0f, 0.0f));
    const VoxelGridFrame mid = ClipmapLayout::level(scene, 3, 0, midStep);
    QVERIFY(std::abs(after.origin.x - mid.origin.x - 3.0f * step) < 1e-4f);
    QCOMPARE(after.origin.y, mid.origin.y);
    QCOMPARE(after.origin.z, mid.origin.z);
}

void ClipmapLayoutTest::levelsStayInsideTheScene()
{
    const VoxelGridFrame scene = sceneGrid();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (const glm::vec3 camera : { glm::vec3(-1000.0f), glm::vec3(1000.0f), glm::vec3(-20.0f, -3.0f, 5.0f),
             glm::vec3(nan, 0.0f, std::numeric_limits<float>::infinity()) })
        for (int level = 0; level < 2; ++level) {
            const VoxelGridFrame frame = ClipmapLayout::level(scene, 3, level, camera);
            for (int axis = 0; axis < 3; ++axis) {
                QVERIFY(std::isfinite(frame.origin[axis]));
                QVERIFY(frame.origin[axis] >= scene.origin[axis] - 1e-4f);
                QVERIFY(frame.origin[axis] + frame.extent <= scene.origin[axis] + scene.extent + 1e-4f);
            }
        }
}

QTEST_GUILESS_MAIN(ClipmapLayoutTest)
#include "tst_ClipmapLayout.moc"
