#pragma once

#include "core/FrameResources.h"
#include "core/GpuScene.h"
#include "core/RenderPass.h"
#include "gl/Program.h"
#include "gl/Texture.h"

#include <array>
#include <cstdint>

namespace vct::render {

/** Depth maps for every shadow-casting light: a cube per point light, an orthographic map per directional
 * one. */
class ShadowMapPass final : public RenderPass {
public:
    const char* name() const override { return "shadow maps"; }
    PassDeclaration declare() const override;
    std::vector<TextureSlot> textures(const FrameContext& frame) override;
    PassDecision plan(const FrameContext& frame) const override;
    void execute(FrameContext& frame) override;
    void invalidate() override
    {
        m_key = {};
        m_staticKey = {};
    }

private:
    /** What the maps depend on: the casters, the lights' placement and the map size; zero before the first
     * draw. The static casters' own maps leave out the dynamic geometry. */
    struct MapsKey {
        std::uint64_t staticGeometry = 0;
        std::uint64_t dynamicGeometry = 0;
        std::uint64_t lightPlacement = 0;
        int size = 0;
        bool operator==(const MapsKey& other) const = default;
    };
    static MapsKey keyOf(const FrameContext& frame);
    void drawMaps(FrameContext& frame, const gl::Texture& point, const gl::Texture& directional,
        MeshFilter filter, bool clear);

    const gl::Program* m_program = nullptr;
    gl::Texture m_staticPoint; ///< static casters only, when dynamic meshes exist
    gl::Texture m_staticDirectional;
    MapsKey m_key;
    MapsKey m_staticKey; ///< dynamicGeometry left at zero
};

} // namespace vct::render
