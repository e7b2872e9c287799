#include "passes/ShadowMapPass.h"

#include "core/FrameContext.h"
#include "core/LightUniforms.h"
#include "core/ResourceNames.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace vct::render {

using namespace resource;

namespace {

bool anyShadowCaster(const Scene& scene)
{
    for (const PointLight& l : scene.pointLights)
        if (l.castsShadows)
            return true;
    for (const DirectionalLight& l : scene.directionalLights)
        if (l.castsShadows)
            return true;
    return false;
}

} // namespace

PassDeclaration ShadowMapPass::declare() const
{
    return { {}, { kPointShadows, kDirectionalShadows, kStaticPointShadows, kStaticDirectionalShadows } };
}

std::vector<TextureSlot> ShadowMapPass::textures(const FrameContext& frame)
{
    using gl::TextureDesc;
    // Without a shadow caster the maps shrink to one texel: samplers of every type still need a texture.
    const Scene& scene = frame.scene.scene();
    const bool casting = anyShadowCaster(scene);
    const int size = casting ? frame.settings.shadowMapSize : 1;
    const int points = casting ? std::clamp<int>(int(scene.pointLights.size()), 1, kMaxPointLights) : 1;
    const int directionals
        = casting ? std::clamp<int>(int(scene.directionalLights.size()), 1, kMaxDirectionalLights) : 1;
    const TextureDesc point = TextureDesc::cubeArray(GL_DEPTH_COMPONENT32F, size, points);
    const TextureDesc directional = TextureDesc::planeArray(GL_DEPTH_COMPONENT32F, size, size, directionals);
    // Static casters get maps of their own when something moves: a move then costs a copy and its own draw.
    const bool staticLayer = casting && frame.scene.hasDynamicMeshes();
    ShadowMaps& shadows = frame.shadows;
    return { { kPointShadows, ResourceGroup::Shadows, &shadows.pointDepth,
                 point.sampled(TextureDesc::Sampling::DepthComparison) },
        { kDirectionalShadows, ResourceGroup::Shadows, &shadows.directionalDepth,
            directional.sampled(TextureDesc::Sampling::DepthComparison) },
        { kStaticPointShadows, ResourceGroup::Shadows, &m_staticPoint, staticLayer ? point : TextureDesc {} },
        { kStaticDirectionalShadows, ResourceGroup::Shadows, &m_staticDirectional,
            staticLayer ? directional : TextureDesc {} } };
}

ShadowMapPass::MapsKey ShadowMapPass::keyOf(const FrameContext& frame)
{
    return { frame.versions.staticGeometry, frame.versions.dynamicGeometry, frame.versions.lightPlacement,
        frame.settings.shadowMapSize };
}

PassDecision ShadowMapPass::plan(const FrameContext& frame) const
{
    if (!anyShadowCaster(frame.scene.scene()))
        return { PassDecision::Action::Skip, "no shadow-casting light" };
    if (keyOf(frame) == m_key)
        return { PassDecision::Action::Reuse, "lights and geometry unchanged" };
    return { PassDecision::Action::Run,
        m_key == MapsKey {} ? "no valid output yet" : "lights or geometry changed" };
}

void ShadowMapPass::drawMaps(FrameContext& frame, const gl::Texture& point, const gl::Texture& directional,
    MeshFilter filter, bool clear)
{
    const Scene& scene = frame.scene.scene();
    ShadowMaps& shadows = frame.shadows;
    const int points = std::min<int>(int(scene.pointLights.size()), kMaxPointLights);
    const int directionals = std::min<int>(int(scene.directionalLights.size()), kMaxDirectionalLights);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glViewport(0, 0, shadows.size, shadows.size);
    shadows.framebuffer.bind();
    const float clearDepth = 1.0f;
    // Standard cube-map face orientation, so texture(samplerCubeArray, direction) finds the right texel.
    static const glm::vec3 kFaceDirection[6]
        = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
    static const glm::vec3 kFaceUp[6]
        = { { 0, -1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 }, { 0, -1, 0 }, { 0, -1, 0 } };
    const glm::mat4 cubeProjection
        = glm::perspective(glm::radians(90.0f), 1.0f, shadows.pointNear, shadows.pointFar);
    for (int i = 0; i < points; ++i) {
        const PointLight& light = scene.pointLights[std::size_t(i)];
        m_program->set("uOrigin", light.position);
        const Viewpoint eye { light.position,
            1.01f * shadows.pointNear * std::sqrt(3.0f) }; // 90-degree faces
        for (int face = 0; face < 6; ++face) {
            shadows.framebuffer.attachDepthLayer(point, 6 * i + face);
            shadows.framebuffer.finish(0);
            if (clear)
                glClearNamedFramebufferfv(shadows.framebuffer.id(), GL_DEPTH, 0, &clearDepth);
            if (!light.castsShadows)
                continue;
            const glm::mat4 view = glm::lookAt(glm::vec3(0.0f), kFaceDirection[face], kFaceUp[face]);
            m_program->set("uViewProjection", cubeProjection * view);
            // A face sees about a sixth of the scene around its light: draw only the clusters it can see.
            const Frustum faceView(cubeProjection * view, light.position);
            DrawOptions options;
            options.layer = filter;
            if (frame.settings.viewCulling) {
                options.visibleIn = &faceView;
                options.from = &eye;
            }
            frame.scene.draw(*m_program, options, 0);
        }
    }
    m_program->set("uOrigin", glm::vec3(0.0f));
    for (int i = 0; i < directionals; ++i) {
        shadows.framebuffer.attachDepthLayer(directional, i);
        shadows.framebuffer.finish(0);
        if (clear)
            glClearNamedFramebufferfv(shadows.framebuffer.id(), GL_DEPTH, 0, &clearDepth);
        if (!scene.directionalLights[std::size_t(i)].castsShadows)
            continue;
        m_program->set("uViewProjection", shadows.directionalMatrices[std::size_t(i)]);
        const Frustum lightView(shadows.directionalMatrices[std::size_t(i)], glm::vec3(0.0f));
        DrawOptions options;
        options.layer = filter;
        if (frame.settings.viewCulling)
            options.visibleIn = &lightView;
        frame.scene.draw(*m_program, options, 0);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void ShadowMapPass::execute(FrameContext& frame)
{
    if (!m_program)
        m_program = &frame.shaders.program(
            { "shadow depth", { "shadow/ShadowDepth.vert", "shadow/ShadowDepth.frag" }, {} });
    m_key = keyOf(frame);
    const Scene& scene = frame.scene.scene();
    ShadowMaps& shadows = frame.shadows;
    const int size = frame.settings.shadowMapSize;
    const int points = std::min<int>(int(scene.pointLights.size()), kMaxPointLights);
    const int directionals = std::min<int>(int(scene.directionalLights.size()), kMaxDirectionalLights);
    const bool dynamicLayer = frame.scene.hasDynamicMeshes();
    shadows.size = size;
    if (!shadows.rawDepth)
        shadows.rawDepth = gl::Sampler::createRawDepth();
    if (!shadows.framebuffer)
        shadows.framebuffer = gl::Framebuffer::create();

    // Depth ranges come from the grid around the scene (a clipmap's coarsest level, not the finest, which
    // follows the camera), which only changes with a static rebuild: the static layer's distances stay valid
    // while a dynamic object moves.
    Aabb bounds;
    bounds.extend(frame.sceneGrid.origin);
    bounds.extend(frame.sceneGrid.origin + glm::vec3(frame.sceneGrid.extent));
    // The floors only keep a degenerate (empty or point-sized) grid from giving a zero depth range; they are
    // far below any scene size, so tiny scenes keep their proportions (tests/hardcases, scale invariance).
    const float radius = std::max(0.5f * glm::length(bounds.size()), 1e-20f);
    shadows.pointFar = 0.0f;
    for (int i = 0; i < points; ++i)
        shadows.pointFar = std::max(shadows.pointFar,
            glm::length(scene.pointLights[std::size_t(i)].position - bounds.center()) + radius);
    shadows.pointFar = std::max(shadows.pointFar * 1.01f, 1e-20f);
    // Relative to the far plane only: an absolute floor would clip most of a scene measured in 1e-4 units.
    shadows.pointNear = shadows.pointFar * 1e-4f;
    shadows.directionalMatrices.clear();
    for (int i = 0; i < directionals; ++i) {
        const glm::vec3 dir = glm::normalize(scene.directionalLights[std::size_t(i)].direction);
        const glm::vec3 up = std::abs(dir.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
        const glm::mat4 view = glm::lookAt(bounds.center() - dir * (2.0f * radius), bounds.center(), up);
        shadows.directionalMatrices.push_back(
            glm::ortho(-radius, radius, -radius, radius, radius * 0.5f, radius * 3.5f) * view);
    }

    if (!dynamicLayer) {
        drawMaps(frame, shadows.pointDepth, shadows.directionalDepth, MeshFilter::All, true);
    } else {
        // Static casters are drawn once into their own maps; a moving object costs a copy and its own draw.
        const MapsKey staticKey { frame.versions.staticGeometry, 0, frame.versions.lightPlacement, size };
        if (staticKey != m_staticKey) {
            drawMaps(frame, m_staticPoint, m_staticDirectional, MeshFilter::Static, true);
            m_staticKey = staticKey;
        }
        glCopyImageSubData(m_staticPoint.id(), GL_TEXTURE_CUBE_MAP_ARRAY, 0, 0, 0, 0, shadows.pointDepth.id(),
            GL_TEXTURE_CUBE_MAP_ARRAY, 0, 0, 0, 0, size, size, shadows.pointDepth.depth());
        glCopyImageSubData(m_staticDirectional.id(), GL_TEXTURE_2D_ARRAY, 0, 0, 0, 0,
            shadows.directionalDepth.id(), GL_TEXTURE_2D_ARRAY, 0, 0, 0, 0, size, size,
            shadows.directionalDepth.depth());
        drawMaps(frame, shadows.pointDepth, shadows.directionalDepth, MeshFilter::Dynamic, false);
    }
    ++shadows.version;
}

} // namespace vct::render
