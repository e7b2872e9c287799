#include "GlTestContext.h"

#include "core/ConeSet.h"
#include "core/FrameContext.h"
#include "core/Pipeline.h"
#include "core/ShaderLibrary.h"

#include <QtTest>

#include <stdexcept>

using namespace vct;
using render::PassDecision;

namespace {

/** A pass that makes one texture as told, and counts what the pipeline does with it. */
class ScriptedPass final : public render::RenderPass {
public:
    ScriptedPass(const char* name, const char* texture, std::vector<std::string> reads = {})
        : m_name(name)
        , m_texture(texture)
        , m_reads(std::move(reads))
    {
    }
    const char* name() const override { return m_name; }
    render::PassDeclaration declare() const override
    {
        return { m_reads,
            declaresItsTexture ? std::vector<std::string> { m_texture } : std::vector<std::string> {} };
    }
    PassDecision plan(const render::FrameContext&) const override { return { action, "scripted" }; }
    std::vector<render::TextureSlot> textures(const render::FrameContext&) override
    {
        return { { m_texture, render::ResourceGroup::PassState, &texture, wanted } };
    }
    void execute(render::FrameContext&) override { ++runs; }
    void invalidate() override { ++invalidations; }

    PassDecision::Action action = PassDecision::Action::Run;
    gl::TextureDesc wanted;
    bool declaresItsTexture = true;
    gl::Texture texture;
    int runs = 0, invalidations = 0;

private:
    const char* m_name;
    const char* m_texture;
    std::vector<std::string> m_reads;
};

/** A pipeline of one scripted pass, which makes @p texture; the pipeline owns the pass. */
std::pair<std::unique_ptr<render::Pipeline>, ScriptedPass*> onePass(const char* texture)
{
    auto owned = std::make_unique<ScriptedPass>("maker", texture);
    ScriptedPass* pass = owned.get();
    std::vector<std::unique_ptr<render::RenderPass>> passes;
    passes.push_back(std::move(owned));
    return { std::make_unique<render::Pipeline>(std::move(passes)), pass };
}

} // namespace

/**
 * The pipeline's resource table (issue 18): passes say what textures they need each frame and the pipeline
 * makes, remakes and frees them; a pass whose textures were made anew redoes its output even where it
 * planned to reuse it.
 */
class ResourceTableTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void texturesAreMadeAsDescribed();
    void aRemadeTextureMakesTheOwnerRunAgain();
    void anEmptyDescriptionFreesWithoutInvalidating();
    void aZeroedTextureMadeFromNothingKeepsTheOutput();
    void declarationsAreChecked();

private:
    render::FrameStats frame(render::Pipeline& pipeline);

    test::GlTestContext m_gl;
    std::unique_ptr<render::ShaderLibrary> m_shaders;
    std::unique_ptr<render::GpuScene> m_scene;
    render::RenderSettings m_settings;
    render::ChangeVersions m_versions;
    render::VoxelVolume m_voxels;
    render::ShadowMaps m_shadows;
    render::ScreenTargets m_screen;
    render::ConeSet m_cones = render::ConeSet::diffuse(1);
};

void ResourceTableTest::initTestCase()
{
    m_gl = test::GlTestContext::create();
    QVERIFY2(m_gl.renderer, m_gl.error.c_str());
    m_shaders = std::make_unique<render::ShaderLibrary>();
    m_scene = std::make_unique<render::GpuScene>(render::Scene {});
}

render::FrameStats ResourceTableTest::frame(render::Pipeline& pipeline)
{
    render::FrameContext context { *m_shaders, *m_scene, m_settings, m_versions, m_voxels, m_shadows,
        m_screen, m_cones, render::Aabb {}, render::Camera {}, glm::mat4(1.0f), glm::mat4(1.0f),
        glm::mat3(1.0f), nullptr, 0, render::FrameShape {}, &pipeline.resources(), m_voxels.frame, {} };
    return pipeline.execute(context);
}

void ResourceTableTest::texturesAreMadeAsDescribed()
{
    auto [owner, made] = onePass("scratch");
    render::Pipeline& pipeline = *owner;
    ScriptedPass& pass = *made;
    pass.wanted = gl::TextureDesc::volume(GL_RGBA16F, 8, 4);
    frame(pipeline);
    QVERIFY(pass.texture);
    QVERIFY(pass.texture.desc() == pass.wanted);
    QCOMPARE(pass.texture.levels(), 4);
    QCOMPARE(pipeline.resources().find("scratch"), &pass.texture);
    QCOMPARE(pipeline.resources().entries().front().owner, std::string("maker"));
    // 8^3 + 4^3 + 2^3 + 1 texels of 8 bytes, counted from the description and by the texture itself.
    QCOMPARE(pipeline.resources().byteSize(render::ResourceGroup::PassState), std::uint64_t(585 * 8));
    QCOMPARE(std::uint64_t(pass.texture.byteSize()), pass.wanted.byteSize());
    QCOMPARE(pipeline.resources().byteSize(render::ResourceGroup::Voxels), std::uint64_t(0));
    // The same description again: the same texture, invalidated only when it was first made.
    const std::uint64_t serial = pass.texture.serial();
    frame(pipeline);
    QCOMPARE(pass.texture.serial(), serial);
    QCOMPARE(pass.invalidations, 1);
    QCOMPARE(pass.runs, 2);
}

void ResourceTableTest::aRemadeTextureMakesTheOwnerRunAgain()
{
    auto [owner, made] = onePass("scratch");
    render::Pipeline& pipeline = *owner;
    ScriptedPass& pass = *made;
    pass.wanted = gl::TextureDesc::plane(GL_RGBA32F, 4, 4);
    frame(pipeline);
    QCOMPARE(pass.invalidations, 1); // made from nothing: there was no output to keep
    pass.action = PassDecision::Action::Reuse;
    frame(pipeline);
    QCOMPARE(pass.runs, 1);
    // A new size loses the content the pass meant to reuse: it runs, and says why.
    pass.wanted = gl::TextureDesc::plane(GL_RGBA32F, 8, 4);
    const render::FrameStats stats = frame(pipeline);
    QCOMPARE(pass.runs, 2);
    QCOMPARE(pass.invalidations, 2);
    QCOMPARE(stats.passes.front().action, std::string("run"));
    QCOMPARE(stats.passes.front().reason, std::string("its textures were made anew"));
    QCOMPARE(pass.texture.width(), 8);
}

void ResourceTableTest::anEmptyDescriptionFreesWithoutInvalidating()
{
    auto [owner, made] = onePass("scratch");
    render::Pipeline& pipeline = *owner;
    ScriptedPass& pass = *made;
    pass.wanted = gl::TextureDesc::plane(GL_RGBA16F, 4, 4);
    frame(pipeline);
    pass.action = PassDecision::Action::Skip;
    pass.wanted = {};
    const render::FrameStats stats = frame(pipeline);
    QCOMPARE(stats.passes.front().action, std::string("skipped"));
    QVERIFY(!pass.texture);
    QCOMPARE(pass.invalidations, 1);
    QCOMPARE(pipeline.resources().byteSize(render::ResourceGroup::PassState), std::uint64_t(0));
    // Still listed, by name, with nothing allocated.
    QCOMPARE(pipeline.resources().find("scratch"), &pass.texture);
}

void ResourceTableTest::aZeroedTextureMadeFromNothingKeepsTheOutput()
{
    auto [owner, made] = onePass("emission-like");
    render::Pipeline& pipeline = *owner;
    ScriptedPass& pass = *made;
    pass.action = PassDecision::Action::Reuse;
    pass.wanted = gl::TextureDesc::volume(GL_R11F_G11F_B10F, 4).zeroedWhenMade();
    frame(pipeline);
    QCOMPARE(pass.invalidations, 0);
    QCOMPARE(pass.runs, 0);
    std::vector<float> texels(4 * 4 * 4 * 4, -1.0f);
    glGetTextureImage(
        pass.texture.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * sizeof(float)), texels.data());
    for (std::size_t i = 0; i < texels.size(); i += 4)
        QCOMPARE(texels[i] + texels[i + 1] + texels[i + 2], 0.0f);
    // Made anew at another size, it no longer holds what the pass wrote.
    pass.wanted = gl::TextureDesc::volume(GL_R11F_G11F_B10F, 8).zeroedWhenMade();
    frame(pipeline);
    QCOMPARE(pass.invalidations, 1);
    QCOMPARE(pass.runs, 1);
}

void ResourceTableTest::declarationsAreChecked()
{
    {
        // A read nothing before writes.
        std::vector<std::unique_ptr<render::RenderPass>> passes;
        passes.push_back(std::make_unique<ScriptedPass>("reader", "a", std::vector<std::string> { "b" }));
        passes.push_back(std::make_unique<ScriptedPass>("writer", "b"));
        QVERIFY_THROWS_EXCEPTION(std::logic_error, render::Pipeline(std::move(passes)));
    }
    {
        // A texture the pass does not declare it writes.
        auto owned = std::make_unique<ScriptedPass>("maker", "undeclared");
        owned->declaresItsTexture = false;
        owned->wanted = gl::TextureDesc::plane(GL_RGBA16F, 1, 1);
        std::vector<std::unique_ptr<render::RenderPass>> passes;
        passes.push_back(std::move(owned));
        render::Pipeline pipeline(std::move(passes));
        QVERIFY_THROWS_EXCEPTION(std::logic_error, frame(pipeline));
    }
    {
        // Two passes making a texture of the same name.
        std::vector<std::unique_ptr<render::RenderPass>> passes;
        passes.push_back(std::make_unique<ScriptedPass>("first", "shared"));
        passes.push_back(std::make_unique<ScriptedPass>("second", "shared"));
        render::Pipeline pipeline(std::move(passes));
        QVERIFY_THROWS_EXCEPTION(std::logic_error, frame(pipeline));
    }
}

QTEST_GUILESS_MAIN(ResourceTableTest)
#include "tst_ResourceTable.moc"
