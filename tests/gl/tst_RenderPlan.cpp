#include "GlTestContext.h"
#include "TestSupport.h"

#include "document/Document.h"
#include "document/SceneLoader.h"
#include "imageio/ImageMetrics.h"
#include "sync/SceneSync.h"

#include <glm/gtc/matrix_transform.hpp>

#include <map>
#include <string>

#include <QtTest>

using namespace vct;

/**
 * Invalidation is exact: after every kind of edit, the frame rendered with the plan (reusing and skipping
 * passes) equals the frame rendered with every pass forced to run. Float atomics add voxel fragments in a
 * varying order, so images may differ in the last bits: the bound is 1e-4 relative.
 */
class RenderPlanTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cameraOnlyReusesEverythingButPerPixelWork();
    void movedLightKeepsVoxels();
    void brighterLightKeepsShadowMaps();
    void movedRectLightKeepsVoxelsAndShadowMaps();
    void movedDynamicObjectRedoesOnlyItsLayer();
    void editedMaterialRedoesOnlyLayersUsingIt();
    void glossyMaterialAddsSpecularCones();
    void voxelSettingsRebuildEverything();
    void settingsInvalidateOnlyWhatReadsThem();
    void ambientOcclusionOnlyWhenShown();
    void noLightSourcesMeansNoIndirectLight();
    void secondBounceFollowsTheFirst();
    void bouncesConvergeAcrossFrames();
    void draggedObjectKeepsTheConvergedLight();
    void everyBounceGoesOnFromTwoBounces();
    void newSolveRunsOneIterationInItsFirstFrame();
    void irradianceCacheFollowsTheLight();
    void timesCanComeFromThePreviousFrame();
    void renamesChangeNothingTheRendererHas();
    void stagedRebuildSplitsOnlyFullRebuilds();
    void bounceSolveTimesItsPhases();

private:
    render::FrameStats planned();
    /** The room at 32^3 in an interactive view that runs one bounce iteration a frame. */
    void startInteractiveBounces();
    /** A frame that runs every pass and every bounce iteration at once. */
    render::RadianceImage renderedFromScratch();
    void expectSameAsForced(const char* what);
    const render::PassStats& pass(const std::string& name) const;
    void expectAction(const std::string& pass, const std::string& action);

    test::GlTestContext m_gl;
    render::Scene m_scene;
    render::Camera m_camera;
    render::FrameStats m_last;
    render::RadianceImage m_plannedImage;
    int m_dynamicMesh = -1;
    int m_staticOnlyMaterial = -1;
};

void RenderPlanTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
    QString error;
    QVERIFY2(
        doc::SceneLoader::load(QStringLiteral("builtin:cornell_point"), m_scene, &error), qPrintable(error));
    // The short box moves (dynamic) and gets its own material so material edits can target one layer.
    for (std::size_t i = 0; i < m_scene.meshes.size(); ++i)
        if (m_scene.meshes[i].name.rfind("shortbox", 0) == 0) {
            m_dynamicMesh = int(i);
            m_scene.meshes[i].dynamic = true;
            render::Material own = m_scene.materials[std::size_t(m_scene.meshes[i].material)];
            own.name = "shortbox";
            m_scene.materials.push_back(own);
            m_scene.meshes[i].material = int(m_scene.materials.size()) - 1;
        }
    QVERIFY(m_dynamicMesh >= 0);
    for (std::size_t m = 0; m < m_scene.materials.size(); ++m)
        if (m_scene.materials[m].name == "red")
            m_staticOnlyMaterial = int(m);
    QVERIFY(m_staticOnlyMaterial >= 0);
    render::RenderSettings settings;
    settings.voxelResolution = 32;
    settings.shadowMapSize = 256;
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(m_scene);
    m_camera = m_scene.camera;
    planned();
    expectSameAsForced("first frame");
}

render::FrameStats RenderPlanTest::planned()
{
    m_last = m_gl.renderer->renderFrame(m_camera, 40, 40);
    m_plannedImage = m_gl.renderer->readFrame();
    return m_last;
}

void RenderPlanTest::startInteractiveBounces()
{
    render::RenderSettings settings;
    settings.voxelResolution = 32;
    settings.shadowMapSize = 256;
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(m_scene);
    m_gl.renderer->setBounceIterationsPerFrame(1);
}

render::RadianceImage RenderPlanTest::renderedFromScratch()
{
    m_gl.renderer->setBounceIterationsPerFrame(0);
    m_gl.renderer->invalidate();
    m_gl.renderer->renderFrame(m_camera, 40, 40);
    return m_gl.renderer->readFrame();
}

void RenderPlanTest::expectSameAsForced(const char* what)
{
    m_gl.renderer->invalidate();
    const render::FrameStats forced = m_gl.renderer->renderFrame(m_camera, 40, 40);
    for (const render::PassStats& p : forced.passes)
        QVERIFY2(p.action != "reused",
            qPrintable(QString("%1: forced frame reused %2").arg(what, p.name.c_str())));
    const render::RadianceImage reference = m_gl.renderer->readFrame();
    double worst = 0.0;
    for (std::size_t i = 0; i < reference.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double a = m_plannedImage.pixels[i][c], b = reference.pixels[i][c];
            worst = std::max(worst, std::abs(a - b) / (1.0 + std::abs(b)));
        }
    QVERIFY2(worst <= 1e-4,
        qPrintable(QString("%1: planned frame differs from forced by %2").arg(what).arg(worst)));
    QVERIFY(m_gl.renderer->takeGlErrors().empty());
}

const render::PassStats& RenderPlanTest::pass(const std::string& name) const
{
    for (const render::PassStats& p : m_last.passes)
        if (p.name == name)
            return p;
    qFatal("no pass %s", name.c_str());
}

void RenderPlanTest::expectAction(const std::string& name, const std::string& action)
{
    const render::PassStats& p = pass(name);
    QVERIFY2(p.action == action,
        qPrintable(QString("%1: %2 (%3), expected %4")
                       .arg(name.c_str(), p.action.c_str(), p.reason.c_str(), action.c_str())));
}

void RenderPlanTest::cameraOnlyReusesEverythingButPerPixelWork()
{
    m_camera.position = glm::vec3(
        glm::rotate(glm::mat4(1.0f), 0.2f, glm::vec3(0, 1, 0)) * glm::vec4(m_camera.position, 1.0f));
    planned();
    for (const char* name : { "shadow maps", "enclosed space", "voxelize", "inject light", "mipmaps" })
        expectAction(name, "reused");
    for (const char* name : { "g-buffer", "cone trace", "composite" })
        expectAction(name, "run");
    expectSameAsForced("camera orbit");
}

void RenderPlanTest::movedLightKeepsVoxels()
{
    m_scene.pointLights[0].position += glm::vec3(0.1f, -0.05f, 0.0f);
    m_gl.renderer->setLights(m_scene.pointLights, m_scene.directionalLights, m_scene.surfaceLights);
    planned();
    expectAction("shadow maps", "run");
    expectAction("voxelize", "reused");
    expectAction("inject light", "run");
    expectAction("mipmaps", "run");
    expectSameAsForced("moved light");
}

void RenderPlanTest::brighterLightKeepsShadowMaps()
{
    m_scene.pointLights[0].intensity *= 1.5f;
    m_gl.renderer->setLights(m_scene.pointLights, m_scene.directionalLights, m_scene.surfaceLights);
    planned();
    expectAction("shadow maps", "reused");
    expectAction("voxelize", "reused");
    expectAction("inject light", "run");
    expectSameAsForced("brighter light");
}

// A rectangle light is no geometry and has no shadow map: adding and moving one re-injects and re-traces its
// shadows, and keeps the voxels and the point light's shadow maps.
void RenderPlanTest::movedRectLightKeepsVoxelsAndShadowMaps()
{
    render::SurfaceLight rect;
    rect.centre = m_scene.pointLights[0].position + glm::vec3(0.0f, 0.1f, 0.0f);
    rect.width = 0.3f;
    rect.height = 0.2f;
    rect.radiance = glm::vec3(4.0f);
    m_scene.surfaceLights = { rect };
    for (const char* what : { "added rect light", "moved rect light" }) {
        m_gl.renderer->setLights(m_scene.pointLights, m_scene.directionalLights, m_scene.surfaceLights);
        planned();
        expectAction("shadow maps", "reused");
        expectAction("voxelize", "reused");
        expectAction("inject light", "run");
        expectAction("area-light shadows", "run");
        expectSameAsForced(what);
        m_scene.surfaceLights[0].centre.x += 0.1f;
    }
    m_scene.surfaceLights.clear();
    m_gl.renderer->setLights(m_scene.pointLights, m_scene.directionalLights, m_scene.surfaceLights);
    planned();
    expectAction("area-light shadows", "skipped");
}

// Twice: the first move after a forced frame draws the static casters' own shadow maps again, the second only
// copies the ones the first drew (passes/ShadowMapPass), and what it shows must still match a forced frame.
void RenderPlanTest::movedDynamicObjectRedoesOnlyItsLayer()
{
    for (const glm::vec3 offset : { glm::vec3(-0.1f, 0.0f, 0.05f), glm::vec3(-0.2f, 0.0f, 0.1f) }) {
        m_gl.renderer->setMeshTransform(std::size_t(m_dynamicMesh), glm::translate(glm::mat4(1.0f), offset));
        planned();
        expectAction("voxelize", "run");
        QVERIFY(pass("voxelize").reason.find("dynamic") != std::string::npos);
        expectAction("shadow maps", "run"); // its shadow moved too
    }
    expectSameAsForced("moved dynamic object");
}

void RenderPlanTest::editedMaterialRedoesOnlyLayersUsingIt()
{
    render::Material red = m_scene.materials[std::size_t(m_staticOnlyMaterial)];
    red.albedo *= 0.5f;
    m_gl.renderer->setMaterial(std::size_t(m_staticOnlyMaterial), red);
    planned();
    expectAction("voxelize", "run");
    expectAction("shadow maps", "reused"); // a material does not move geometry
    QVERIFY(pass("voxelize").reason.find("objects that use it") != std::string::npos);
    QVERIFY(pass("inject light").reason.find("re-injecting only") != std::string::npos);
    expectSameAsForced("static material edit");

    render::Material box
        = m_scene.materials[std::size_t(m_scene.meshes[std::size_t(m_dynamicMesh)].material)];
    box.albedo = glm::vec3(0.2f, 0.6f, 0.2f);
    m_gl.renderer->setMaterial(std::size_t(m_scene.meshes[std::size_t(m_dynamicMesh)].material), box);
    planned();
    expectAction("voxelize", "run");
    QVERIFY(pass("voxelize").reason.find("dynamic") != std::string::npos);
    expectSameAsForced("dynamic-only material edit");
}

void RenderPlanTest::glossyMaterialAddsSpecularCones()
{
    QVERIFY(pass("cone trace").reason.find("no specular cones") != std::string::npos);
    render::Material white;
    for (std::size_t m = 0; m < m_scene.materials.size(); ++m)
        if (m_scene.materials[m].name == "white") {
            white = m_scene.materials[m];
            white.specular = glm::vec3(0.2f);
            white.albedo *= 0.75f;
            white.shininess = 60.0f;
            m_gl.renderer->setMaterial(m, white);
        }
    planned();
    QVERIFY(pass("cone trace").reason.find("specular cones") != std::string::npos);
    QVERIFY(pass("cone trace").reason.find("no specular") == std::string::npos);
    expectSameAsForced("glossy material");
    // Voxels hold no specular: making the material matte again touches per-pixel work only.
    for (std::size_t m = 0; m < m_scene.materials.size(); ++m)
        if (m_scene.materials[m].name == "white") {
            render::Material matte = m_gl.renderer->scene().materials[m];
            matte.specular = glm::vec3(0.0f);
            matte.shininess = 0.0f;
            m_gl.renderer->setMaterial(m, matte);
        }
    planned();
    for (const char* name : { "shadow maps", "voxelize", "inject light", "mipmaps" })
        expectAction(name, "reused");
    QVERIFY(pass("cone trace").reason.find("no specular cones") != std::string::npos);
    expectSameAsForced("glossy material made matte");
}

void RenderPlanTest::voxelSettingsRebuildEverything()
{
    render::RenderSettings settings = m_gl.renderer->settings();
    settings.voxelResolution = 16;
    m_gl.renderer->setSettings(settings);
    planned();
    for (const char* name : { "shadow maps", "enclosed space", "voxelize", "inject light", "mipmaps" })
        expectAction(name, "run");
    expectSameAsForced("grid resolution");
}

// No table of settings decides what to redo: each pass keys on the settings it reads.
void RenderPlanTest::settingsInvalidateOnlyWhatReadsThem()
{
    const render::RenderSettings original = m_gl.renderer->settings();
    render::RenderSettings settings = original;
    settings.conservativeVoxelization = !original.conservativeVoxelization;
    m_gl.renderer->setSettings(settings);
    planned();
    expectAction("shadow maps", "reused");
    expectAction("voxelize", "run");
    expectSameAsForced("voxelization mode");
    m_gl.renderer->setSettings(original);
    planned();

    settings = original;
    settings.shadowMapSize = original.shadowMapSize * 2;
    m_gl.renderer->setSettings(settings);
    planned();
    expectAction("shadow maps", "run");
    expectAction("voxelize", "reused");
    expectAction("inject light", "run");
    QVERIFY2(
        pass("inject light").reason.find("only") == std::string::npos, pass("inject light").reason.c_str());
    expectSameAsForced("shadow map size");
    m_gl.renderer->setSettings(original);
    planned();

    settings = original;
    settings.direct = !original.direct;
    m_gl.renderer->setSettings(settings);
    planned();
    expectAction("shadow maps", "reused");
    expectAction("voxelize", "reused");
    expectAction("inject light", "run");
    expectSameAsForced("direct light off");
    m_gl.renderer->setSettings(original);
    planned();

    // The enclosed-space map reads the static meshes and the grid only; off, nothing keeps it, and on again
    // it is built anew (its texture was freed).
    settings = original;
    settings.enclosedSpace = false;
    m_gl.renderer->setSettings(settings);
    planned();
    expectAction("enclosed space", "skipped");
    expectAction("voxelize", "reused");
    expectSameAsForced("enclosed space off");
    m_gl.renderer->setSettings(original);
    planned();
    expectAction("enclosed space", "run");
    expectAction("voxelize", "reused");
    expectSameAsForced("enclosed space on again");

    // The bounce solve's step is its own: the solve runs again over the same voxels and light, and the pixels
    // see light gathered with other steps (the image changes: the setting reaches the solve's gathers).
    const render::RadianceImage before = m_plannedImage;
    settings = original;
    settings.bounceStepScale = 0.5f * original.bounceStepScale;
    m_gl.renderer->setSettings(settings);
    planned();
    expectAction("voxelize", "reused");
    expectAction("inject light", "reused");
    expectAction("bounces", "run");
    double moved = 0.0;
    for (std::size_t i = 0; i < before.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            moved = std::max(moved, double(std::abs(m_plannedImage.pixels[i][c] - before.pixels[i][c])));
    QVERIFY2(moved > 1e-4, qPrintable(QString("bounce step: the image moved by only %1").arg(moved)));
    expectSameAsForced("bounce step");
    m_gl.renderer->setSettings(original);
    planned();

    // Nothing gathers diffuse light: the map is not built.
    settings = original;
    settings.indirectDiffuse = false;
    settings.bounces = 1;
    m_gl.renderer->setSettings(settings);
    planned();
    expectAction("enclosed space", "skipped");
    expectSameAsForced("no diffuse gather");

    m_gl.renderer->setSettings(original);
    planned();
}

void RenderPlanTest::ambientOcclusionOnlyWhenShown()
{
    QVERIFY(pass("cone trace").reason.find("no AO") != std::string::npos);
    render::RenderSettings settings = m_gl.renderer->settings();
    settings.view = render::DebugView::AmbientOcclusion;
    m_gl.renderer->setSettings(settings);
    planned();
    QVERIFY(pass("cone trace").reason.find("no AO") == std::string::npos);
    expectSameAsForced("AO view");
    settings.view = render::DebugView::Final;
    m_gl.renderer->setSettings(settings);
}

void RenderPlanTest::noLightSourcesMeansNoIndirectLight()
{
    m_gl.renderer->setLights({}, {}, {});
    planned();
    expectAction("cone trace", "skipped");
    QVERIFY(pass("cone trace").reason.find("no lights and no emission") != std::string::npos);
    for (const glm::vec3& p : m_plannedImage.pixels)
        QCOMPARE(p, glm::vec3(0.0f)); // nothing emits, nothing can be seen
    expectSameAsForced("no light sources");
}

// bounces = 2 adds a per-voxel gather: it runs when the first-bounce radiance changes, is reused for camera
// moves, and is skipped (its volume released, cones back on the first bounce) when set back to 1.
void RenderPlanTest::secondBounceFollowsTheFirst()
{
    render::RenderSettings settings;
    settings.voxelResolution = 32;
    settings.shadowMapSize = 256;
    settings.bounces = 1;
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(m_scene);
    planned();
    expectAction("bounces", "skipped");
    const std::size_t oneBounceBytes = m_gl.renderer->voxelBytes();

    for (const int bounces : { 2, render::RenderSettings::kConvergedBounces }) {
        settings.bounces = bounces;
        m_gl.renderer->setSettings(settings);
        planned();
        expectAction("bounces", "run");
        expectAction("inject light", "reused");
        QVERIFY(m_gl.renderer->voxelBytes() > oneBounceBytes);
        QVERIFY(m_last.lightConverged);
        QCOMPARE(m_last.bounceIterations > 1, bounces == render::RenderSettings::kConvergedBounces);
        expectSameAsForced("bounces on");

        m_camera.position += glm::vec3(0.05f, 0.0f, 0.0f);
        planned();
        expectAction("bounces", "reused");
        expectSameAsForced("camera move with bounces");

        m_scene.pointLights[0].position += glm::vec3(0.0f, -0.05f, 0.0f);
        m_gl.renderer->setLights(m_scene.pointLights, m_scene.directionalLights, m_scene.surfaceLights);
        planned();
        expectAction("inject light", "run");
        expectAction("bounces", "run");
        expectSameAsForced("moved light with bounces");
    }

    settings.bounces = 1;
    m_gl.renderer->setSettings(settings);
    planned();
    expectAction("bounces", "skipped");
    QCOMPARE(m_gl.renderer->voxelBytes(), oneBounceBytes);
    expectSameAsForced("bounces off");
}

// An interactive view spreads the iteration over frames: each frame runs one iteration and says it has not
// converged, until it has; then the pass is reused. A light edit starts from the last solution, so the first
// frame after it is already close to the converged image, and the end result matches a frame that ran every
// iteration from scratch within the convergence tolerance.
void RenderPlanTest::bouncesConvergeAcrossFrames()
{
    startInteractiveBounces();
    int frames = 0;
    for (planned(); !m_last.lightConverged && frames < 100; planned()) {
        expectAction("bounces", "run");
        QCOMPARE(m_last.bounceIterations, frames + 1);
        ++frames;
    }
    // One iteration a frame: at least one frame shows the light still converging (from the second iteration
    // on the solve may end by extrapolating its geometric tail).
    QVERIFY2(m_last.lightConverged && frames >= 1, qPrintable(QString("%1 frames").arg(frames)));
    planned();
    expectAction("bounces", "reused");

    m_scene.pointLights[0].intensity *= 1.2f;
    m_gl.renderer->setLights(m_scene.pointLights, m_scene.directionalLights, m_scene.surfaceLights);
    planned();
    expectAction("bounces", "run");
    const render::RadianceImage firstAfterEdit = m_plannedImage;
    while (!m_last.lightConverged)
        planned();
    const render::RadianceImage converged = m_plannedImage;
    const render::RadianceImage fromScratch = renderedFromScratch();
    const double againstScratch = io::ImageMetrics::relativeMse(converged, fromScratch);
    const double firstFrame = io::ImageMetrics::relativeMse(firstAfterEdit, fromScratch);
    qInfo("converged over %d frames; after a 20%% light edit: first frame %.2e, converged %.2e relative MSE "
          "from "
          "a frame that iterated from scratch",
        frames, firstFrame, againstScratch);
    QVERIFY2(againstScratch < 1e-3, qPrintable(QString::number(againstScratch)));
    QVERIFY2(firstFrame < 0.02, qPrintable(QString::number(firstFrame)));
}

// While an object is dragged in the interactive view, each frame redoes its voxels; the bounce solve carries
// on from the last one instead of starting over from the first bounce, so the frame right after a move is
// already close to the converged image (starting over, it showed one iteration's light: darker), and the
// solve still ends where one from scratch does.
void RenderPlanTest::draggedObjectKeepsTheConvergedLight()
{
    startInteractiveBounces();
    for (int frames = 0; frames < 100 && !planned().lightConverged; ++frames) { }
    QVERIFY(m_last.lightConverged);
    m_gl.renderer->setMeshTransform(
        std::size_t(m_dynamicMesh), glm::translate(glm::mat4(1.0f), glm::vec3(-0.15f, 0.0f, 0.1f)));
    planned();
    expectAction("bounces", "run");
    QCOMPARE(m_last.bounceIterations, 1);
    const render::RadianceImage firstAfterMove = m_plannedImage;
    for (int frames = 0; frames < 100 && !planned().lightConverged; ++frames) { }
    QVERIFY(m_last.lightConverged);
    const render::RadianceImage converged = m_plannedImage;
    const render::RadianceImage fromScratch = renderedFromScratch();
    const double firstFrame = io::ImageMetrics::relativeMse(firstAfterMove, fromScratch);
    const double againstScratch = io::ImageMetrics::relativeMse(converged, fromScratch);
    qInfo(
        "dragged object, one iteration a frame: first frame after the move %.2e, converged %.2e relative MSE "
        "from a frame that iterated from scratch; means %.4f / %.4f",
        firstFrame, againstScratch, double(io::ImageMetrics::meanRadiance(firstAfterMove).r),
        double(io::ImageMetrics::meanRadiance(fromScratch).r));
    // 1.6e-3 with every bounce on the bounce cells; 2.7e-3 with the higher bounces on cells of 8^3 voxels,
    // four to this grid's side, in which the object's move shifts where a cell gathers from.
    QVERIFY2(firstFrame < 4e-3, qPrintable(QString::number(firstFrame)));
    QVERIFY2(againstScratch < 1e-3, qPrintable(QString::number(againstScratch)));
    m_gl.renderer->setMeshTransform(std::size_t(m_dynamicMesh), glm::mat4(1.0f));
}

// The interactive view switched from two bounces to every bounce goes on from the two-bounce light with a
// solve that gathers the later bounces on coarser cells (VoxelBouncePass), whose textures are new then: there
// is no earlier first-bounce gather to take the two-bounce iterate's against. Taken against what the new
// textures' memory held, its first frame counted the first bounce twice (mean 0.764 against a converged
// 0.714); against the new first-bounce light's gather it lies between the two-bounce image and the converged
// one (0.618, 0.664, 0.714).
void RenderPlanTest::everyBounceGoesOnFromTwoBounces()
{
    startInteractiveBounces();
    render::RenderSettings settings = m_gl.renderer->settings();
    settings.bounces = 2;
    m_gl.renderer->setSettings(settings);
    for (int frames = 0; frames < 10 && !planned().lightConverged; ++frames) { }
    QVERIFY(m_last.lightConverged);
    const double twoBounces = double(io::ImageMetrics::meanRadiance(m_plannedImage).r);
    settings.bounces = render::RenderSettings::kConvergedBounces;
    m_gl.renderer->setSettings(settings);
    planned();
    expectAction("bounces", "run");
    const double firstFrame = double(io::ImageMetrics::meanRadiance(m_plannedImage).r);
    for (int frames = 0; frames < 100 && !planned().lightConverged; ++frames) { }
    QVERIFY(m_last.lightConverged);
    const double converged = double(io::ImageMetrics::meanRadiance(m_plannedImage).r);
    qInfo("mean red: two bounces %.4f, the first frame of every bounce %.4f, converged %.4f", twoBounces,
        firstFrame, converged);
    m_gl.renderer->setBounceIterationsPerFrame(0);
    QVERIFY2(converged > twoBounces, "every bounce is brighter than two");
    QVERIFY2(
        firstFrame >= twoBounces && firstFrame <= converged * 1.001, qPrintable(QString::number(firstFrame)));
}

// At two iterations a frame, as the editor runs: a frame that starts a solve runs its first iteration only
// (it gathers the new first-bounce light on both sizes of cells, about three later iterations' work: a
// dragged light's frames 350 -> 319 ms on the atrium, docs/BENCHMARKS.md), the frames that go on with it two
// each.
void RenderPlanTest::newSolveRunsOneIterationInItsFirstFrame()
{
    startInteractiveBounces();
    m_gl.renderer->setBounceIterationsPerFrame(2);
    for (int frames = 0; frames < 100 && !planned().lightConverged; ++frames) { }
    QVERIFY(m_last.lightConverged);
    const glm::vec3 intensity = m_scene.pointLights[0].intensity;
    m_scene.pointLights[0].intensity = 1.2f * intensity;
    m_gl.renderer->setLights(m_scene.pointLights, m_scene.directionalLights, m_scene.surfaceLights);
    planned();
    const int first = m_last.bounceIterations;
    planned();
    const int second = m_last.bounceIterations;
    m_scene.pointLights[0].intensity = intensity;
    m_gl.renderer->setLights(m_scene.pointLights, m_scene.directionalLights, m_scene.surfaceLights);
    m_gl.renderer->setBounceIterationsPerFrame(0);
    QCOMPARE(first, 1);
    QCOMPARE(second, 3);
}

// The irradiance cache gathers each cell in view once per voxel light: a camera move gathers only what came
// into view, a moved light redoes it, and switching it off releases its memory. Its image stays close to
// per-pixel cones: the cells interpolate what a pixel's own cones would gather from nearly the same place.
void RenderPlanTest::irradianceCacheFollowsTheLight()
{
    render::RenderSettings settings;
    settings.voxelResolution = 32;
    settings.shadowMapSize = 256;
    settings.indirectDivisor = 1;
    settings.irradianceCache = false;
    m_gl.renderer->setSettings(settings);
    m_gl.renderer->setScene(m_scene);
    planned();
    expectAction("irradiance cache", "skipped");
    const std::size_t uncachedBytes = m_gl.renderer->voxelBytes();
    const render::RadianceImage perPixel = m_plannedImage;

    for (const int cell : { 1, 2 }) {
        settings.irradianceCache = true;
        settings.irradianceCellSize = cell;
        m_gl.renderer->setSettings(settings);
        planned();
        expectAction("irradiance cache", "run");
        expectAction("inject light", "reused");
        QCOMPARE(std::uint64_t(m_gl.renderer->voxelBytes()),
            settings.voxelMemoryBytes({ .emission = false, .areaLights = false }));
        const double difference = io::ImageMetrics::relativeMse(m_plannedImage, perPixel);
        qInfo("irradiance cache, %d^3-voxel cells: relative MSE %.2e against per-pixel cones", cell,
            difference);
        // Measured 2e-3 to 2e-2 on the atrium and the Cornell box (docs/BENCHMARKS.md); a lookup that picked
        // the wrong cells (a wall's far side, another face) would show as large errors at the edges.
        QVERIFY2(difference < 0.05, qPrintable(QString::number(difference)));
        bool sawCache = false;
        for (const render::NonFiniteCount& c : m_gl.renderer->countNonFinite()) {
            QVERIFY2(c.count == 0, c.resource.c_str());
            sawCache = sawCache || c.resource == "voxel irradiance cache, level 0";
        }
        QVERIFY(sawCache);
        expectSameAsForced("irradiance cache on");
    }

    // Cells are gathered as traced pixels need them: a camera move gathers only the cells that came into
    // view, yet the image is the one a fresh gather gives; an unchanged view reuses everything.
    m_camera.position += glm::vec3(0.05f, 0.0f, 0.0f);
    planned();
    expectAction("irradiance cache", "run");
    QVERIFY2(pass("irradiance cache").reason.find("came into view") != std::string::npos,
        pass("irradiance cache").reason.c_str());
    expectSameAsForced("camera move with the irradiance cache");
    planned();
    planned();
    expectAction("irradiance cache", "reused");
    for (const float turn : { 0.3f, -0.6f }) {
        m_camera.position = glm::vec3(
            glm::rotate(glm::mat4(1.0f), turn, glm::vec3(0, 1, 0)) * glm::vec4(m_camera.position, 1.0f));
        planned();
        expectAction("irradiance cache", "run");
    }
    expectSameAsForced("camera turned both ways with the irradiance cache");

    m_scene.pointLights[0].position += glm::vec3(0.0f, -0.05f, 0.0f);
    m_gl.renderer->setLights(m_scene.pointLights, m_scene.directionalLights, m_scene.surfaceLights);
    planned();
    expectAction("inject light", "run");
    expectAction("irradiance cache", "run");
    expectSameAsForced("moved light with the irradiance cache");

    settings.irradianceCache = false;
    m_gl.renderer->setSettings(settings);
    planned();
    expectAction("irradiance cache", "skipped");
    QCOMPARE(m_gl.renderer->voxelBytes(), uncachedBytes);
}

// The editor reads the GPU times of the frame before, so it never waits for the frame it just issued: each
// frame then reports the times of exactly the passes that ran in the one before.
void RenderPlanTest::timesCanComeFromThePreviousFrame()
{
    m_gl.renderer->setTimesFromPreviousFrame(true);
    m_gl.renderer->invalidate();
    const render::FrameStats first = m_gl.renderer->renderFrame(m_camera, 40, 40);
    QVERIFY(first.timesFromPreviousFrame);
    QCOMPARE(first.totalGpuMs, 0.0); // nothing came before since the readback changed
    m_camera.position += glm::vec3(0.02f, 0.0f, 0.0f);
    const render::FrameStats second = m_gl.renderer->renderFrame(m_camera, 40, 40);
    QVERIFY(second.totalGpuMs > 0.0);
    for (std::size_t i = 0; i < first.passes.size(); ++i) {
        const bool ranBefore = first.passes[i].action == "run";
        QVERIFY2((second.passes[i].gpuMs > 0.0) == ranBefore, first.passes[i].name.c_str());
    }
    // The shadow maps ran in the first frame only: the second reuses them but reports their time.
    QCOMPARE(second.passes.front().action, std::string("reused"));
    QVERIFY(second.passes.front().gpuMs > 0.0);
    m_gl.renderer->setTimesFromPreviousFrame(false);
    const render::FrameStats exact = m_gl.renderer->renderFrame(m_camera, 40, 40);
    QVERIFY(!exact.timesFromPreviousFrame);
    for (const render::PassStats& p : exact.passes)
        QVERIFY2((p.gpuMs > 0.0) == (p.action == "run"), p.name.c_str());
}

// Through the editor's path (document, change events, SceneSync): renaming a node or a light reruns no pass
// an unchanged frame would not. They used to re-upload and re-voxelize the scene, and re-inject and re-gather
// every light.
void RenderPlanTest::renamesChangeNothingTheRendererHas()
{
    doc::Document document;
    QString error;
    QVERIFY2(document.newFromScene(QStringLiteral("builtin:cornell_point"), &error), qPrintable(error));
    render::RenderSettings settings = document.state().settings;
    settings.voxelResolution = 32;
    settings.shadowMapSize = 256;
    document.setSettings(settings);
    QVERIFY(!document.state().nodes.empty() && !document.state().lights.empty());
    sync::SceneSync sceneSync(&document);
    sceneSync.apply(*m_gl.renderer, true);
    m_camera = document.state().camera;
    planned();
    sceneSync.apply(*m_gl.renderer);
    planned();
    std::vector<std::pair<std::string, std::string>> unchanged;
    for (const render::PassStats& p : m_last.passes)
        unchanged.emplace_back(p.name, p.action);
    QVERIFY2(pass("voxelize").action == "reused", "an unchanged frame reuses the voxels");

    const auto expectUnchanged = [&](const char* what) {
        QVERIFY(sceneSync.hasPendingChanges());
        sceneSync.apply(*m_gl.renderer);
        planned();
        for (const auto& [name, action] : unchanged)
            QVERIFY2(pass(name).action == action,
                qPrintable(QString("%1: %2 %3 (%4), as unchanged %5")
                               .arg(what, name.c_str(), pass(name).action.c_str(), pass(name).reason.c_str(),
                                   action.c_str())));
        expectSameAsForced(what);
    };
    document.setNodeName(0, QStringLiteral("renamed node"));
    expectUnchanged("node renamed");
    doc::LightNode light = document.state().lights.front();
    light.name = QStringLiteral("renamed light");
    document.setLight(0, light, doc::LightField::Name);
    expectUnchanged("light renamed");

    // Hiding a node redoes what its geometry reaches (shadow maps, voxels, light) but uploads nothing: the
    // renderer keeps the hidden mesh, flagged. Showing it again is the same. Each image is the one a scene
    // built without the node (or with it) gives from scratch.
    int hidden = -1;
    for (std::size_t i = 0; i < document.state().nodes.size(); ++i)
        if (document.state().nodes[i].name.startsWith(QStringLiteral("tallbox")))
            hidden = int(i);
    QVERIFY(hidden >= 0);
    for (const bool visible : { false, true }) {
        const char* what = visible ? "node shown again" : "node hidden";
        const std::uint64_t uploads = m_gl.renderer->sceneUploads();
        document.setNodeVisible(hidden, visible);
        QVERIFY(sceneSync.hasPendingChanges());
        sceneSync.apply(*m_gl.renderer);
        planned();
        QVERIFY2(m_gl.renderer->sceneUploads() == uploads, what);
        for (const char* name : { "shadow maps", "voxelize", "inject light" })
            QVERIFY2(pass(name).action == "run",
                qPrintable(QString("%1: %2 %3").arg(what, name, pass(name).action.c_str())));
        expectSameAsForced(what);
        // From scratch: a renderer given the scene the document now makes, hidden nodes left out.
        const render::RadianceImage kept = m_plannedImage;
        m_gl.renderer->setScene(document.buildRenderScene());
        m_gl.renderer->renderFrame(m_camera, 40, 40);
        const render::RadianceImage scratch = m_gl.renderer->readFrame();
        const double difference = io::ImageMetrics::relativeMse(kept, scratch);
        QVERIFY2(difference < 1e-6,
            qPrintable(QString("%1: relative MSE %2 from a new scene").arg(what).arg(difference)));
        sceneSync.apply(*m_gl.renderer, true);
        planned();
    }
    QVERIFY(document.state().nodes[std::size_t(hidden)].visible);

    // The dynamic flag is a property too, and does change the voxel layers.
    document.setNodeDynamic(0, !document.state().nodes.front().dynamic);
    sceneSync.apply(*m_gl.renderer);
    planned();
    expectAction("voxelize", "run");
    expectSameAsForced("dynamic flag");
}

// Issue 20: an interactive view splits a full rebuild over frames instead of blocking for all of it. Each
// frame stops before its second whole-grid step (voxelizing, injecting, starting the bounce solve over new
// voxels); the last one completes the image, which is the one a single complete frame gives. Edits that
// redo only part of the grid are not split, so moving a light or an object costs no extra frame.
void RenderPlanTest::stagedRebuildSplitsOnlyFullRebuilds()
{
    m_gl.renderer->setStagedRebuilds(true);
    m_gl.renderer->setScene(m_scene);
    planned();
    QVERIFY(m_last.deferred);
    expectAction("voxelize", "run");
    expectAction("inject light", "deferred");
    expectAction("composite", "deferred");
    planned();
    QVERIFY(m_last.deferred);
    expectAction("voxelize", "reused");
    expectAction("inject light", "run");
    expectAction("mipmaps", "deferred"); // once a rebuild is split, each whole-grid step has a frame
    expectAction("bounces", "deferred");
    planned();
    QVERIFY(m_last.deferred);
    expectAction("inject light", "reused");
    expectAction("bounces", "run");
    expectAction("g-buffer", "deferred"); // the screen passes get a frame of their own too
    planned();
    QVERIFY(!m_last.deferred);
    expectAction("bounces", "reused");
    expectAction("composite", "run");

    m_scene.pointLights[0].position += glm::vec3(-0.05f, 0.02f, 0.0f);
    m_gl.renderer->setLights(m_scene.pointLights, m_scene.directionalLights, m_scene.surfaceLights);
    planned();
    QVERIFY(!m_last.deferred);
    expectAction("inject light", "run");
    m_gl.renderer->setMeshTransform(
        std::size_t(m_dynamicMesh), glm::translate(glm::mat4(1.0f), glm::vec3(0.1f, 0.0f, -0.1f)));
    planned();
    QVERIFY(!m_last.deferred);
    expectAction("voxelize", "run");
    expectAction("composite", "run");
    m_gl.renderer->setStagedRebuilds(false);
    expectSameAsForced("after a staged rebuild");
}

// Asked for its phases, a solve from the first-bounce light says where its time went: after every pass's own
// line, one line per phase, with the runs of a solve of as many iterations (the bounce cells gather the
// first-bounce light once; the higher-bounce cells gather it and then each iterate; a reinjection per
// iteration; a filtering of the first-bounce light and of each iterate), their time a part of the pass's.
void RenderPlanTest::bounceSolveTimesItsPhases()
{
    startInteractiveBounces();
    m_gl.renderer->setBounceIterationsPerFrame(0);
    m_gl.renderer->setPhaseTimes(true);
    m_gl.renderer->invalidate();
    planned();
    m_gl.renderer->setPhaseTimes(false);
    const int iterations = m_last.bounceIterations;
    QVERIFY2(iterations >= 2, qPrintable(QString::number(iterations)));
    const std::string prefix = "bounces: ";
    std::map<std::string, int> runs;
    double phasesMs = 0.0;
    bool inPhases = false;
    for (const render::PassStats& p : m_last.passes) {
        if (p.name.rfind(prefix, 0) != 0) {
            QVERIFY2(!inPhases, qPrintable(QString::fromStdString(p.name + " follows the phases")));
            continue;
        }
        inPhases = true;
        QCOMPARE(p.action, std::string("run"));
        QVERIFY(p.gpuMs >= 0.0);
        runs[p.name.substr(prefix.size())] = std::stoi(p.reason);
        phasesMs += p.gpuMs;
    }
    QCOMPARE(int(runs.size()), 4);
    QCOMPARE(runs["gathers on the bounce cells"], 1);
    QCOMPARE(runs["gathers on the higher-bounce cells"], iterations);
    QCOMPARE(runs["reinjections"], iterations);
    QCOMPARE(runs["filterings into the mip chains"], iterations + 1);
    QVERIFY2(phasesMs <= pass("bounces").gpuMs + 1e-3,
        qPrintable(QString("phases %1 ms, the pass %2 ms").arg(phasesMs).arg(pass("bounces").gpuMs)));

    // Not asked for: no phases.
    m_gl.renderer->invalidate();
    planned();
    for (const render::PassStats& p : m_last.passes)
        QVERIFY2(p.name.rfind(prefix, 0) != 0, p.name.c_str());
}

QTEST_GUILESS_MAIN(RenderPlanTest)
#include "tst_RenderPlan.moc"
