#include "passes/EnclosurePass.h"

#include "core/EnclosedSpace.h"
#include "core/FrameContext.h"
#include "core/ResourceNames.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace vct::render {

VoxelGridFrame EnclosurePass::mapGrid(const FrameContext& frame)
{
    VoxelGridFrame grid = frame.sceneGrid;
    grid.resolution = std::min(grid.resolution, EnclosedSpace::kMaxResolution);
    return grid;
}

bool EnclosurePass::needed(const FrameContext& frame)
{
    return frame.settings.enclosedSpace && frame.enclosure
        && (frame.shape.diffuseCones || frame.shape.irradianceCache || frame.shape.bounceVolume);
}

EnclosurePass::Key EnclosurePass::keyOf(const FrameContext& frame)
{
    return { frame.versions.staticGeometry, mapGrid(frame) };
}

PassDeclaration EnclosurePass::declare() const
{
    return { {}, { resource::kEnclosure } };
}

std::vector<TextureSlot> EnclosurePass::textures(const FrameContext& frame)
{
    if (!frame.enclosure)
        return {};
    // Sampled filtered: a gather whose start lies in a wall's cell beside enclosed space still counts as
    // enclosed (common/ConeTracing.glsl, startsEnclosed).
    const gl::TextureDesc desc
        = needed(frame) ? gl::TextureDesc::volume(GL_R8, mapGrid(frame).resolution) : gl::TextureDesc {};
    return { { resource::kEnclosure, ResourceGroup::Voxels, &frame.enclosure->texture, desc } };
}

PassDecision EnclosurePass::plan(const FrameContext& frame) const
{
    if (!frame.settings.enclosedSpace)
        return { PassDecision::Action::Skip, "enclosed_space=off" };
    if (!needed(frame))
        return { PassDecision::Action::Skip, "no diffuse gather reads it" };
    if (!m_key)
        return { PassDecision::Action::Run, "no valid output yet" };
    if (!(*m_key == keyOf(frame)))
        return { PassDecision::Action::Run, "static geometry or grid changed" };
    return { PassDecision::Action::Reuse, "static geometry unchanged" };
}

void EnclosurePass::execute(FrameContext& frame)
{
    EnclosureMap& map = *frame.enclosure;
    const VoxelGridFrame grid = mapGrid(frame);
    EnclosedSpace space(grid.resolution);
    const glm::mat4 toGrid = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f / grid.voxelSize()))
        * glm::translate(glm::mat4(1.0f), -grid.origin);
    for (const Mesh& mesh : frame.scene.scene().meshes)
        if (mesh.visible && !mesh.dynamic)
            space.addMesh(mesh.positions, mesh.indices, toGrid * mesh.transform);
    space.solve();
    const std::vector<std::uint8_t> texels = space.texels();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage3D(map.texture.id(), 0, 0, 0, 0, grid.resolution, grid.resolution, grid.resolution,
        GL_RED, GL_UNSIGNED_BYTE, texels.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    map.grid = grid;
    map.enclosedCells = space.enclosedCells();
    map.inUse = true;
    ++map.version;
    m_key = keyOf(frame);
}

void EnclosurePass::release(FrameContext& frame)
{
    if (frame.enclosure)
        frame.enclosure->inUse = false;
    m_key.reset();
}

} // namespace vct::render
