#pragma once

#include "core/RenderPass.h"
#include "core/VoxelGridFrame.h"

#include <cstdint>
#include <optional>

namespace vct::render {

/**
 * Finds the space no light can leave (core/EnclosedSpace) in the grid around the scene, from the static
 * meshes, and uploads it as FrameContext::enclosure for the diffuse gathers (common/ConeTracing.glsl). Redone
 * when the static meshes or the grid change; dynamic objects are left out, so an object that moves never
 * opens or closes a room (a door closing a room leaves it counted open).
 */
class EnclosurePass final : public RenderPass {
public:
    const char* name() const override { return "enclosed space"; }
    PassDeclaration declare() const override;
    std::vector<TextureSlot> textures(const FrameContext& frame) override;
    PassDecision plan(const FrameContext& frame) const override;
    void execute(FrameContext& frame) override;
    void release(FrameContext& frame) override;
    void invalidate() override { m_key.reset(); }

    /** The grid the map is built on: the scene's, coarsened to at most EnclosedSpace::kMaxResolution cells a
     * side. */
    static VoxelGridFrame mapGrid(const FrameContext& frame);
    /** Whether the frame has a diffuse gather to read the map: per-pixel cones, the irradiance cache, or the
     * bounce iteration's cells. */
    static bool needed(const FrameContext& frame);

private:
    /// What the map was built from: the static meshes (their version) and the grid.
    struct Key {
        std::uint64_t staticGeometry = 0;
        VoxelGridFrame grid;
        bool operator==(const Key&) const = default;
    };
    static Key keyOf(const FrameContext& frame);
    std::optional<Key> m_key;
};

} // namespace vct::render
